// Reparam - the splits of a small polygon into triangles and quadrangles
// along its diagonals: as many as there are dissections of a convex
// polygon (1, 3, 10, 38 for 3 to 6 corners), each covering the polygon
// once in its orientation, none twice

#include <cmath>
#include <set>
#include <gtest/gtest.h>
#include "SPoint3.h"
#include "polygonSplits.h"

using namespace reparam;

namespace {

  // the regular polygon of n corners, counterclockwise
  std::vector<SPoint3> regular(int n)
  {
    std::vector<SPoint3> p;
    for(int i = 0; i < n; i++)
      p.push_back(
        SPoint3(std::cos(2. * M_PI * i / n), std::sin(2. * M_PI * i / n), 0.));
    return p;
  }

  double area(const std::vector<SPoint3> &x, const std::vector<int> &c)
  {
    double a = 0.;
    for(std::size_t k = 0; k < c.size(); k++) {
      const SPoint3 &p = x[c[k]], &q = x[c[(k + 1) % c.size()]];
      a += p.x() * q.y() - q.x() * p.y();
    }
    return 0.5 * a;
  }

} // namespace

TEST(polygonSplits, asManyAsTheDissectionsOfAConvexPolygon)
{
  const std::size_t expected[] = {1, 3, 10, 38, 154};
  for(int n = 3; n <= 7; n++) {
    std::vector<int> polygon;
    for(int i = 0; i < n; i++) polygon.push_back(i);
    const std::vector<polygonSplit> splits = polygonSplits(polygon);
    EXPECT_EQ(splits.size(), expected[n - 3]) << n << " corners";
    const std::vector<SPoint3> x = regular(n);
    const double whole = area(x, polygon);
    std::set<std::multiset<std::vector<int> > > distinct;
    for(const polygonSplit &s : splits) {
      double sum = 0.;
      std::multiset<std::vector<int> > elements;
      for(const auto &t : s.triangles) {
        const std::vector<int> c(t.begin(), t.end());
        EXPECT_GT(area(x, c), 0.);
        sum += area(x, c);
        elements.insert(c);
      }
      for(const auto &q : s.quadrangles) {
        const std::vector<int> c(q.begin(), q.end());
        EXPECT_GT(area(x, c), 0.);
        sum += area(x, c);
        elements.insert(c);
      }
      // 3 t + 4 q - 2 (t + q - 1) = n: each element's sides, the inner
      // ones counted twice
      EXPECT_EQ(s.triangles.size() + 2 * s.quadrangles.size() + 2,
                (std::size_t)n);
      EXPECT_NEAR(sum, whole, 1e-12);
      distinct.insert(elements);
    }
    EXPECT_EQ(distinct.size(), splits.size());
  }
}

TEST(polygonSplits, theCornersOfTheCallersPolygon)
{
  const std::vector<polygonSplit> splits = polygonSplits({7, 3, 9, 4});
  ASSERT_EQ(splits.size(), 3u);
  std::size_t quadrangles = 0;
  for(const polygonSplit &s : splits)
    for(const auto &q : s.quadrangles) {
      EXPECT_EQ(q, (std::array<int, 4>{{7, 3, 9, 4}}));
      quadrangles++;
    }
  EXPECT_EQ(quadrangles, 1u);
  EXPECT_TRUE(polygonSplits({1, 2}).empty());
}
