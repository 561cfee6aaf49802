// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Reparam's options (Mesh.Compound*). Their values live here rather than in
// Gmsh's CTX, so that Gmsh's Common/Context.h stays untouched; the option
// table entries (Common/DefaultOptions.h, patches/) call the accessors below.

#ifndef REPARAM_OPTIONS_H
#define REPARAM_OPTIONS_H

#include <string>
#include "mapKind.h"

namespace reparam {

struct reparamOptions {
  int parametrization = (int)compoundParametrization::automatic;
  // Mesh.CompoundFillHoles: triangulate inner boundary loops before mapping
  bool fillHoles = true;
  // Mesh.CompoundRepair: cavity and boundary checks on flipped triangles
  bool repair = true;
  // Mesh.CompoundSplit: ClassifySurfaces also splits the patches Reparam
  // cannot map, or maps only with mean value because its conformal maps fold
  bool split = false;
  // Mesh.CompoundLayout: ClassifySurfaces{..., forParametrization = 1} lays
  // out the patches with Reparam's own cleaning, cutting and verification
  bool layout = true;
  // Mesh.CompoundNoiseSize: the mesh size feature patches are noise against
  // (0: the edge of a uniform mesh with as many triangles as the input)
  double noiseSize = 0.;
  // Mesh.CompoundFeatureScale: sharp edges no longer sharp over a disk of
  // this many noise sizes are no features (Mesh/layout/featureScale.h);
  // 0: every sharp edge is one
  double featureScale = 0.;
  // Mesh.CompoundCurveCorners: nodes of discrete curves on the input's
  // corners
  bool curveCorners = true;
  // Mesh.CompoundOptimize: 1: each new face mesh optimized on its input
  // (input nodes it cuts off inserted, long edges split, flips and node
  // moves around its poor triangles); 2: also its short edges collapsed;
  // 0: none
  int optimize = 1;
  // Mesh.CompoundMeshSizeGradient: where sizes extend from the boundary,
  // the size of a short boundary segment grows by this much per unit
  // distance into the face, and along discrete curves the size from the
  // ends of the short curves (Geo/sizes/reparamSizeGrading.cpp); 0: Gmsh's
  // sizes
  double meshSizeGradient = 0.5;
  // Mesh.CompoundMeshSizeFromStrips: with a gradient, the surfaces
  // narrower than the size give their curves sizes of their width
  // (Mesh/sizes/narrowStrips.h); off by default (bench/README.md,
  // "Narrow strips")
  int meshSizeFromStrips = 0;
  // Mesh.CompoundCurvatureMetric: N > 0: anisotropic sizes 2 pi R / N along
  // the principal directions of the input's curvature (BAMG), the smaller
  // one for the isotropic meshers (Geo/sizes/reparamCurvatureMetric.h); 0: off
  double curvatureMetric = 0.;
  // Mesh.CompoundReport: quality and fidelity lines after meshing
  bool report = true;
  // Mesh.CompoundReportFile: the same report as JSON; empty: none
  std::string reportFile;
};

reparamOptions &getReparamOptions();

} // namespace reparam

#endif
