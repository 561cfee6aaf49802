// Reparam tutorial 1: remeshing a poor STL triangulation
//
// dome.stl is a bumpy dome with two holes, triangulated with long slivers
// (kappa min < 0.1), like a raw segmentation. We classify it into discrete
// surfaces, parametrize each one and remesh it with Gmsh's planar mesher in
// the parametric plane. In batch, Reparam's options on the command line:
//
//   gmsh t1_remesh_stl.geo -2              (automatic map, the default)
//   gmsh t1_remesh_stl.geo -2 -setnumber Mesh.CompoundParametrization 0
//                                          (Gmsh's own map; 3: mean value,
//                                          5: spectral conformal...)
//   gmsh t1_remesh_stl.geo -2 -setnumber Mesh.CompoundFillHoles 0
//                                          (holes left free)
//   gmsh t1_remesh_stl.geo -2 -setnumber Mesh.CompoundOptimize 0
//                                          (planar mesh as is)
//
// In the GUI: gmsh t1_remesh_stl.geo, then Tools > Options > Mesh >
// Compound to choose the map, the hole filling and the optimization, and
// Mesh > 2D. A map chosen after the file is loaded is the one the next mesh
// uses (the surfaces are parametrized again); the mesh size is the
// "Reparam/Mesh size" parameter on the left.
//
// Maps 1 to 3 put the outer boundary on the unit circle; maps 4 and 5 leave
// it free (conformal); the automatic map (6) takes the first one-to-one map
// of a chain. The two holes are filled on their mean plane before mapping
// (Mesh.CompoundFillHoles) and stay holes in the new mesh.
//
// After the planar mesher, the new mesh is optimized on the input
// (Mesh.CompoundOptimize: input nodes it cuts off inserted, long edges split
// and short ones collapsed, flips and node moves around its poor triangles;
// 1 leaves the short edges).
//
// The log has one "Reparam:" line per parametrization (stage times), one per
// meshed surface (triangles, kappa min and mean) and one on the optimization
// (kappa min before and after).

// The mesh size, from a list (-setnumber Size takes any value)
DefineConstant[
  Size = {0.05, Choices{0.1 = "0.1", 0.05 = "0.05", 0.025 = "0.025",
                        0.0125 = "0.0125"},
          Name "Reparam/Mesh size"}
];

Merge "dome.stl";

// Split the triangulation where the angle between triangles exceeds 40
// degrees, keep the boundary, and make every patch parametrizable (1)
ClassifySurfaces{40 * Pi / 180, 1, 1, 180 * Pi / 180};
CreateGeometry;

Mesh.MeshSizeMin = Size;
Mesh.MeshSizeMax = Size;
Mesh.Algorithm = 6; // Frontal-Delaunay in the parametric plane

