// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Mesh sizes that grow away from a face's short boundary segments. Gmsh's
// Mesh.MeshSizeExtendFromBoundary gives each boundary node the length of its
// shortest segment and interpolates these linearly over the triangulation
// of the boundary nodes the meshers start from; on a discrete face that
// first triangulation has triangles across the whole face, so one short
// segment shrinks the mesh far away from it
// (bench/README.md#sizes-from-the-curves). Here a node's size only reaches
// as far as the gradient lets it.

#ifndef GRADED_BOUNDARY_SIZE_H
#define GRADED_BOUNDARY_SIZE_H

#include <array>
#include <unordered_map>
#include <vector>
#include "SPoint3.h"

namespace reparam {

class gradedBoundarySize {
public:
  // nodes[i] asks for sizes[i]; at a distance d from it, sizes[i] +
  // gradient * d. gradient > 0; reach: the largest size the queries will be
  // bounded by (the mesh size), which sets the cells of the search
  gradedBoundarySize(const std::vector<SPoint3> &nodes,
                     const std::vector<double> &sizes, double gradient,
                     double reach);
  // the smallest size a node asks for at x, or bound if none asks for less
  double operator()(const SPoint3 &x, double bound) const;
  std::size_t size() const { return _sizes.size(); }

private:
  std::vector<SPoint3> _nodes;
  std::vector<double> _sizes;
  double _gradient, _smallest = 0., _cell = 1.;
  // the nodes by cell of a uniform grid, searched ring by ring from the
  // query's cell until no node farther can give less
  typedef std::array<long, 3> cellKey;
  struct cellHash {
    std::size_t operator()(const cellKey &c) const
    {
      return (std::size_t)(c[0] * 73856093L ^ c[1] * 19349663L ^
                           c[2] * 83492791L);
    }
  };
  std::unordered_map<cellKey, std::vector<int>, cellHash> _cells;
  cellKey _low, _high; // the cells with nodes lie between
  cellKey cellOf(const SPoint3 &x) const;
};

// The length of the shortest of the segments (pairs of indices into
// nodes) at each node; 0 for a node without any
std::vector<double>
shortestSegmentAtNodes(const std::vector<SPoint3> &nodes,
                       const std::vector<std::pair<int, int> > &segments);

} // namespace reparam

#endif
