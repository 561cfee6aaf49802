// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Why a triangle of a new surface mesh is poor (kappa below 0.3) once the
// optimization on the input is done: what is left is mostly set by the
// input's features, which the report names (issue: "the reason for each
// remaining bad triangle").

#ifndef POOR_TRIANGLE_CAUSE_H
#define POOR_TRIANGLE_CAUSE_H

#include "SPoint3.h"

namespace reparam {

// A triangle's corners and where they lie in the model
struct triangleCorners {
  SPoint3 x[3];
  int dim[3] = {2, 2, 2}; // 0: on a model point, 1: on a curve, 2: inside
  bool edgeOnCurve[3] = {false, false, false}; // edge k: corners k, k + 1
};

enum class poorTriangleCause {
  // two curves meet at a model point under 30 degrees: the triangle's
  // angle there is theirs
  sharpCurveAngle,
  // an edge of a curve's 1D mesh under 0.3 times the triangle's longest
  // edge (a curve shorter than the size, a corner next to a model point)
  shortCurveSegment,
  // every corner on a curve: the surface is narrower than the mesh size
  // there, no inner node fits
  narrowStrip,
  // none of these: inside the surface (a fold of the input thinner than the
  // mesh size)
  inside
};
const int numPoorTriangleCauses = 4;

// The first cause of the list above that applies to t
poorTriangleCause poorTriangleCauseOf(const triangleCorners &t);

// "where curves meet at a sharp angle", "on short curve segments", "in
// strips narrower than the mesh size", "inside surfaces"
const char *poorTriangleCauseName(poorTriangleCause c);

} // namespace reparam

#endif
