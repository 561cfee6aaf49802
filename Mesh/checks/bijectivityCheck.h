// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Is a map of a patch one-to-one? The paper's Sec. 5: flipped triangles
// (signed uv area of the wrong sign) and folds (the image of the boundary
// crossing itself, Eq. 31), plus degenerate images (triangles crushed to
// numerically nothing, which the planar mesher cannot tell apart).

#ifndef BIJECTIVITY_CHECK_H
#define BIJECTIVITY_CHECK_H

#include <array>
#include <cstddef>
#include <vector>
#include "discretePatch.h"

namespace reparam {

struct bijectivityReport {
  // Orientation of the image: +1 when the total signed uv area is positive
  // (every map of ours, by construction), -1 when the whole map is mirrored
  int orientation = 1;
  // Triangles whose image has the other orientation or none (exact sign)
  std::vector<int> flippedTriangles;
  // Triangles whose share of the uv area is below degenerateRatio times
  // their share of the 3D area
  std::vector<int> degenerateTriangles;
  // Pairs of boundary edges without a common node whose images intersect
  std::size_t numFolds = 0;
  // The first node of each edge of such pairs (at most maxFoldPairs)
  std::vector<std::array<int, 2> > foldPairs;
  // Degenerate images are one-to-one, only numerically fragile: they do
  // not count here
  bool bijective() const { return flippedTriangles.empty() && numFolds == 0; }
};

// Exact (robust predicates): do segments [a, b] and [c, d] of the plane
// share a point? Touching and collinear overlapping segments do.
bool segmentsIntersect(const double *a, const double *b, const double *c,
                       const double *d);

// Exact sign of twice the signed area of the plane triangle (a, b, c)
double orientation2d(const double *a, const double *b, const double *c);

// Number of pairs of edges of the patch's boundary loops (all of them) that
// intersect in uv without sharing a node. Edges are binned in a uniform grid
// (expected linear time), each candidate pair tested exactly. With `within`
// > 0, a pair where a node of one edge lies within that uv distance of the
// other is not counted (a crossing of the input's own rounding).
// `pairs` (if given): the first node of each edge of the first
// maxFoldPairs crossing pairs.
const std::size_t maxFoldPairs = 64;
std::size_t
countBoundaryFolds(const discretePatch &patch, const std::vector<double> &uv,
                   double within = 0.,
                   std::vector<std::array<int, 2> > *pairs = nullptr);

const double defaultDegenerateRatio = 1e-12;

bijectivityReport
checkBijectivity(const discretePatch &patch, const std::vector<double> &uv,
                 double degenerateRatio = defaultDegenerateRatio);

} // namespace reparam

#endif
