// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Mesh sizes that grow away from a face's short boundary segments. Gmsh's
// Mesh.MeshSizeExtendFromBoundary gives each boundary node the length of its
// shortest segment and interpolates these linearly over the triangulation
// of the boundary nodes the meshers start from; on a discrete face that
// first triangulation has triangles across the whole face, so one short
// segment shrinks the mesh far away from it (tau 77.8 % and 42 338 triangles
// on armadillo where the size asks for 28 468). Here a node's size only
// reaches as far as the gradient lets it.

#ifndef GRADED_BOUNDARY_SIZE_H
#define GRADED_BOUNDARY_SIZE_H

#include <vector>
#include "SPoint3.h"

class gradedBoundarySize {
public:
  // nodes[i] asks for sizes[i]; at a distance d from it, sizes[i] +
  // gradient * d. gradient > 0
  gradedBoundarySize(const std::vector<SPoint3> &nodes,
                     const std::vector<double> &sizes, double gradient);
  // the smallest size a node asks for at x, or bound if none asks for less
  double operator()(const SPoint3 &x, double bound) const;
  std::size_t size() const { return _sizes.size(); }

private:
  // by increasing size: the search stops at the first node whose own size
  // is no smaller than the best found
  std::vector<SPoint3> _nodes;
  std::vector<double> _sizes;
  double _gradient;
};

// The length of the shortest of the segments (pairs of indices into
// nodes) at each node; 0 for a node without any
std::vector<double>
shortestSegmentAtNodes(const std::vector<SPoint3> &nodes,
                       const std::vector<std::pair<int, int> > &segments);

#endif
