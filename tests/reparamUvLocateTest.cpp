// Reparam - points just outside a discrete face's (u, v) image are taken on
// the closest triangle (the uv locate hook, patches/0007)

#include <vector>
#include <gtest/gtest.h>
#include "MTriangle.h"
#include "MVertex.h"
#include "reparamUvLocate.h"

TEST(reparamUvLocate, pointOutsideGoesToTheClosestBoundaryPoint)
{
  // An L-shaped image: the squares [0,1]x[0,1], [1,2]x[0,1] and [0,1]x[1,2], two triangles each;
  // a chord from (2, 1) to (1, 2) leaves the image at its reflex corner
  std::vector<MVertex> v;
  v.reserve(8);
  const double xy[8][2] = {{0, 0}, {1, 0}, {2, 0}, {0, 1},
                           {1, 1}, {2, 1}, {0, 2}, {1, 2}};
  for(const auto &p : xy) v.emplace_back(p[0], p[1], 0.);
  std::vector<MTriangle> t = {
    MTriangle(&v[0], &v[1], &v[4]), MTriangle(&v[0], &v[4], &v[3]),
    MTriangle(&v[1], &v[2], &v[5]), MTriangle(&v[1], &v[5], &v[4]),
    MTriangle(&v[3], &v[4], &v[7]), MTriangle(&v[3], &v[7], &v[6])};
  // in the notch of the L, nearer the top of the right square than the
  // right side of the top square: onto that top edge, on its triangle
  double u = 1.5, w = 1.2;
  MTriangle *found = reparamClosestUvTriangle(t, u, w);
  ASSERT_NE(found, nullptr);
  EXPECT_EQ(found, &t[3]);
  EXPECT_NEAR(u, 1.5, 1e-15);
  EXPECT_NEAR(w, 1., 1e-15);
  // below the bottom edge: straight up onto it, on the triangle of that edge
  u = 1.75, w = -0.5;
  found = reparamClosestUvTriangle(t, u, w);
  EXPECT_EQ(found, &t[2]);
  EXPECT_NEAR(u, 1.75, 1e-15);
  EXPECT_NEAR(w, 0., 1e-15);
  // nothing to find in nothing
  std::vector<MTriangle> none;
  EXPECT_EQ(reparamClosestUvTriangle(none, u, w), nullptr);
}
