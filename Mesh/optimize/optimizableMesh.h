// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The mesh the optimization on the input works on: a surfaceMesh of
// triangles (no quadrangles), and beside them what must stay (movable
// nodes, locked edges) and what each step records of its points and
// triangles, so that the caller can write the changes back to its own mesh.

#ifndef OPTIMIZABLE_MESH_H
#define OPTIMIZABLE_MESH_H

#include <set>
#include <utility>
#include <vector>
#include "surfaceMesh.h"

namespace reparam {

// A triangle mesh to optimize (triangles consistently oriented), with what
// must stay
struct optimizableMesh : surfaceMesh {
  std::vector<bool> movable; // per point: an inner node, free to move
  std::set<std::pair<int, int> > lockedEdges; // (i < j): never flipped
  // per point, set by the optimizer: the input triangle a moved or new
  // point lies on (-1: not moved), and the input node a new point was
  // inserted at (-1: none)
  std::vector<int> landing, inputNode;
  // per triangle, set by the optimizer: whether it points against the input
  // (each change leaves none of its new triangles so)
  std::vector<bool> against;
  // per point, the mesh size asked there (empty: no edge is split nor
  // collapsed); a new point gets the mean of the corners of the triangle it
  // splits
  std::vector<double> size;
  // per point and per triangle, the index it had when the optimizer began
  // (-1: new); edge collapses remove points and triangles
  std::vector<int> origin, triangleOrigin;
};

// Removes the points and triangles of m marked dead, renumbering the rest
// (every per-point and per-triangle array, the locked edges); returns the
// new index of each point (-1: removed)
std::vector<int> removeDeadParts(optimizableMesh &m,
                                 const std::vector<bool> &deadPoint,
                                 const std::vector<bool> &deadTriangle);

// The worst kappa of m's triangles (1 without triangles)
double worstKappa(const optimizableMesh &m);

} // namespace reparam

#endif
