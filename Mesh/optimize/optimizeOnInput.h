// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Local optimization of a new surface mesh on the input triangulation it was
// made from: edge flips and node moves around the triangles of poor shape.
// The planar mesher makes triangles good in the (u, v) plane's metric, but a
// triangle larger than the input's spans places where the map's Jacobian
// changes (its corners' images are not where a uniform stretch puts them),
// and thin folds and strips give slivers in 3D: on the shared scans most
// triangles below kappa 0.3 have no edge on a curve (bench/README.md,
// Optimization on the input). Every node moved lands on the input (its
// closest point), and a change is kept only if it raises the worst kappa of
// the triangles it touches, leaves none of them pointing against the input,
// and takes none of them farther from the input than they were (beyond a
// small share of their size). The steps live in Mesh/optimize/internal/
// (flips, moves, smoothing sweeps, ring measures); this is their one entry.

#ifndef OPTIMIZE_ON_INPUT_H
#define OPTIMIZE_ON_INPUT_H

#include <cstddef>
#include <vector>
#include "optimizableMesh.h"

namespace reparam {

class closestTriangleSearch;

struct meshOptimizationOptions {
  // triangles below this kappa get their edges and inner corners tried
  double target = 0.6;
  int maxPasses = 4;
  // how much farther from the input a change may take a triangle, as a share
  // of its longest edge (a flip across a crease of the input cuts it off)
  double tolerance = 0.02;
  // ... unless the flip lifts a triangle below `sliver`: then this share
  // (a chord a fifth of its length off a curved input is better than a
  // sliver there: bench/README.md, Flips of slivers)
  double sliver = 0.3, sliverTolerance = 0.2;
  // the same for a node move (the node stays on the input: the centroids
  // of the triangles around it move off a curved input by their sag, which
  // grows as a sliver becomes a fat triangle of the same edges;
  // bench/README.md, Optimization on the input)
  double moveTolerance = 0.1;
  // the mesh's triangles turn against the input's (most of them do)
  bool reversed = false;
  // per triangle, whether the caller knows it lies along the input (it was
  // checked already): not tested again (empty: all are tested)
  std::vector<bool> knownAlong;
  // inner input nodes farther from the mesh than this share of the edges
  // around are inserted (a crease or tip the mesh cuts off; 0: none)
  double insertAbove = 0.25;
  // inner edges longer than this times the size at their ends are split
  // (Mesh/optimize/longEdgeSplit.h), those shorter than collapseBelow times
  // it collapsed (Mesh/optimize/shortEdgeCollapse.h; 0: none)
  double splitAbove = 1.6, collapseBelow = 0.;
  int maxInsertionRounds = 3;
  // the flips and moves stop after this many searches of the input per
  // triangle (with 1000 more), counted over all rounds
  std::size_t searchesPerTriangle = 30;
  // then sweeps moving every movable node to its neighbours' centroid, the
  // mean of the points that make its triangles equilateral, or halfway to
  // either, where the mean kappa of its ring rises by smoothGain, its worst
  // does not fall and none falls below the target: the rows of triangles
  // along the curves, which the frontal mesher left uneven and the
  // targeted moves do not reach (bench/README.md, Smoothing), then the
  // targeted flips and moves again
  int smoothPasses = 3;
  double smoothGain = 1e-3;
  // each sweep begins with flips of the edges whose four corners'
  // valences come closer to a mesh of equilateral triangles' (6 inside):
  // an input node inserted in a triangle has valence 3, a collapse leaves
  // one of 7 or 8, and no node move makes their triangles equilateral
  bool valenceFlips = true;
  // a smoothing move takes no triangle farther from the input (as a node
  // move, moveTolerance), and leaves the node's old place and the input's
  // points closest to the ring's centroids (on a crease under the feature
  // angle the mesh held, points of the crease) no farther from the ring
  // than this share of its longest edge beyond where they were (more lets
  // the ring leave such a crease: bench/README.md, Smoothing; 0: no
  // smoothing on a curved input)
  double smoothTolerance = 0.02;
};

struct meshOptimizationResult {
  double minBefore = 1., minAfter = 1.; // kappa
  std::size_t belowBefore = 0, belowAfter = 0; // triangles below the target
  std::size_t againstBefore = 0, againstAfter = 0; // triangles
  std::size_t flips = 0, moves = 0, passes = 0;
  // input nodes the mesh cut off, now mesh nodes: new ones, or `snapped`
  // onto a node moved there (Mesh/optimize/farInputNodes.h)
  std::size_t inserted = 0, snapped = 0;
  std::size_t splits = 0; // long edges
  std::size_t collapses = 0; // short edges
  // tangles re-meshed (Mesh/optimize/tangledCavity.h)
  std::size_t cavities = 0;
  std::size_t searches = 0; // of the input, by the flips and moves
};

// Optimizes m in place against the input triangulation `input` (searched by
// onInput, built on it), in rounds while nodes are added: inserts the inner
// input nodes the mesh cuts off (Mesh/optimize/farInputNodes.h), splits the
// long edges (Mesh/optimize/longEdgeSplit.h) and collapses the short ones
// (Mesh/optimize/shortEdgeCollapse.h), then flips edges not locked and
// moves movable nodes, projected on the input, around the triangles below
// the target or pointing against the input (which count as worse than any
// triangle along it), pass after pass until a pass keeps no change; then
// re-meshes the tangles left (Mesh/optimize/tangledCavity.h), and smooths
// (o.smoothPasses sweeps) before the flips and moves once more.
// m's triangles must turn the same way; the per-point and per-triangle
// arrays it lacks are made (landing, inputNode -1, movable false, origin
// and triangleOrigin the index now)
meshOptimizationResult optimizeOnInput(optimizableMesh &m,
                                       const surfaceMesh &input,
                                       const closestTriangleSearch &onInput,
                                       const meshOptimizationOptions &o = {});

} // namespace reparam

#endif
