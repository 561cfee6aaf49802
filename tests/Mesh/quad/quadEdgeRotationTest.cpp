// Reparam - edge rotations between quadrangles: a grid with one edge
// rotated the wrong way gets it back (every inner node of valence 4, every
// quadrangle a square), locked edges and edges between parts stay, the
// ideal valences of a grid are those of its own nodes

#include <algorithm>
#include <gtest/gtest.h>
#include "quadEdgeRotation.h"
#include "quadQuality.h"
#include "surfaceMesh.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  int point(int n, int i, int j) { return i + (n + 1) * j; }

  // The 4 x 4 grid with the edge between quadrangles (1, 1) and (2, 1)
  // (from point (2, 1) to (2, 2)) rotated to the diagonal from (1, 1) to
  // (3, 2): its ends have valence 3, the new one's 5
  surfaceMesh grid4WithARotatedEdge()
  {
    const int n = 4;
    surfaceMesh m = quadGrid(n);
    const int r = point(n, 1, 1), s = point(n, 1, 2), b = point(n, 2, 2);
    const int p = point(n, 3, 2), q = point(n, 3, 1), a = point(n, 2, 1);
    // hexagon a, q, p, b, s, r (counterclockwise from (2, 1))
    m.quadrangles[1 + n * 1] = {{r, a, q, p}};
    m.quadrangles[2 + n * 1] = {{p, b, s, r}};
    return m;
  }

  bool hasEdge(const surfaceMesh &m, int a, int b)
  {
    for(const auto &q : m.quadrangles)
      for(int k = 0; k < 4; k++)
        if((q[k] == a && q[(k + 1) % 4] == b) ||
           (q[k] == b && q[(k + 1) % 4] == a))
          return true;
    return false;
  }

  double worstEta(const surfaceMesh &m)
  {
    double worst = 1.;
    for(const auto &q : m.quadrangles)
      worst = std::min(worst, quadEta(m.points[q[0]], m.points[q[1]],
                                      m.points[q[2]], m.points[q[3]]));
    return worst;
  }

} // namespace

TEST(quadEdgeRotation, idealValencesOfAGrid)
{
  const surfaceMesh m = quadGrid(3);
  const std::vector<int> ideal = idealValences(m);
  const std::vector<int> valence = valences(m);
  EXPECT_EQ(ideal, valence); // a grid is as regular as it gets
  EXPECT_EQ(ideal[point(3, 0, 0)], 2); // corner
  EXPECT_EQ(ideal[point(3, 1, 0)], 3); // border
  EXPECT_EQ(ideal[point(3, 1, 1)], 4); // inner
}

TEST(quadEdgeRotation, aWronglyRotatedEdgeGoesBack)
{
  surfaceMesh m = grid4WithARotatedEdge();
  EXPECT_LT(worstEta(m), 0.6);
  const quadRotationResult r = rotateQuadEdges(m, {}, {});
  EXPECT_EQ(r.irregularBefore, 4u);
  EXPECT_EQ(r.irregularAfter, 0u);
  EXPECT_EQ(r.rotations, 1u);
  EXPECT_TRUE(hasEdge(m, point(4, 2, 1), point(4, 2, 2)));
  EXPECT_NEAR(worstEta(m), 1., 1e-12);
  for(int v : valences(m)) EXPECT_LE(v, 4);
  EXPECT_EQ(m.quadrangles.size(), 16u);
  // a second call finds nothing to do
  EXPECT_EQ(rotateQuadEdges(m, {}, {}).rotations, 0u);
}

TEST(quadEdgeRotation, lockedEdgesAndEdgesBetweenPartsStay)
{
  const int r = point(4, 1, 1), p = point(4, 3, 2);
  {
    surfaceMesh m = grid4WithARotatedEdge();
    std::set<std::pair<int, int> > locked = {
      std::make_pair(std::min(r, p), std::max(r, p))};
    rotateQuadEdges(m, {}, locked);
    EXPECT_TRUE(hasEdge(m, r, p));
  }
  {
    surfaceMesh m = grid4WithARotatedEdge();
    std::vector<int> part(m.quadrangles.size(), 0);
    part[1 + 4 * 1] = 1; // the two quadrangles on either side of (r, p)
    const quadRotationResult result = rotateQuadEdges(m, part, {});
    EXPECT_TRUE(hasEdge(m, r, p));
    EXPECT_EQ(result.irregularAfter, result.irregularBefore);
  }
}

TEST(quadEdgeRotation, noRotationMakesAPoorQuadrangle)
{
  // the same with the grid sheared so much that the square-making
  // rotation would give a quadrangle below the eta asked for
  surfaceMesh m = grid4WithARotatedEdge();
  for(SPoint3 &x : m.points) x = SPoint3(x.x() + 1.5 * x.y(), x.y(), 0.);
  quadRotationOptions o;
  o.minEta = 0.5;
  const quadRotationResult r = rotateQuadEdges(m, {}, {}, o);
  EXPECT_EQ(r.rotations, 0u);
}

TEST(quadEdgeRotation, closedRingsAndIrregularNodes)
{
  const surfaceMesh grid = quadGrid(3);
  const std::vector<bool> closed = closedRings(grid);
  EXPECT_EQ(std::count(closed.begin(), closed.end(), true), 4); // inner
  EXPECT_TRUE(closed[point(3, 1, 1)]);
  EXPECT_FALSE(closed[point(3, 1, 0)]); // border
  EXPECT_EQ(irregularNodes(grid), 0u);
  // the rotated edge's ends of valence 3, the new one's of 5
  EXPECT_EQ(irregularNodes(grid4WithARotatedEdge()), 4u);
}
