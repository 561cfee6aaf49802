// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Local repair of flipped triangles (the paper's Sec. 5, Fig. 10-11): the
// cavity check moves an interior node into the kernel of its one-ring
// polygon; on free boundaries (conformal maps) the boundary check moves a
// node along its projection onto the segment of its two boundary neighbours.
// Folds are not repaired here: the automatic chain switches map.

#ifndef FLIP_REPAIR_H
#define FLIP_REPAIR_H

#include <cstddef>
#include <vector>
#include "discretePatch.h"

namespace reparam {

struct flipRepairResult {
  std::size_t flippedBefore = 0;
  std::size_t flippedAfter = 0;
  int movedNodes = 0; // moves accepted, over all passes
  int passes = 0;
};

// Repairs the triangles of uv whose orientation differs from `orientation`
// (+1 or -1, see bijectivityReport), at most maxPasses sweeps over the
// flipped triangles' nodes. With freeBoundary false, boundary nodes never
// move (maps onto a fixed convex boundary). Every move leaves all triangles
// around the moved node with the right orientation (exact predicates), so
// the number of flipped triangles never grows.
flipRepairResult repairFlips(const discretePatch &patch,
                             std::vector<double> &uv, int orientation,
                             bool freeBoundary, int maxPasses = 10);

// The kernel of a star (the region from which every edge (a_k, b_k) is seen
// on its left, for orientation +1), clipped to `box` (umin, vmin, umax,
// vmax), as a polygon; empty if there is none. Exposed for the tests.
std::vector<std::array<double, 2> >
starKernel(const std::vector<std::array<double, 4> > &edges,
           const std::array<double, 4> &box, int orientation);

} // namespace reparam

#endif
