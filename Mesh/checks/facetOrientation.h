// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Facets of a triangle soup turned to agree with their neighbours. STL files
// from scanners and exporters often have some facets reversed; Gmsh keeps
// them, so its ClassifySurfaces sees a 180 degree crease around each one
// (a tiny feature patch) and every test of a mesh against the input's
// orientation finds them pointing the other way. Facets using the same three
// nodes as another are dropped (a closed two-facet piece: Gmsh's split loop
// never ends on it).

#ifndef FACET_ORIENTATION_H
#define FACET_ORIENTATION_H

#include <array>
#include <vector>

namespace reparam {

struct facetRepair {
  std::vector<bool> reverse, drop; // per facet
  std::size_t reversed = 0, dropped = 0;
  // a facet of each piece made of repeated facets only, dropped whole
  // (counted in `dropped`)
  std::vector<int> droppedPieces;
};

// Across every edge used by exactly two kept facets, the second must use it
// in the other direction; each connected piece keeps the orientation of the
// larger part of its facets (by count), so a consistent input is
// unchanged. Facets are node index triples; degenerate ones (a repeated
// node) are left alone. Of facets using the same three nodes the first is
// kept, unless their piece is made of such facets only: a closed
// zero-volume pillow, dropped whole rather than left as an open facet.
facetRepair orientFacets(const std::vector<std::array<int, 3> > &facets);

} // namespace reparam

#endif
