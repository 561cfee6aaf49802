// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Closed pieces of a triangle soup that enclose no volume and are smaller
// than the input's own triangles: a needle or a crumpled sheet a
// segmentation leaves between two labels. Every triangulation of such a
// piece is slivers (its facets are; a mesh coarser than the input can only
// be worse), and the planar meshers get faces of a few hundredths of the
// size. Like the pillows of repeated facets (facetOrientation.h) they are
// dropped whole; a thin part larger than the input's triangles is kept.

#ifndef FLAT_PIECES_H
#define FLAT_PIECES_H

#include <array>
#include <vector>

namespace reparam {

struct flatPieceDrop {
  std::vector<bool> drop; // per facet
  std::size_t dropped = 0; // facets
  std::vector<int> pieces; // a facet of each piece dropped
};

// A piece is closed when each of its edges is used by exactly two of its
// facets. It is flat when its mean thickness, 3 |volume| / area, is below a
// hundredth of its bounding box's diagonal, and small when that diagonal
// is below `size` (the edge of the equilateral triangles as many as the
// input's, the layout's noise size). Facets with skip[i] set are no piece's.
flatPieceDrop findFlatPieces(const std::vector<std::array<double, 3> > &nodes,
                             const std::vector<std::array<int, 3> > &facets,
                             const std::vector<bool> &skip, double size);

// The area of the non-skipped, non-degenerate facets, and their count
double facetArea(const std::vector<std::array<double, 3> > &nodes,
                 const std::vector<std::array<int, 3> > &facets,
                 const std::vector<bool> &skip, std::size_t &count);

} // namespace reparam

#endif
