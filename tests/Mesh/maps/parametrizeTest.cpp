// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The stage's entry parametrize(): hole filling, the chain, the fallback of
// a map chosen by hand, the outcome; and the map cache it reads.

#include <gtest/gtest.h>
#include "bijectivityCheck.h"
#include "mapCache.h"
#include "parametrize.h"
#include "reparamOptions.h"
#include "testPatches.h"

namespace {

  const std::vector<std::array<int, 4> > twoHoles = {{{3, 6, 0, 6}},
                                                     {{3, 6, 20, 26}}};

  parametrizeOptions optionsFor(compoundParametrization map)
  {
    parametrizeOptions o;
    o.map = (int)map;
    return o;
  }

} // namespace

TEST(parametrize, holesAreFilledAndTheMapIsOneToOneOnThePatchsNodes)
{
  discretePatch p =
    makePatchOrDie(liftPlanar(polarDiskWithHoles(10, 40, twoHoles), 0.3));
  ASSERT_EQ(p.boundaryLoops.size(), 3u);
  parametrization m =
    parametrize(p, optionsFor(compoundParametrization::meanValue));
  ASSERT_TRUE(m.ok());
  EXPECT_EQ(m.holes, 2u);
  EXPECT_EQ(m.filledHoles, 2);
  EXPECT_EQ(m.skippedHoles, 0);
  EXPECT_EQ(m.result.map.uv.size(), 2 * p.points.size());
  EXPECT_TRUE(checkBijectivity(p, m.result.map.uv).bijective());
  EXPECT_TRUE(holesFillable(p));

  parametrizeOptions free = optionsFor(compoundParametrization::meanValue);
  free.fillHoles = false;
  parametrization unfilled = parametrize(p, free);
  ASSERT_TRUE(unfilled.ok());
  EXPECT_EQ(unfilled.holes, 2u);
  EXPECT_EQ(unfilled.filledHoles, 0);
}

// One and a half turns of a ramp: both conformal maps fold. The automatic
// chain ends on the mean value map; LSCM chosen by hand is replaced by it
TEST(parametrize, aFoldingMapChosenByHandFallsBackToMeanValue)
{
  discretePatch p = makePatchOrDie(helicoidStrip(120, 6, 1.5, 1., 2., 0.05));
  parametrization chain =
    parametrize(p, optionsFor(compoundParametrization::automatic));
  ASSERT_TRUE(chain.ok());
  EXPECT_EQ(chain.chosen().map, (int)compoundParametrization::meanValue);
  EXPECT_EQ(chain.result.attempts.size(), 3u);
  EXPECT_TRUE(chain.fallbackAttempts.empty());

  parametrization lscm =
    parametrize(p, optionsFor(compoundParametrization::conformal));
  ASSERT_TRUE(lscm.ok());
  EXPECT_TRUE(lscm.usedFallback);
  ASSERT_EQ(lscm.failedChoice, 0);
  EXPECT_GE(lscm.result.attempts[0].foldsAfter, 1u);
  ASSERT_EQ(lscm.fallbackAttempts.size(), 1u);
  EXPECT_EQ(lscm.result.attempts.size(), 2u);
  EXPECT_EQ(lscm.result.chosen, 1);
  EXPECT_EQ(lscm.chosen().map, (int)compoundParametrization::meanValue);
  EXPECT_TRUE(lscm.result.bijective);
  EXPECT_TRUE(checkBijectivity(p, lscm.result.map.uv).bijective());
}

TEST(parametrize, anUnknownMapIsNotImplemented)
{
  discretePatch p = makePatchOrDie(polarDisk(4, 12));
  parametrizeOptions o;
  o.map = 9;
  EXPECT_EQ(parametrize(p, o).outcome, parametrizeOutcome::notImplemented);
}

// The layout keeps its maps, CreateGeometry takes them: the same (u, v) to
// the last bit, each map taken once, only for the same patch and choice
TEST(parametrize, aMapKeptInTheCacheIsTakenOnceForTheSamePatch)
{
  discretePatch p = makePatchOrDie(sphericalCap(8, 32, 1.));
  mapCache cache;
  parametrizeOptions keep = optionsFor(compoundParametrization::automatic);
  keep.cache = &cache;
  keep.keepInCache = true;
  parametrization computed = parametrize(p, keep);
  ASSERT_TRUE(computed.ok());
  EXPECT_FALSE(computed.fromCache);
  EXPECT_EQ(cache.size(), 1u);

  parametrizeOptions other = optionsFor(compoundParametrization::meanValue);
  other.cache = &cache;
  EXPECT_FALSE(parametrize(p, other).fromCache);
  EXPECT_EQ(cache.size(), 1u);

  parametrizeOptions take = optionsFor(compoundParametrization::automatic);
  take.cache = &cache;
  parametrization taken = parametrize(p, take);
  EXPECT_TRUE(taken.fromCache);
  EXPECT_EQ(taken.result.map.uv, computed.result.map.uv);
  EXPECT_EQ(cache.size(), 0u);
  EXPECT_FALSE(parametrize(p, take).fromCache);

  discretePatch moved = makePatchOrDie(sphericalCap(8, 32, 1.01));
  parametrize(p, keep);
  EXPECT_FALSE(parametrize(moved, take).fromCache);
  cache.clear();
  EXPECT_EQ(cache.size(), 0u);
}
