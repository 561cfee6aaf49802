// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The ways to split a small polygon into triangles and quadrangles along
// its diagonals. Two elements of a quadrangle mesh sharing an edge make a
// polygon of four to six corners; where one of them points against the
// input (it lies across a fold thinner than the mesh size), another split
// of the same polygon, with the same corners and sides, may follow the
// input on both sides of the fold
// (bench/README.md#elements-against-the-input-split-again).

#ifndef POLYGON_SPLITS_H
#define POLYGON_SPLITS_H

#include <array>
#include <vector>

namespace reparam {

struct polygonSplit {
  std::vector<std::array<int, 3> > triangles;
  std::vector<std::array<int, 4> > quadrangles;
};

// Every split of the polygon (its corners in order, 3 to 8 of them) into
// triangles and quadrangles whose corners are the polygon's, whose sides
// are its sides or diagonals, none crossing another, each in the
// polygon's order of corners
std::vector<polygonSplit> polygonSplits(const std::vector<int> &polygon);

} // namespace reparam

#endif
