// Reparam tutorial 1: remeshing a poor STL triangulation
//
// dome.stl is a bumpy dome with two holes, triangulated with long slivers
// (kappa min < 0.1), like a raw segmentation. We classify it into discrete
// surfaces, parametrize each one and remesh it with Gmsh's planar mesher in
// the parametric plane:
//
//   gmsh t1_remesh_stl.geo -2                  (mean value map, the default)
//   gmsh t1_remesh_stl.geo -2 -setnumber Parametrization 0   (Gmsh's own)
//   gmsh t1_remesh_stl.geo -2 -setnumber Parametrization 5   (spectral)
//   gmsh t1_remesh_stl.geo -2 -setnumber FillHoles 0  (holes left free)
//   gmsh t1_remesh_stl.geo -2 -setnumber Optimize 0   (planar mesh as is)
//
// Maps 1 to 3 put the outer boundary on the unit circle; maps 4 and 5 leave
// it free (conformal). The two holes are filled on their mean plane before
// mapping (Mesh.CompoundFillHoles) and stay holes in the new mesh.
//
// After the planar mesher, the new mesh is optimized on the input
// (Mesh.CompoundOptimize: input nodes it cuts off inserted, long edges split
// and short ones collapsed, flips and node moves around its poor triangles;
// 1 leaves the short edges).
//
// The log has one "Reparam:" line per parametrization (stage times), one per
// meshed surface (triangles, kappa min and mean) and one on the optimization
// (kappa min before and after).

DefineConstant[
  Parametrization = {3, Choices{0 = "Gmsh built-in", 1 = "FE harmonic",
                                2 = "Barycentric", 3 = "Mean value",
                                4 = "FE conformal", 5 = "Spectral conformal",
                                6 = "Automatic"},
                     Name "Reparam/Parametrization"}
  FillHoles = {1, Choices{0, 1}, Name "Reparam/Fill holes"}
  Optimize = {2, Choices{0 = "None", 1 = "On the input, no collapse",
                         2 = "On the input, short edges collapsed"},
              Name "Reparam/Optimize"}
  Size = {0.05, Min 0.005, Max 0.5, Step 0.005,
              Name "Reparam/Mesh size"}
];

Merge "dome.stl";

// Mesh.CompoundParametrization must be set before CreateGeometry, which
// computes the parametrizations
Mesh.CompoundParametrization = Parametrization;
Mesh.CompoundFillHoles = FillHoles;
Mesh.CompoundOptimize = Optimize;

// Split the triangulation where the angle between triangles exceeds 40
// degrees, keep the boundary, and make every patch parametrizable (1)
ClassifySurfaces{40 * Pi / 180, 1, 1, 180 * Pi / 180};
CreateGeometry;

Mesh.MeshSizeMin = Size;
Mesh.MeshSizeMax = Size;
Mesh.Algorithm = 6; // Frontal-Delaunay in the parametric plane

