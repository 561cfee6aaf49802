// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Diagonal collapses that make a mesh of quadrangles more regular. The edge
// rotations (Mesh/quad/quadEdgeRotation.h) move an irregular node but keep how
// many there are; most of those Frontal-Delaunay for quads and Blossom
// leave come as a node of valence 3 next to two of valence 5 across a
// quadrangle, corners of valence 3, 4, 5, 5 in turn
// (bench/README.md#quadrangles-collapsed-along-a-diagonal).
// Collapsing such a quadrangle along the diagonal of its other two corners
// merges them into one node (valence the sum less 2) and takes one
// quadrangle from each of the two corners left: 3 + 4 - 2 = 5 and 5 - 1 =
// 4 twice, three irregular nodes become one.

#ifndef QUAD_DIAGONAL_COLLAPSE_H
#define QUAD_DIAGONAL_COLLAPSE_H

#include <cmath>
#include <cstddef>
#include <functional>
#include <vector>
#include "SPoint3.h"

namespace reparam {

class closestTriangleSearch;
struct surfaceMesh;

struct quadCollapseOptions {
  // every quadrangle around the merged node at least this eta (the node
  // moves after better them)
  double minEta = 0.3;
  // ... and turned by less than this from where it was (radians)
  double maxTurn = M_PI / 4.;
  int maxPasses = 4;
  // with an input: both nodes' old places within nodeTolerance times the
  // quadrangle's mean side from the new quadrangles (a node on a tip or a
  // crease stays: without this test the Hausdorff distance rose on the
  // scans, bench/README.md#quadrangles-collapsed-along-a-diagonal), and the
  // new quadrangles' centres no farther from the input than the old ones'
  // by more than tolerance times it
  double nodeTolerance = 0.1, tolerance = 0.05;
  // the size asked at a point (empty: none): a quadrangle whose mean side
  // is over `largest` times the size at its centre does not collapse (its
  // neighbours grow into it)
  std::function<double(const SPoint3 &)> size;
  double largest = 1.1;
  // the input surface the mesh lies on (null: not projected): the merged
  // node goes to the input's point closest to where it is tried
  const closestTriangleSearch *onInput = nullptr;
};

struct quadCollapseResult {
  std::size_t collapses = 0;
  // inner nodes (elements closed around them) of valence other than 4
  std::size_t irregularBefore = 0, irregularAfter = 0;
  int passes = 0;
};

// Collapses quadrangles of m along a diagonal, pass after pass until none
// is or o.maxPasses are done, where the squared distance of the four
// corners' valences to their ideal (Mesh/quad/quadEdgeRotation.h, computed
// before the first pass) falls. Only quadrangles whose diagonal joins two
// points of the same owner as the quadrangle (owner per point, -1: fixed,
// a curve's node; part per quadrangle; empty part: all 0) collapse, whose
// corners share no other neighbour, none of them on a triangle, and whose
// merged node has a place (the diagonal's midpoint, or its new neighbours'
// centroid, each on the input) where its quadrangles pass o's tests (the
// best worst eta of the two). The
// merged node is the diagonal's first corner, moved there; mergedInto[i]
// is the point i went into (-1: kept), removed[q] whether quadrangle q
// went; the others keep their places in m.quadrangles, removed ones stay
// there too (the caller drops them)
quadCollapseResult collapseQuadDiagonals(surfaceMesh &m,
                                         const std::vector<int> &part,
                                         const std::vector<int> &owner,
                                         std::vector<int> &mergedInto,
                                         std::vector<bool> &removed,
                                         const quadCollapseOptions &o = {});

} // namespace reparam

#endif
