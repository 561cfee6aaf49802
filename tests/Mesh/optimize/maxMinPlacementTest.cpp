// Reparam - the place of a node that lifts the worst triangle around it most

#include <cmath>
#include <random>
#include <gtest/gtest.h>
#include "maxMinPlacement.h"
#include "triangleQuality.h"

using namespace reparam;

namespace {

  // The ring of a node inside the regular hexagon of radius 1 (z = 0),
  // counterclockwise seen from +z
  std::vector<std::array<SPoint3, 2> > hexagonRing()
  {
    std::vector<std::array<SPoint3, 2> > ring;
    for(int k = 0; k < 6; k++)
      ring.push_back(
        {{SPoint3(std::cos(k * M_PI / 3.), std::sin(k * M_PI / 3.), 0.),
          SPoint3(std::cos((k + 1) * M_PI / 3.), std::sin((k + 1) * M_PI / 3.),
                  0.)}});
    return ring;
  }

} // namespace

TEST(maxMinPlacement, aNodeOffTheCentreOfAHexagonGoesBackToIt)
{
  const auto ring = hexagonRing();
  const SVector3 up(0., 0., 1.);
  const SPoint3 start(0.6, -0.25, 0.);
  const double before = worstRingKappa(start, start, ring, up);
  const SPoint3 best = maxMinKappaPoint(start, ring, up, 0.25);
  EXPECT_LT(best.distance(SPoint3(0., 0., 0.)), 0.02);
  EXPECT_GT(worstRingKappa(best, start, ring, up), 0.99); // equilateral
  EXPECT_LT(before, 0.6);
  EXPECT_NEAR(best.z(), 0., 1e-12); // in the ring's plane
}

TEST(maxMinPlacement, neverWorseNorTurnedOver)
{
  // rings of 5-8 jittered neighbours, the node anywhere inside
  std::mt19937 random(3);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25);
  const SVector3 up(0., 0., 1.);
  for(int trial = 0; trial < 200; trial++) {
    const int n = 5 + trial % 4;
    std::vector<SPoint3> around;
    for(int k = 0; k < n; k++) {
      const double a = 2. * M_PI * (k + 0.3 * jitter(random)) / n;
      const double r = 1. + jitter(random);
      around.push_back(SPoint3(r * std::cos(a), r * std::sin(a), 0.));
    }
    std::vector<std::array<SPoint3, 2> > ring;
    for(int k = 0; k < n; k++)
      ring.push_back({{around[k], around[(k + 1) % n]}});
    const SPoint3 start(0.4 * jitter(random), 0.4 * jitter(random), 0.);
    const double before = worstRingKappa(start, start, ring, up);
    if(before < 0.) continue;
    const SPoint3 best = maxMinKappaPoint(start, ring, up, 0.25);
    const double after = worstRingKappa(best, start, ring, up);
    EXPECT_GE(after, before);
    // every triangle still counterclockwise
    for(const auto &o : ring)
      EXPECT_GT(dot(crossprod(SVector3(best, o[0]), SVector3(best, o[1])), up),
                0.);
  }
  // nothing to lift: the start
  EXPECT_EQ(maxMinKappaPoint(SPoint3(1., 2., 3.), {}, up, 0.25)
              .distance(SPoint3(1., 2., 3.)),
            0.);
}
