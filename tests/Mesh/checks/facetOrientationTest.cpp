// Reparam - facets of a triangle soup turned to agree with their neighbours

#include <map>
#include <gtest/gtest.h>
#include "facetOrientation.h"

using namespace reparam;

namespace {

  // a strip of 2 n facets over a grid of 2 x (n + 1) nodes, all turned
  // the same way
  std::vector<std::array<int, 3> > strip(int n)
  {
    std::vector<std::array<int, 3> > f;
    for(int i = 0; i < n; i++) {
      f.push_back({{2 * i, 2 * i + 2, 2 * i + 1}});
      f.push_back({{2 * i + 1, 2 * i + 2, 2 * i + 3}});
    }
    return f;
  }

  // whether every edge used twice is used in both directions
  bool consistent(const std::vector<std::array<int, 3> > &f,
                  const facetRepair &r)
  {
    std::map<std::pair<int, int>, int> directed;
    for(std::size_t i = 0; i < f.size(); i++) {
      if(r.drop[i]) continue;
      std::array<int, 3> g = f[i];
      if(r.reverse[i]) std::swap(g[1], g[2]);
      for(int k = 0; k < 3; k++)
        if(++directed[{g[k], g[(k + 1) % 3]}] > 1) return false;
    }
    return true;
  }

} // namespace

TEST(facetOrientation, aConsistentSurfaceIsUnchanged)
{
  const std::vector<std::array<int, 3> > f = strip(10);
  const facetRepair r = orientFacets(f);
  EXPECT_EQ(r.reversed, 0u);
  EXPECT_EQ(r.dropped, 0u);
  EXPECT_TRUE(consistent(f, r));
}

TEST(facetOrientation, theFewReversedFacetsAreTurned)
{
  std::vector<std::array<int, 3> > f = strip(10);
  for(int i : {3, 8, 9, 15}) std::swap(f[i][1], f[i][2]);
  const facetRepair r = orientFacets(f);
  EXPECT_EQ(r.reversed, 4u); // the minority, not the other 16
  for(int i : {3, 8, 9, 15}) EXPECT_TRUE(r.reverse[i]) << i;
  EXPECT_TRUE(consistent(f, r));
}

TEST(facetOrientation, aRepeatedFacetIsDroppedWhicheverWayItTurns)
{
  std::vector<std::array<int, 3> > f = strip(4);
  f.push_back({{f[2][0], f[2][2], f[2][1]}}); // the closed two-facet piece
  f.push_back({{0, 0, 1}}); // degenerate: left alone
  const facetRepair r = orientFacets(f);
  EXPECT_EQ(r.dropped, 1u);
  EXPECT_TRUE(r.drop[8]);
  EXPECT_FALSE(r.drop[9]);
  EXPECT_FALSE(r.reverse[9]);
  EXPECT_EQ(r.reversed, 0u);
  EXPECT_TRUE(r.droppedPieces.empty());
}

TEST(facetOrientation, aPieceOfFacetsOnEachOtherIsDroppedWhole)
{
  // a strip, a two-facet pillow beside it and a double-sided sheet of four
  // facets: kept as one facet each they would be open pieces
  std::vector<std::array<int, 3> > f = strip(3);
  f.push_back({{100, 101, 102}});
  f.push_back({{100, 102, 101}});
  for(std::array<int, 3> g : strip(2)) {
    for(int &n : g) n += 200;
    f.push_back(g);
    std::swap(g[1], g[2]);
    f.push_back(g);
  }
  const facetRepair r = orientFacets(f);
  EXPECT_EQ(r.dropped, 10u);
  for(std::size_t i = 0; i < f.size(); i++) EXPECT_EQ(r.drop[i], i >= 6) << i;
  ASSERT_EQ(r.droppedPieces.size(), 2u);
  EXPECT_EQ(f[r.droppedPieces[0]][0], 100);
  EXPECT_GE(f[r.droppedPieces[1]][0], 200);
  EXPECT_EQ(r.reversed, 0u);
}

TEST(facetOrientation, separatePiecesEachKeepTheirMajority)
{
  std::vector<std::array<int, 3> > f = strip(3);
  for(std::array<int, 3> g : strip(3)) { // a second piece, all reversed
    for(int &n : g) n += 100;
    std::swap(g[1], g[2]);
    f.push_back(g);
  }
  const facetRepair r = orientFacets(f);
  EXPECT_EQ(r.reversed, 0u);
  EXPECT_TRUE(consistent(f, r));
}
