// Reparam - how closely quadrangles follow the input: the distance of a
// point to quadrangles, their centres' farthest distance to the input, and
// a quadrangle's unit normal

#include <cmath>
#include <gtest/gtest.h>
#include "closestTriangle.h"
#include "quadFidelity.h"
#include "quadQuality.h"

using namespace reparam;

TEST(quadFidelity, distancesOfAPointAndOfTheCentres)
{
  // the unit square at height 0 and a copy folded along its diagonal 0-2:
  // corner 3 raised by 1
  const std::vector<SPoint3> x = {SPoint3(0., 0., 0.), SPoint3(1., 0., 0.),
                                  SPoint3(1., 1., 0.), SPoint3(0., 1., 0.),
                                  SPoint3(0., 1., 1.)};
  const std::vector<std::array<int, 4> > flat = {{{0, 1, 2, 3}}},
                                         folded = {{{0, 1, 2, 4}}};
  EXPECT_NEAR(distanceToQuadrangles(SPoint3(0.5, 0.5, 0.3), flat, x), 0.3,
              1e-12);
  EXPECT_NEAR(distanceToQuadrangles(SPoint3(2., 0.5, 0.), flat, x), 1., 1e-12);
  // the plane z = 0 as the input: the flat square's centres on it, the
  // folded one's diagonal 1-4 has its midpoint at height 0.5
  const std::vector<SPoint3> plane = {
    SPoint3(-5., -5., 0.), SPoint3(5., -5., 0.), SPoint3(0., 5., 0.)};
  const closestTriangleSearch onInput(plane, {{{0, 1, 2}}});
  EXPECT_NEAR(farthestCentreFromInput(flat, x, onInput), 0., 1e-12);
  EXPECT_NEAR(farthestCentreFromInput(folded, x, onInput), 0.5, 1e-12);
  // normals: +z for the counterclockwise square, zero when degenerate
  const SVector3 n = quadNormal(flat[0], x);
  EXPECT_NEAR(n.z(), 1., 1e-12);
  EXPECT_NEAR(n.norm(), 1., 1e-12);
  const std::vector<SPoint3> line = {SPoint3(0., 0., 0.), SPoint3(1., 0., 0.),
                                     SPoint3(2., 0., 0.), SPoint3(3., 0., 0.)};
  EXPECT_NEAR(quadNormal({{0, 1, 2, 3}}, line).norm(), 0., 1e-12);
}
