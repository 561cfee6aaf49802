// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// A triangulation whose boundary nodes are replaced by other nodes on the
// same boundary polyline: the safety net that keeps a face's input
// triangles in the mesh when no map can parametrize it, stitched to the 1D
// meshes of its curves (Gmsh places them on the input's boundary edges, at
// other points than the input's nodes) so that its neighbours' meshes meet
// it without a gap.

#ifndef BOUNDARY_STITCH_H
#define BOUNDARY_STITCH_H

#include <array>
#include <vector>
#include "SPoint3.h"

namespace reparam {

struct stitchedTriangulation {
  // nodes 0 .. points.size() - 1 are the input's, then boundaryNodes[k] is
  // node points.size() + k; input nodes of the boundary are no longer used
  std::vector<std::array<int, 3> > triangles;
  // boundary nodes farther than the tolerance from the input's boundary
  // (left out), input boundary nodes that could not be removed (kept)
  std::size_t unplacedNodes = 0, keptInputNodes = 0;
  // triangles whose normal turned against the input's by the removals
  std::size_t turnedTriangles = 0;
};

// Each boundary node is inserted on the input's boundary edge it lies on
// (within `tolerance`, absolute), taking the place of an input node it
// coincides with; then every other input node of the boundary loops that
// got boundary nodes is collapsed onto a boundary neighbour, the one that
// turns no triangle if it can (a loop without any is left as it is; a
// node whose only triangle is a sliver's tip goes with that triangle when
// its third edge stays inside).
// Labels, when given, say which curve or corner each point is on, so that
// boundary edges of different curves lying on each other (a degenerate
// triangle's) are told apart: a node goes to an edge whose both ends carry
// one of its labels, or to a point with its label, if one is near enough.
stitchedTriangulation
stitchToBoundaryNodes(const std::vector<SPoint3> &points,
                      const std::vector<std::array<int, 3> > &triangles,
                      const std::vector<SPoint3> &boundaryNodes,
                      double tolerance,
                      const std::vector<int> &pointLabels = {},
                      const std::vector<std::vector<int> > &nodeLabels = {});

} // namespace reparam

#endif
