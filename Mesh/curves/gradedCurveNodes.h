// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The nodes of a curve's 1D mesh spread along its polyline by a size that
// varies: Gmsh's 1D mesher integrates 1 / size along the curve to a relative
// precision of 1e-9 (Mesh.LcIntegrationPrecision), which a size made of
// cones (Mesh/sizes/gradedBoundarySize.h) turns into hundreds of thousands of
// evaluations (seconds of 1D meshing: bench/README.md#sizes-from-the-curves);
// here 1 / size is summed over pieces of a quarter of the size.

#ifndef GRADED_CURVE_NODES_H
#define GRADED_CURVE_NODES_H

#include <functional>
#include <vector>
#include "SPoint3.h"

namespace reparam {

// The parameters (polyline node i at i) of the ends and the nodes of a 1D
// mesh of the polyline whose segments follow size(x, t) (t: x's
// parameter): as many segments as
// the integral of 1 / size rounded, at least `fewest`, at equal steps of it;
// `even`: an even number of segments (a curve of a face recombined by
// Blossom, which pairs all the face's triangles only if its boundary has
// an even number of segments; Gmsh's 1D mesher does the same)
std::vector<double> gradedCurveParameters(
  const std::vector<SPoint3> &polyline,
  const std::function<double(const SPoint3 &, double)> &size, int fewest,
  bool even = false);

} // namespace reparam

#endif
