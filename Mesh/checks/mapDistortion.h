// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// How far a map is from conformal, triangle by triangle: the ratio of the
// singular values of the Jacobian of the affine map from a 3D triangle to
// its (u, v) image (1 for a similarity, larger as angles are distorted).

#ifndef MAP_DISTORTION_H
#define MAP_DISTORTION_H

#include <vector>
#include "SPoint3.h"
#include "discretePatch.h"

namespace reparam {

// sigma_max / sigma_min of the triangle's Jacobian; +infinity when its image
// is degenerate or flipped (oriented against the triangle)
double angleDistortion(const SPoint3 &x0, const SPoint3 &x1, const SPoint3 &x2,
                       const double *uv0, const double *uv1, const double *uv2);

struct mapDistortionStats {
  double mean = 0.; // over the triangles that are not flipped
  double max = 0.;
  std::size_t flipped = 0; // images of zero or negative area
};

// Over the given triangles of the patch (all if `which` is empty); uv holds
// 2 values per node
mapDistortionStats angleDistortionStats(const discretePatch &patch,
                                        const std::vector<double> &uv,
                                        const std::vector<int> &which = {});

} // namespace reparam

#endif
