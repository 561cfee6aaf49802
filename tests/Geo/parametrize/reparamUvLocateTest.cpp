// Reparam - points just outside a discrete face's (u, v) image are taken on
// the closest triangle (the uv locate hook, patches/0007); points inside
// found by a tree of the triangles' boxes (patches/0021)

#include <cmath>
#include <vector>
#include <gtest/gtest.h>
#include "MElementOctree.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "SPoint2.h"
#include "SPoint3.h"
#include "reparamHooks.h"
#include "reparamHooks.h"


TEST(reparamUvLocate, pointOutsideGoesToTheClosestBoundaryPoint)
{
  // An L-shaped image: the squares [0,1]x[0,1], [1,2]x[0,1] and [0,1]x[1,2],
  // two triangles each; a chord from (2, 1) to (1, 2) leaves the image at its
  // reflex corner
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

TEST(reparamUvLocate, theTreeFindsWhatGmshsOctreeFinds)
{
  // A fan of 12 triangles around (0.3, 0.2), its rim on a wobbly circle
  std::vector<MVertex> v;
  v.reserve(13);
  v.emplace_back(0.3, 0.2, 0.);
  for(int k = 0; k < 12; k++) {
    const double a = 2. * M_PI * k / 12., r = 1. + 0.3 * (k % 3 == 0);
    v.emplace_back(0.3 + r * std::cos(a), 0.2 + r * std::sin(a), 0.);
  }
  std::vector<MTriangle> t;
  for(int k = 0; k < 12; k++)
    t.emplace_back(&v[0], &v[1 + k], &v[1 + (k + 1) % 12]);
  std::vector<MElement *> elements;
  for(MTriangle &e : t) elements.push_back(&e);
  MElementOctree octree(elements);
  reparamUvLocator *locator = reparamNewUvLocator(t); // the automatic map
  ASSERT_NE(locator, nullptr);
  for(int i = -15; i <= 15; i++)
    for(int j = -15; j <= 15; j++) {
      const double u = 0.3 + 0.1 * i, w = 0.2 + 0.1 * j;
      MElement *gmsh = octree.find(u, w, 0., -1, true);
      MElement *tree = reparamFindUvTriangle(locator, &octree, t, u, w);
      // the same triangle, or both inside within Gmsh's tolerance (a point
      // on a shared edge)
      ASSERT_EQ(gmsh == nullptr, tree == nullptr) << u << " " << w;
      if(gmsh != tree) {
        double xyz[3] = {u, w, 0.}, uvw[3];
        tree->xyz2uvw(xyz, uvw);
        EXPECT_TRUE(tree->isInside(uvw[0], uvw[1], uvw[2]));
      }
    }
  // without a locator (Gmsh's own map): the octree's answer
  EXPECT_EQ(reparamFindUvTriangle(nullptr, &octree, t, 0.35, 0.25),
            octree.find(0.35, 0.25, 0., -1, true));
  reparamDeleteUvLocator(locator);
}

TEST(reparamUvLocate, parFromPointAnswersKeptPerPoint)
{
  std::vector<MVertex> v;
  v.reserve(3);
  v.emplace_back(0., 0., 0.);
  v.emplace_back(1., 0., 0.);
  v.emplace_back(0., 1., 0.);
  std::vector<MTriangle> t = {MTriangle(&v[0], &v[1], &v[2])};
  reparamUvLocator *locator = reparamNewUvLocator(t);
  ASSERT_NE(locator, nullptr);
  // a search that counts its calls and answers (x + z, y)
  int searches = 0;
  auto search = [&](const SPoint3 &q) {
    searches++;
    return SPoint2(q.x() + q.z(), q.y());
  };
  const SPoint3 p(0.25, 0.5, 0.125), q(0.25, 0.5, 0.1250000001);
  SPoint2 uv = reparamParFromPoint(locator, p, search);
  EXPECT_EQ(searches, 1);
  EXPECT_EQ(uv.x(), 0.375);
  EXPECT_EQ(uv.y(), 0.5);
  // asked again: the answer kept, no search
  uv = reparamParFromPoint(locator, p, search);
  EXPECT_EQ(searches, 1);
  EXPECT_EQ(uv.x(), 0.375);
  // another point, however close, is searched
  uv = reparamParFromPoint(locator, q, search);
  EXPECT_EQ(searches, 2);
  EXPECT_NEAR(uv.x(), 0.3750000001, 1e-15);
  // without a locator (Gmsh's own map): searched every time
  reparamParFromPoint(nullptr, p, search);
  reparamParFromPoint(nullptr, p, search);
  EXPECT_EQ(searches, 4);
  reparamDeleteUvLocator(locator);
}
