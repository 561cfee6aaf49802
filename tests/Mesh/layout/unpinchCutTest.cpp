// Reparam - a cut that pinches a side is moved, and a part pinched by its
// own boundary is parted between its fans

#include <cmath>
#include <set>
#include <vector>
#include <gtest/gtest.h>
#include "patchLayout.h"
#include "triangleAdjacency.h"
#include "unpinchCut.h"

using namespace reparam;

namespace {

  // n x n unit cells, two triangles each (cell (i, j): triangles 2 (i n + j)
  // and 2 (i n + j) + 1); node (i, j) is i (n + 1) + j
  layoutMesh cellGrid(int n)
  {
    layoutMesh m;
    for(int i = 0; i <= n; i++)
      for(int j = 0; j <= n; j++) m.points.push_back(SPoint3(i, j, 0));
    auto node = [n](int i, int j) { return i * (n + 1) + j; };
    for(int i = 0; i < n; i++)
      for(int j = 0; j < n; j++) {
        m.triangles.push_back(
          {{node(i, j), node(i + 1, j), node(i + 1, j + 1)}});
        m.triangles.push_back(
          {{node(i, j), node(i + 1, j + 1), node(i, j + 1)}});
      }
    return m;
  }

  // The most fans the triangles of one side make around any node
  int mostFans(const layoutMesh &m, const std::vector<int> &part,
               const std::vector<char> &side)
  {
    int most = 0;
    for(std::size_t v = 0; v < m.points.size(); v++)
      for(char s = 0; s < 2; s++) {
        std::vector<int> at; // part positions around v on side s
        for(std::size_t i = 0; i < part.size(); i++)
          for(int n : m.triangles[part[i]])
            if(n == (int)v && side[i] == s) at.push_back((int)i);
        // fans: joined when the two triangles share an edge through v
        std::vector<int> fan(at.size());
        for(std::size_t i = 0; i < at.size(); i++) fan[i] = (int)i;
        for(int pass = 0; pass < 8; pass++)
          for(std::size_t i = 0; i < at.size(); i++)
            for(std::size_t j = 0; j < at.size(); j++) {
              std::set<int> shared;
              for(int x : m.triangles[part[at[i]]])
                for(int y : m.triangles[part[at[j]]])
                  if(x == y) shared.insert(x);
              if(shared.size() == 2) fan[i] = fan[j] = std::min(fan[i], fan[j]);
            }
        most =
          std::max(most, (int)std::set<int>(fan.begin(), fan.end()).size());
      }
    return most;
  }

  // unpinchCut leaves `side` as it is, and says it moved no fan
  void expectCutKept(const layoutMesh &m, const triangleAdjacency &a,
                     const std::vector<int> &part, std::vector<char> side)
  {
    const std::vector<char> kept = side;
    EXPECT_EQ(unpinchCut(m, a, part, side), 0u);
    EXPECT_EQ(side, kept);
  }

} // namespace

TEST(unpinchCut, aCutThroughANodeTwiceIsMoved)
{
  // 4 x 4 cells, quadrants alternating sides like a checkerboard: each
  // side's triangles make two fans at the centre node (2, 2)
  const layoutMesh m = cellGrid(4);
  const triangleAdjacency a = makeTriangleAdjacency(m.triangles);
  std::vector<int> part;
  std::vector<char> side;
  for(int i = 0; i < 4; i++)
    for(int j = 0; j < 4; j++)
      for(int k = 0; k < 2; k++) {
        part.push_back(2 * (4 * i + j) + k);
        side.push_back((i < 2) != (j < 2));
      }
  ASSERT_EQ(mostFans(m, part, side), 2);
  const std::vector<char> before = side;
  EXPECT_EQ(unpinchCut(m, a, part, side), 1u);
  EXPECT_EQ(mostFans(m, part, side), 1);
  // only triangles at the centre node moved
  for(std::size_t i = 0; i < part.size(); i++)
    if(side[i] != before[i]) {
      bool atCentre = false;
      for(int n : m.triangles[part[i]]) atCentre |= n == 2 * 5 + 2;
      EXPECT_TRUE(atCentre) << part[i];
    }
  // a cut that pinches nothing is left as it is
  std::vector<char> halves(part.size());
  for(std::size_t i = 0; i < part.size(); i++) halves[i] = part[i] < 16;
  expectCutKept(m, a, part, halves);
}

TEST(unpinchCut, aPartPinchedByItsBoundaryIsPartedBetweenItsFans)
{
  // 3 x 3 cells less the centre one (a hole) and the corner cell (2, 2):
  // the ring is open there, cells (1, 2) and (2, 1) touching at node (2, 2)
  const layoutMesh m = cellGrid(3);
  const triangleAdjacency a = makeTriangleAdjacency(m.triangles);
  std::vector<int> part;
  for(int c = 0; c < 9; c++)
    if(c != 4 && c != 8)
      for(int k = 0; k < 2; k++) part.push_back(2 * c + k);
  ASSERT_EQ(mostFans(m, part, std::vector<char>(part.size(), 0)), 2);
  const std::vector<char> side = separateFansAtPinch(m, a, part);
  ASSERT_EQ(side.size(), part.size());
  EXPECT_EQ(mostFans(m, part, side), 1);
  // the two cells at the pinch on different sides
  auto sideOfCell = [&](int c) {
    for(std::size_t i = 0; i < part.size(); i++)
      if(part[i] / 2 == c) return (int)side[i];
    return -1;
  };
  EXPECT_NE(sideOfCell(1 * 3 + 2), sideOfCell(2 * 3 + 1));
  // the full grid is pinched nowhere
  std::vector<int> all;
  for(int t = 0; t < 18; t++) all.push_back(t);
  EXPECT_TRUE(separateFansAtPinch(m, a, all).empty());
}

TEST(unpinchCut, twoClosedFansAtANodeArePinchedOneIsNot)
{
  // two cones with the same apex: around it every triangle has both its
  // neighbours through the apex, yet they make two fans (two rings); one
  // cone alone has no pinched node
  layoutMesh m;
  m.points.push_back(SPoint3(0, 0, 0)); // the apex
  const int n = 6;
  for(int cone = 0; cone < 2; cone++)
    for(int k = 0; k < n; k++) {
      const double a = 2 * M_PI * k / n, z = cone ? 1. : -1.;
      m.points.push_back(SPoint3(std::cos(a), std::sin(a), z));
    }
  for(int cone = 0; cone < 2; cone++)
    for(int k = 0; k < n; k++)
      m.triangles.push_back(
        {{0, 1 + cone * n + k, 1 + cone * n + (k + 1) % n}});
  const triangleAdjacency a = makeTriangleAdjacency(m.triangles);
  std::vector<int> both(2 * n), one(n);
  for(int t = 0; t < 2 * n; t++) both[t] = t;
  for(int t = 0; t < n; t++) one[t] = t;
  const std::vector<char> side = separateFansAtPinch(m, a, both);
  ASSERT_EQ(side.size(), both.size());
  for(int t = 0; t < 2 * n; t++)
    EXPECT_EQ(side[t], side[0] == 0 ? t >= n : t < n);
  EXPECT_TRUE(separateFansAtPinch(m, a, one).empty());
  // the two rings on sides of their own: no fan to move
  std::vector<char> apart(2 * n, 0);
  for(int t = n; t < 2 * n; t++) apart[t] = 1;
  expectCutKept(m, a, both, apart);
}

TEST(unpinchCut, neighboursGivenOrFoundGiveTheSameParts)
{
  // the layout finds a part's neighbours once and hands them to each step:
  // the same components, cut and moves as each step finding them itself
  const layoutMesh m = cellGrid(6);
  const triangleAdjacency a = makeTriangleAdjacency(m.triangles);
  // two blocks of cells joined at one node only, and the whole grid
  std::vector<int> blocks, all(m.triangles.size());
  for(int i = 0; i < 6; i++)
    for(int j = 0; j < 6; j++)
      if((i < 3 && j < 3) || (i >= 3 && j >= 3))
        for(int k = 0; k < 2; k++) blocks.push_back(2 * (6 * i + j) + k);
  for(std::size_t t = 0; t < all.size(); t++) all[t] = (int)t;
  for(const std::vector<int> &part : {blocks, all}) {
    const auto across = partNeighbours(a, part, m.triangles.size());
    EXPECT_EQ(partComponents(a, part, m.triangles.size(), &across),
              partComponents(a, part, m.triangles.size()));
    EXPECT_EQ(separateFansAtPinch(m, a, part, &across),
              separateFansAtPinch(m, a, part));
    std::vector<char> given =
      bisectPart(m, a, part, 0, partCheck(), nullptr, &across);
    std::vector<char> found = bisectPart(m, a, part);
    EXPECT_EQ(given, found);
    EXPECT_EQ(unpinchCut(m, a, part, given, &across),
              unpinchCut(m, a, part, found));
    EXPECT_EQ(given, found);
  }
  EXPECT_EQ(partComponents(a, blocks, m.triangles.size()).size(), 2u);
}
