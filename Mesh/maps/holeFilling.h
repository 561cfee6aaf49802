// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Holes (Sec. 3): with the inner loops free, convex and harmonic maps lose
// their conformality near them (paper Fig. 9). Each inner loop is therefore
// triangulated on its mean plane and the map computed on the extended patch.
// No node is added, so the (u, v) of the patch's nodes are those of the
// extended patch's, and the filling triangles never enter the face's
// parametric domain: they only take part in the solve.

#ifndef HOLE_FILLING_H
#define HOLE_FILLING_H

#include <array>
#include <vector>
#include "discretePatch.h"

namespace reparam {

struct holeFilling {
  // Triangles filling the holes, oriented like the patch's
  std::vector<std::array<int, 3> > triangles;
  int filledHoles = 0;
  // Inner loops left free: their projection on the mean plane is not a
  // simple polygon that ear clipping can cut without duplicating an edge
  int skippedHoles = 0;
};

// Triangulates the polygon of one inner loop: ear clipping on its mean
// plane (Newell's normal), then Delaunay edge flips in that plane; no
// diagonal may duplicate an edge of the patch. False if it cannot.
bool triangulateHole(const discretePatch &patch, int loop,
                     std::vector<std::array<int, 3> > &triangles);

// All inner loops (every loop but patch.outerLoop)
holeFilling fillHoles(const discretePatch &patch);

} // namespace reparam

#endif
