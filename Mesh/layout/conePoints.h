// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The tips of a triangulation: interior nodes where the surface comes to a
// point (a cone apex: a wing tip, a spike of bone). A planar mesher with a
// uniform size puts no node there unless told to, and cuts the tip off
// (bench/README.md#tips-and-creases).

#ifndef CONE_POINTS_H
#define CONE_POINTS_H

#include <array>
#include <vector>
#include "SPoint3.h"

namespace reparam {

// The interior nodes (every edge around them has two triangles) whose
// triangles' angles at them sum to less than maxAngleSum (radians; a flat
// node has 2 pi, a cube's corner 3 pi / 2, the apex of a cone of half-angle
// a has 2 pi sin a).
std::vector<int> conePoints(const std::vector<SPoint3> &points,
                            const std::vector<std::array<int, 3> > &triangles,
                            double maxAngleSum);

} // namespace reparam

#endif
