// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Node splits that make a mesh of quadrangles more regular: the inverse of
// the diagonal collapses (Mesh/quad/quadDiagonalCollapse.h). A node of
// valence 5 whose ring holds two nodes of valence 3 two sides apart is split
// in two along them, with a new quadrangle between the halves: the halves
// get valences 3 and 4, each of the two nodes one more (3 + 1 = 4), three
// irregular nodes become one. Frontal-Delaunay for quads and Blossom leave
// such nodes where the collapses cannot reach (bench/README.md#nodes-split).

#ifndef QUAD_NODE_SPLIT_H
#define QUAD_NODE_SPLIT_H

#include <cmath>
#include <cstddef>
#include <vector>

namespace reparam {

class closestTriangleSearch;
struct surfaceMesh;

struct quadNodeSplitOptions {
  // every quadrangle around the two halves at least this eta (the node
  // moves after better them) ...
  double minEta = 0.3;
  // ... the old ones turned by less than this from where they were and the
  // new one from their mean normal (radians)
  double maxTurn = M_PI / 4.;
  int maxPasses = 4;
  // with an input: the node's old place within nodeTolerance times the mean
  // side of its quadrangles from the new ones (the mesh keeps passing
  // there), so are the input's nodes under them (or no farther than from
  // the old ones), and the new quadrangles' centres no farther from the
  // input than the old ones' by more than tolerance times that side
  double nodeTolerance = 0.1, tolerance = 0.05;
  // the input surface the mesh lies on and its search (null: not
  // projected): the halves go to the input's points closest to where they
  // are tried
  const surfaceMesh *input = nullptr;
  const closestTriangleSearch *onInput = nullptr;
};

struct quadNodeSplitResult {
  std::size_t splits = 0;
  // inner nodes (elements closed around them) of valence other than 4
  std::size_t irregularBefore = 0, irregularAfter = 0;
  int passes = 0;
};

// Splits inner nodes of m, pass after pass until none is or o.maxPasses are
// done, where the squared distance of the valences of the node, its two
// halves and the two nodes of its ring they are split along to their ideal
// (Mesh/quad/quadEdgeRotation.h, computed before the first pass) falls. Only
// nodes of an owner (owner per point, -1: fixed, a curve's node) all of
// whose elements are quadrangles of that part (part per quadrangle; empty
// part: all 0) split, along two nodes of their ring not joined already, and
// only where the halves have places (their quadrangles' corners' centroid,
// or halfway to it, on the input) passing o's tests. The first half keeps
// the node's index; the second is a new point of m (the same owner, its
// index in splitFrom, the node split), the new quadrangle is appended to
// m.quadrangles and to part (the node's part)
quadNodeSplitResult splitQuadNodes(surfaceMesh &m, std::vector<int> &part,
                                   std::vector<int> &owner,
                                   std::vector<int> &splitFrom,
                                   const quadNodeSplitOptions &o = {});

} // namespace reparam

#endif
