// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The connected pieces of a triangle soup through its edges, however many
// facets use an edge: the STL input's repairs drop or turn whole pieces.

#ifndef FACET_PIECES_H
#define FACET_PIECES_H

#include <array>
#include <vector>

namespace reparam {

// A root facet per facet (facets with a repeated node are pieces of their
// own, and join none); facets skipped (skip[i], when given) join none
// either. closed (when given), per root: whether every edge of the piece is
// used by exactly two of its facets.
std::vector<int> facetPieceRoots(const std::vector<std::array<int, 3> > &facets,
                                 const std::vector<bool> *skip = nullptr,
                                 std::vector<char> *closed = nullptr);

} // namespace reparam

#endif
