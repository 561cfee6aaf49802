// Reparam tutorial 6: an anisotropic mesh from the surface's curvature
//
// Sec. 6.3 of the paper: BAMG meshes the parametric plane with a metric
// built from the curvature of the input, so that the elements are long
// where the surface bends little and short across its bends. With
// Mesh.CompoundCurvatureMetric = N, the size along each principal
// direction of curvature is 2 pi R / N (R the radius of curvature there),
// bounded by Mesh.MeshSizeMin and Mesh.MeshSizeMax and graded along the
// surface (sizes growing by at most 1.3 from element to element); BAMG
// pulls the metric back to the (u, v) plane through the map's Jacobian:
//
//   gmsh t6_anisotropic.geo -2
//   gmsh t6_anisotropic.geo -2 -setnumber Anisotropic 0  (isotropic:
//        Frontal-Delaunay with Gmsh's Mesh.MeshSizeFromCurvature = N)
//
// The conformal maps suit it best: their metric is smooth up to the
// boundary, where a map onto a fixed circle crowds the mesh. The log's
// "Reparam: surface N: sizes from the curvature of its input" line gives
// the bounds; the total line the elements and the distance to the input.

DefineConstant[
  // 0: Frontal-Delaunay, isotropic; 1: BAMG, anisotropic
  Anisotropic = {1, Choices{0, 1}, Name "Reparam/Anisotropic (BAMG)"}
  // (-setnumber ElementsPerCircle takes any value)
  ElementsPerCircle = {20, Choices{10 = "10", 20 = "20", 40 = "40"},
                       Name "Reparam/Per circle",
                       Help "Elements per circle of curvature"}
];

Merge "dome.stl";
ClassifySurfaces{40 * Pi / 180, 1, 1, 180 * Pi / 180};
CreateGeometry;

Mesh.MeshSizeMin = 0.0125;
Mesh.MeshSizeMax = 0.2;
If(Anisotropic)
  Mesh.Algorithm = 7; // BAMG
  Mesh.CompoundCurvatureMetric = ElementsPerCircle;
Else
  Mesh.Algorithm = 6; // Frontal-Delaunay
  Mesh.MeshSizeFromCurvature = ElementsPerCircle;
EndIf
