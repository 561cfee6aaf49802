// Reparam tutorial 3: the five maps side by side
//
// Remeshes dome.stl (a bumpy dome with two holes and slivers) once with each
// parametrization and saves t3_map<N>.msh for each:
//
//   gmsh t3_all_maps.geo -parse_and_exit
//
// Compare the "Reparam: surface ..." lines of the log: the barycentric map
// (2) ignores the geometry and gives the planar mesher a distorted metric;
// the mean value (3) and the conformal maps (4, 5) give the best triangles.
// Open a t3_map<N>.msh to look at one result.

// 1: FE harmonic, 2: barycentric (Tutte), 3: mean value, 4: FE conformal
// (LSCM), 5: spectral conformal
For map In {1:5}
  Printf("Reparam tutorial 3: Mesh.CompoundParametrization = %g", map);
  Merge "dome.stl";
  Mesh.CompoundParametrization = map;
  ClassifySurfaces{40 * Pi / 180, 1, 1, 180 * Pi / 180};
  CreateGeometry;
  Mesh.MeshSizeMin = 0.05;
  Mesh.MeshSizeMax = 0.05;
  Mesh.Algorithm = 6;
  Mesh 2;
  Save Sprintf("t3_map%g.msh", map);
  Delete Model;
EndFor
