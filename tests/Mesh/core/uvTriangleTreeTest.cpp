// Reparam - the (u, v) point location of discrete faces (Mesh/core/uvTriangleTree)

#include <random>
#include <gtest/gtest.h>
#include "uvTriangleTree.h"

using namespace reparam;

namespace {

  // An n x n grid of the unit square, each cell cut in two, its nodes moved
  // by up to a third of a cell: triangles of unequal sizes
  std::vector<std::array<double, 6> > jitteredGrid(int n, unsigned seed)
  {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> jitter(-0.3 / n, 0.3 / n);
    std::vector<double> x((n + 1) * (n + 1)), y((n + 1) * (n + 1));
    for(int j = 0; j <= n; j++)
      for(int i = 0; i <= n; i++) {
        const bool inside = i > 0 && i < n && j > 0 && j < n;
        x[j * (n + 1) + i] = (double)i / n + (inside ? jitter(random) : 0.);
        y[j * (n + 1) + i] = (double)j / n + (inside ? jitter(random) : 0.);
      }
    std::vector<std::array<double, 6> > t;
    auto corner = [&](int i, int j, std::array<double, 6> &c, int k) {
      c[2 * k] = x[j * (n + 1) + i];
      c[2 * k + 1] = y[j * (n + 1) + i];
    };
    for(int j = 0; j < n; j++)
      for(int i = 0; i < n; i++) {
        std::array<double, 6> a, b;
        corner(i, j, a, 0);
        corner(i + 1, j, a, 1);
        corner(i + 1, j + 1, a, 2);
        corner(i, j, b, 0);
        corner(i + 1, j + 1, b, 1);
        corner(i, j + 1, b, 2);
        t.push_back(a);
        t.push_back(b);
      }
    return t;
  }

  // Barycentric test, written independently of the tree's
  bool inside(const std::array<double, 6> &c, double u, double v, double tol)
  {
    auto cross = [](double ax, double ay, double bx, double by) {
      return ax * by - ay * bx;
    };
    const double area =
      cross(c[2] - c[0], c[3] - c[1], c[4] - c[0], c[5] - c[1]);
    const double l1 =
      cross(c[4] - c[2], c[5] - c[3], u - c[2], v - c[3]) / area;
    const double l2 =
      cross(c[0] - c[4], c[1] - c[5], u - c[4], v - c[5]) / area;
    const double l0 = 1. - l1 - l2;
    return l0 >= -tol && l1 >= -tol && l2 >= -tol;
  }

} // namespace

TEST(uvTriangleTree, findsTheTriangleHoldingEachPoint)
{
  const std::vector<std::array<double, 6> > t = jitteredGrid(40, 7);
  uvTriangleTree tree(t);
  EXPECT_GT(tree.numBoxes(), t.size() / 4);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> in(0., 1.);
  for(int k = 0; k < 2000; k++) {
    const double u = in(random), v = in(random);
    const int found = tree.find(u, v);
    ASSERT_GE(found, 0) << u << " " << v;
    EXPECT_TRUE(inside(t[found], u, v, 1e-6)) << u << " " << v;
    // the same with a hint, right or wrong
    EXPECT_EQ(tree.find(u, v, found), found);
    const int other = tree.find(u, v, (found + 17) % (int)t.size());
    ASSERT_GE(other, 0);
    EXPECT_TRUE(inside(t[other], u, v, 1e-6));
  }
}

TEST(uvTriangleTree, outsideWithinTheToleranceOnly)
{
  const std::vector<std::array<double, 6> > t = jitteredGrid(10, 3);
  uvTriangleTree tree(t);
  // the square's corners and sides (never moved) are found
  EXPECT_GE(tree.find(0., 0.), 0);
  EXPECT_GE(tree.find(1., 0.5), 0);
  // just outside: within 1e-6 of the cell (barycentric), found; beyond, not
  EXPECT_GE(tree.find(-1e-8, 0.5), 0);
  EXPECT_EQ(tree.find(-1e-3, 0.5), -1);
  EXPECT_EQ(tree.find(0.5, 1.01), -1);
  EXPECT_EQ(tree.find(2., 2.), -1);
  // a flat triangle holds nothing; an empty tree finds nothing
  uvTriangleTree flat(std::vector<std::array<double, 6> >(
    1, std::array<double, 6>{{0., 0., 1., 0., 2., 0.}}));
  EXPECT_EQ(flat.find(0.5, 0.), -1);
  uvTriangleTree none((std::vector<std::array<double, 6> >()));
  EXPECT_EQ(none.find(0., 0.), -1);
  EXPECT_EQ(none.numBoxes(), 0u);
}
