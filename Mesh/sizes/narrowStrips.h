// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Where a triangulated surface is narrower than the mesh size: the width of
// a strip measured from its boundary straight across it. A strip narrower
// than the size gets triangles across it whatever the mesher does; with the
// size along its curves, one triangle spans it with a base of the size and
// a height of its width (bench/README.md#narrow-strips). Sizes of about its
// width along its curves give near-equilateral triangles instead.

#ifndef NARROW_STRIPS_H
#define NARROW_STRIPS_H

#include <functional>
#include <vector>
#include "SPoint3.h"

namespace reparam {

struct surfaceMesh;

struct stripWidth {
  SPoint3 point; // on the boundary
  double width;
  int a = -1, b = -1; // the boundary edge it lies on (m's points)
};

// Points of m's boundary (its edges with one triangle), spaced along it by
// at most a quarter of the size there, where m is narrower than `share`
// times the size: the distance to the nearest other boundary point q with
//  - q straight across: the segment from each end leaves its boundary edge
//    into the surface, within 40 degrees of the edge's inward normal (no
//    convex corner, whose two sides meet at 90 degrees or more, nor the
//    gap between two arms of the surface, which lies outside it), and
//  - q far from the point along the boundary: on another loop, or over
//    four times their distance away along theirs (not the two sides of a
//    corner, nor of a tip wider than 29 degrees),
// and only where such points follow each other along the boundary for at
// least the size (a shorter neck is spanned by one triangle either way).
// None when the boundary would take over a million samples (a size far
// below the model's scale).
// "Straight across" is judged in `flat`, m's points laid out in a plane
// (its parametrization): a strip bent across, a fillet or a groove, is
// straight there. Widths are measured in space; size(x): the mesh size at
// boundary point x. side(a, b): whether the boundary edge between points a
// and b may be a strip's side (a cut the final mesh crosses is none);
// null: every one.
std::vector<stripWidth>
narrowStripWidths(const surfaceMesh &m, const std::vector<SPoint3> &flat,
                  const std::function<double(const SPoint3 &)> &size,
                  double share,
                  const std::function<bool(int, int)> &side = nullptr);

} // namespace reparam

#endif
