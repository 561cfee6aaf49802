// Reparam - closed pieces without volume, smaller than the input's triangles

#include <gtest/gtest.h>
#include "facetPieces.h"
#include "flatPieces.h"

using namespace reparam;

namespace {

  struct soup {
    std::vector<std::array<double, 3> > nodes;
    std::vector<std::array<int, 3> > facets;
  };

  // An octahedron of half-axes 1, 1 and c around (x, 0, 0), its 8 facets
  // turned outwards
  void addOctahedron(soup &s, double c, double x = 0.)
  {
    const int o = (int)s.nodes.size();
    s.nodes.push_back({{x + 1., 0., 0.}});
    s.nodes.push_back({{x, 1., 0.}});
    s.nodes.push_back({{x - 1., 0., 0.}});
    s.nodes.push_back({{x, -1., 0.}});
    s.nodes.push_back({{x, 0., c}});
    s.nodes.push_back({{x, 0., -c}});
    for(int k = 0; k < 4; k++) {
      s.facets.push_back({{o + k, o + (k + 1) % 4, o + 4}});
      s.facets.push_back({{o + (k + 1) % 4, o + k, o + 5}});
    }
  }

} // namespace

TEST(facetPieces, piecesJoinThroughEdgesNotThroughSkippedFacets)
{
  soup s;
  addOctahedron(s, 1.);
  addOctahedron(s, 1., 5.);
  std::vector<int> root = facetPieceRoots(s.facets);
  for(int i = 1; i < 8; i++) EXPECT_EQ(root[i], root[0]);
  for(int i = 9; i < 16; i++) EXPECT_EQ(root[i], root[8]);
  EXPECT_NE(root[0], root[8]);
  // without the 4 upper facets, the lower 4 still join through the equator's
  // nodes only where they share an edge: every lower facet shares one with
  // the next
  std::vector<bool> skip(16, false);
  for(int k = 0; k < 4; k++) skip[2 * k] = true;
  root = facetPieceRoots(s.facets, &skip);
  for(int k = 0; k < 4; k++) {
    EXPECT_EQ(root[2 * k], 2 * k);
    EXPECT_EQ(root[2 * k + 1], root[1]);
  }
}

TEST(facetPieces, aPieceIsClosedWhenEachEdgeHasTwoFacets)
{
  soup s;
  addOctahedron(s, 1.);
  addOctahedron(s, 1., 5.);
  s.facets.pop_back(); // the second left open
  std::vector<char> closed;
  const std::vector<int> root = facetPieceRoots(s.facets, nullptr, &closed);
  EXPECT_TRUE(closed[root[0]]);
  EXPECT_FALSE(closed[root[8]]);
  // skipping a facet of the first opens it
  std::vector<bool> skip(s.facets.size(), false);
  skip[3] = true;
  const std::vector<int> without = facetPieceRoots(s.facets, &skip, &closed);
  EXPECT_FALSE(closed[without[0]]);
}

TEST(flatPieces, aFlatClosedPieceSmallerThanTheSizeIsDroppedWhole)
{
  soup s;
  addOctahedron(s, 1e-3);
  const std::vector<bool> skip(s.facets.size(), false);
  // diagonal 2.83: within a size of 5, not of 2
  flatPieceDrop r = findFlatPieces(s.nodes, s.facets, skip, 5.);
  EXPECT_EQ(r.dropped, 8u);
  ASSERT_EQ(r.pieces.size(), 1u);
  for(bool d : r.drop) EXPECT_TRUE(d);
  r = findFlatPieces(s.nodes, s.facets, skip, 2.);
  EXPECT_EQ(r.dropped, 0u);
  EXPECT_TRUE(r.pieces.empty());
}

TEST(flatPieces, aPieceWithVolumeOrOpenIsKept)
{
  soup s;
  // mean thickness 0.41 of a diagonal of 2.87: volume
  addOctahedron(s, 0.5);
  // flat, but open: its last facet left out
  addOctahedron(s, 1e-3, 5.);
  s.facets.pop_back();
  const std::vector<bool> skip(s.facets.size(), false);
  const flatPieceDrop r = findFlatPieces(s.nodes, s.facets, skip, 10.);
  EXPECT_EQ(r.dropped, 0u);
}

TEST(flatPieces, onlyTheFlatPieceGoesAlsoFarFromTheOrigin)
{
  // coordinates of 1e4 with a thickness of 1e-4: the volume is taken about
  // a node of the piece, not the origin
  soup s;
  addOctahedron(s, 0.3, 1e4);
  addOctahedron(s, 1e-4, 1e4 + 5.);
  std::vector<bool> skip(s.facets.size(), false);
  flatPieceDrop r = findFlatPieces(s.nodes, s.facets, skip, 4.);
  EXPECT_EQ(r.dropped, 8u);
  ASSERT_EQ(r.pieces.size(), 1u);
  EXPECT_GE(r.pieces[0], 8);
  for(int i = 0; i < 8; i++) EXPECT_FALSE(r.drop[i]);
  // a skipped facet leaves the flat piece open: kept
  skip[9] = true;
  r = findFlatPieces(s.nodes, s.facets, skip, 4.);
  EXPECT_EQ(r.dropped, 0u);
}

TEST(flatPieces, facetAreaSumsTheUsableFacets)
{
  soup s;
  addOctahedron(s, 0.);
  s.facets.push_back({{0, 0, 1}}); // a repeated node
  std::vector<bool> skip(s.facets.size(), false);
  skip[0] = true;
  std::size_t count = 0;
  // the flat octahedron's facets: right triangles of legs 1, area 0.5
  EXPECT_NEAR(facetArea(s.nodes, s.facets, skip, count), 3.5, 1e-12);
  EXPECT_EQ(count, 7u);
}
