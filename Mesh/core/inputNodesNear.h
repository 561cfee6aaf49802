// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The input triangulation's nodes within a distance of a point, found by
// walking the input's triangles from one near the point: a change to the
// new mesh (an edge collapse) checks that the input nodes under it stay as
// near to the mesh as they were, without a search structure of its own.

#ifndef INPUT_NODES_NEAR_H
#define INPUT_NODES_NEAR_H

#include <vector>
#include "SPoint3.h"

namespace reparam {

struct surfaceMesh;

class inputNodesNear {
public:
  explicit inputNodesNear(const surfaceMesh &input);
  // The nodes of the triangles reached from `start` through triangles with
  // a corner within `radius` of `center`, that lie within it themselves
  std::vector<int> within(int start, const SPoint3 &center,
                          double radius) const;

private:
  const surfaceMesh &_input;
  std::vector<std::vector<int> > _around; // per node, its triangles
};

} // namespace reparam

#endif
