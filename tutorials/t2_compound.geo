// Reparam tutorial 2: meshing thin CAD patches as one compound surface
//
// A curved panel made of three patches, the middle one a thin strip (like
// the faces of CAD models that carry no meaning but force tiny, distorted
// triangles on their boundaries). "Compound Surface" meshes the three as one
// surface through Reparam's parametrization: the strip no longer constrains
// the mesh.
//
//   gmsh t2_compound.geo -2
//   gmsh t2_compound.geo -2 -setnumber UseCompound 0     (patch by patch)
//   gmsh t2_compound.geo -2 -setnumber Mesh.CompoundParametrization 3
//                                                  (mean value map)
//
// In the GUI: gmsh t2_compound.geo, the map in Tools > Options > Mesh >
// Compound, the compound on or off with "Reparam/Compound" on the left,
// then Mesh > 2D.

DefineConstant[
  UseCompound = {1, Choices{0, 1}, Name "Reparam/Compound"}
];

lc = 0.1;
w = 0.01; // width of the middle strip
// a twisted panel: z = 0.3 x y, so that the surfaces are not planar
x[] = {0, 0.5 - w / 2, 0.5 + w / 2, 1};
For i In {0 : 3}
  Point(1 + i) = {x[i], 0, 0, lc};
  Point(5 + i) = {x[i], 1, 0.3 * x[i], lc};
EndFor
For i In {0 : 2}
  Line(1 + i) = {1 + i, 2 + i}; // bottom
  Line(4 + i) = {5 + i, 6 + i}; // top
EndFor
For i In {0 : 3}
  Line(7 + i) = {1 + i, 5 + i}; // across
EndFor
For i In {0 : 2}
  Curve Loop(1 + i) = {1 + i, 8 + i, -(4 + i), -(7 + i)};
  Surface(1 + i) = {1 + i}; // bilinear (Coons) patches
EndFor

If(UseCompound)
  Compound Curve{1, 2, 3};
  Compound Curve{4, 5, 6};
  Compound Surface{1, 2, 3};
EndIf
