// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Who is next to whom in a mesh of quadrangles (and triangles), for the
// changes of its topology (Mesh/quad/quadDiagonalCollapse.h,
// Mesh/quad/quadNodeSplit.h), which keep it exact as they go.

#ifndef QUAD_CONNECTIVITY_H
#define QUAD_CONNECTIVITY_H

#include <set>
#include <vector>

namespace reparam {

struct surfaceMesh;

struct quadConnectivity {
  // per point: the points it shares an element side with, the quadrangles
  // it is a corner of, whether it is a triangle's corner
  std::vector<std::set<int> > neighbours, quadsAt;
  std::vector<bool> onTriangle;

  // From m, without the quadrangles marked in `removed` (null: none)
  void build(const surfaceMesh &m, const std::vector<bool> *removed = nullptr);

  // The squared distance of point v's valence, changed by `change`, to
  // its ideal
  double cost(int v, int change, const std::vector<int> &ideal) const
  {
    const double d = (double)neighbours[v].size() + change - ideal[v];
    return d * d;
  }
};

} // namespace reparam

#endif
