// Reparam tutorial 4: looking at a parametrization and at the mesh quality
//
// Plugin(Parametrization) turns the (u, v) of every discrete surface into
// views (paper Fig. 5, 15, 16): u and v on the 3D surface drawn as
// iso-lines, the triangulation flattened in the (u, v) plane, and per
// triangle its angle distortion (1: conformal) and area distortion (1: area
// preserving). Plugin(SurfaceMeshQuality) measures the new mesh (kappa per
// triangle, tau, distance to the input) and adds kappa and its histogram.
//
//   gmsh t4_parametrization_views.geo -                (batch: writes .pos)
//   gmsh t4_parametrization_views.geo -setnumber Mesh.CompoundParametrization 3 \
//        -                                         (the mean value map's)
//   gmsh t4_parametrization_views.geo                  (GUI: look at them)
//
// In batch the views are written to t4_<name>.pos, next to this file.

Merge "dome.stl";
ClassifySurfaces{40 * Pi / 180, 1, 1, 180 * Pi / 180};
CreateGeometry;

// Views 0 to 4: u, v, flattened, angle distortion, area distortion
Plugin(Parametrization).SurfaceTag = -1; // every surface with a parametrization
Plugin(Parametrization).IsoLines = 20;
Plugin(Parametrization).Run;

Mesh.MeshSizeMin = 0.05;
Mesh.MeshSizeMax = 0.05;
Mesh 2;

// Views 5 and 6: kappa per triangle and its histogram (a 2D plot)
Plugin(SurfaceMeshQuality).SurfaceTag = -1;
Plugin(SurfaceMeshQuality).CreateViews = 1;
Plugin(SurfaceMeshQuality).HistogramBins = 20;
Plugin(SurfaceMeshQuality).Run;

names[] = Str("u", "v", "flattened", "angle_distortion", "area_distortion",
              "kappa", "kappa_histogram");
For i In {0 : #names[] - 1}
  Save View[i] StrCat("t4_", names[i], ".pos");
EndFor
