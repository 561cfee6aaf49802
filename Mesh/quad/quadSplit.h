// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Quadrangles split into two triangles. After the recombination, the edge
// rotations, the diagonal collapses and the node moves, the worst
// quadrangles left are those with three corners along a curve that bends
// by 10-20 degrees there (a corner of 160-170 degrees): no node move
// squares them up, the curve's nodes stay on it. Split along the diagonal
// from that corner, they make two fair triangles, the inverse of
// Mesh/quad/triangleMerge.h's pairs
// (bench/README.md#quadrangles-with-a-flat-corner-split).

#ifndef QUAD_SPLIT_H
#define QUAD_SPLIT_H

#include <array>
#include <vector>

namespace reparam {

struct surfaceMesh;

struct quadSplit {
  int quadrangle; // of the mesh
  // its two triangles, in its orientation, along the diagonal chosen
  std::array<std::array<int, 3>, 2> triangles;
  double eta; // the quadrangle's
  double kappa; // the worse of its two triangles'
};

// The quadrangles of m of eta below maxEta, each split along the diagonal
// whose worse triangle is the better, where both of those triangles reach
// kappa minKappa and beat the quadrangle's eta (0: better is enough);
// worst quadrangle first
std::vector<quadSplit> quadSplits(const surfaceMesh &m, double maxEta,
                                  double minKappa);

} // namespace reparam

#endif
