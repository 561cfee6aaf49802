// Reparam tutorial 5: a quadrangle mesh of an STL triangulation
//
// The paper's case for the conformal maps: they keep angles, so the right
// triangles that Gmsh's Frontal-Delaunay for quads lays along a cross field
// in the parametric plane are right triangles on the surface too, and
// Blossom pairs them into near-square quadrangles:
//
//   gmsh t5_quadrangles.geo -2
//   gmsh t5_quadrangles.geo -2 -setnumber Mesh.CompoundParametrization 0
//                                         (Gmsh's own map)
//   gmsh t5_quadrangles.geo -2 -setnumber Mesh.CompoundOptimize 0
//                                         (as Blossom left them)
//
// In the GUI: gmsh t5_quadrangles.geo, the map and the optimization in
// Tools > Options > Mesh > Compound, then Mesh > 2D.
//
// On a surface Reparam parametrized, Gmsh's recombination smooths the
// quadrangles in the parametric plane and removes their diamonds, as on a
// CAD surface (Gmsh skips that on discrete surfaces, which had no map it
// could trust), and the cross field is the smooth one (the closest boundary
// point's direction follows the zig-zag of the cut curves). Then
// Mesh.CompoundOptimize rotates edges, collapses quadrangles along a
// diagonal and splits nodes where that leaves fewer nodes of valence other
// than 4, then squares the quadrangles up on the input, moving the nodes of
// the cut curves across them; a quadrangle left with a flat corner (three
// corners along a bent curve) is split into two fair triangles.
//
// The log's "Reparam:" lines give eta min and mean per surface (Eq. 4 of
// the paper: 1 for a square) and the "quadrangles squared up" line eta
// before and after the optimization.

DefineConstant[
  // (-setnumber Size takes any value)
  Size = {0.05, Choices{0.1 = "0.1", 0.05 = "0.05", 0.025 = "0.025"},
          Name "Reparam/Mesh size"}
];

Merge "dome.stl";
ClassifySurfaces{40 * Pi / 180, 1, 1, 180 * Pi / 180};
CreateGeometry;

Mesh.MeshSizeMin = Size;
Mesh.MeshSizeMax = Size;
Mesh.Algorithm = 8; // Frontal-Delaunay for quads in the parametric plane
Mesh.RecombineAll = 1; // Blossom (Mesh.RecombinationAlgorithm = 1)
