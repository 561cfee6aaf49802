// A Compound Surface over the output of ClassifySurfaces: stock Gmsh 4.8.4
// logged "Curvature not found for node N" for every node and exited with 1.
Merge "../../tutorials/dome.stl";
Mesh.ReparamMaxTriangles = 1000; // split the dome into several patches
ClassifySurfaces{40 * Pi / 180, 1, 1, 180 * Pi / 180};
CreateGeometry;
patches() = Surface{:};
If(#patches() < 2)
  Error("expected several patches, got %g", #patches());
EndIf
Compound Surface{patches()};
Mesh.MeshSizeMin = 0.05;
Mesh.MeshSizeMax = 0.05;
