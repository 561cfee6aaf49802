// Reparam - the input's nodes within a distance of a point, found by a walk
// from a triangle near it: the same nodes as a search of all of them

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include "inputNodesNear.h"
#include "surfaceMesh.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  std::vector<int> bruteForce(const surfaceMesh &m, const SPoint3 &center,
                              double radius)
  {
    std::vector<int> nodes;
    for(std::size_t i = 0; i < m.points.size(); i++)
      if(m.points[i].distance(center) <= radius) nodes.push_back((int)i);
    return nodes;
  }

  // The triangle of m with a corner nearest to p
  int triangleNear(const surfaceMesh &m, const SPoint3 &p)
  {
    int best = 0;
    double d = 1e300;
    for(std::size_t t = 0; t < m.triangles.size(); t++)
      for(int v : m.triangles[t])
        if(m.points[v].distance(p) < d) {
          d = m.points[v].distance(p);
          best = (int)t;
        }
    return best;
  }

} // namespace

TEST(inputNodesNear, theNodesWithinTheRadiusAsAFullSearchFindsThem)
{
  // a jittered grid lifted on a bump: uneven triangles on a curved surface
  testTriangulation t = jitteredGrid(30, 0.3, 7);
  for(SPoint3 &p : t.points)
    p =
      SPoint3(p.x(), p.y(), 0.2 * std::sin(3. * p.x()) * std::cos(2. * p.y()));
  const surfaceMesh m = asSurfaceMesh(t);
  const inputNodesNear near(m);
  int checked = 0;
  for(double x : {0.05, 0.31, 0.5, 0.77})
    for(double y : {0.12, 0.5, 0.93})
      for(double radius : {0.01, 0.05, 0.12}) {
        const SPoint3 c(x, y, 0.2 * std::sin(3. * x) * std::cos(2. * y));
        std::vector<int> found = near.within(triangleNear(m, c), c, radius);
        std::sort(found.begin(), found.end());
        EXPECT_EQ(found, bruteForce(m, c, radius))
          << "at " << x << " " << y << " radius " << radius;
        checked += !found.empty();
      }
  EXPECT_GT(checked, 20); // most balls hold nodes
  // no start triangle: none
  EXPECT_TRUE(near.within(-1, SPoint3(0.5, 0.5, 0.), 1.).empty());
}
