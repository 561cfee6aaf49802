// Reparam - the map of a planar patch: its projection on its plane, what
// Gmsh's discrete faces mesh; rounding-scale folds of the input not counted

#include <cmath>
#include <gtest/gtest.h>
#include "bijectivityCheck.h"
#include "mapKind.h"
#include "parametrize.h"
#include "planeProjection.h"
#include "testPatches.h"

namespace {

  // t turned about the axis (1, 1, 0) by 40 degrees and moved: a plane no
  // coordinate plane
  testTriangulation tilted(testTriangulation t)
  {
    const double a = 40. * M_PI / 180., c = std::cos(a), s = std::sin(a);
    const double k = 1. / std::sqrt(2.);
    for(SPoint3 &p : t.points) {
      // Rodrigues' rotation about the unit axis (k, k, 0)
      const double x = p.x(), y = p.y(), z = p.z();
      const double dot = k * x + k * y;
      const double cx = k * z, cy = -k * z, cz = k * y - k * x;
      p = SPoint3(x * c + cx * s + k * dot * (1 - c) + 3.,
                  y * c + cy * s + k * dot * (1 - c) - 2., z * c + cz * s + 5.);
    }
    return t;
  }

  // The unit square as two triangles, and a sliver on its bottom edge whose
  // third node is `overlap` above that edge: inside the square, the sliver
  // turned over onto it (a CAD export's outline doubling back)
  testTriangulation squareWithTurnedSliver(double overlap)
  {
    testTriangulation t;
    t.points = {SPoint3(0, 0, 0), SPoint3(1, 0, 0), SPoint3(1, 1, 0),
                SPoint3(0, 1, 0), SPoint3(0.5, overlap, 0)};
    t.triangles = {{{0, 1, 2}}, {{0, 2, 3}}, {{1, 0, 4}}};
    return t;
  }

  double uvDistance(const std::vector<double> &uv, int a, int b)
  {
    return std::hypot(uv[2 * a] - uv[2 * b], uv[2 * a + 1] - uv[2 * b + 1]);
  }

} // namespace

TEST(planeProjection, aPlaneInSpaceIsPlanarABentPatchIsNot)
{
  const testTriangulation disk = polarDisk(6, 24);
  EXPECT_TRUE(patchIsPlanar(makePatchOrDie(tilted(disk)), 1e-6));
  EXPECT_FALSE(patchIsPlanar(makePatchOrDie(tilted(disk)), 0.));
  // bent by 1e-4 of its size: planar at 1e-3, not at Gmsh's 1e-6
  const discretePatch bent = makePatchOrDie(tilted(liftPlanar(disk, 1e-4)));
  EXPECT_FALSE(patchIsPlanar(bent, 1e-6));
  EXPECT_TRUE(patchIsPlanar(bent, 1e-3));
}

TEST(planeProjection, theProjectionIsASimilarityOfThePlane)
{
  const discretePatch p = makePatchOrDie(tilted(polarDisk(6, 24)));
  double scale = 0.;
  const patchMap m = planeProjectionMap(p, &scale);
  ASSERT_EQ(m.uv.size(), 2 * p.points.size());
  ASSERT_GT(scale, 0.);
  for(const auto &t : p.triangles)
    for(int k = 0; k < 3; k++) {
      const int a = t[k], b = t[(k + 1) % 3];
      EXPECT_NEAR(uvDistance(m.uv, a, b),
                  scale * p.points[a].distance(p.points[b]), 1e-12);
    }
  // counterclockwise, boundary at a root mean square distance of 1
  EXPECT_TRUE(checkBijectivity(p, m.uv).bijective());
  EXPECT_EQ(checkBijectivity(p, m.uv).orientation, 1);
  double rms = 0.;
  const std::vector<int> &loop = p.boundaryLoops[0];
  for(int i : loop) rms += std::pow(uvDistance(m.uv, i, 0), 2);
  EXPECT_NEAR(std::sqrt(rms / loop.size()), 1., 1e-9);
}

TEST(planeProjection, aFoldOfTheInputsRoundingIsNoFoldALargerOneIs)
{
  // 1e-9 of the square: below Gmsh's planar tolerance, one-to-one with a
  // degenerate image
  const discretePatch rounding = makePatchOrDie(squareWithTurnedSliver(1e-9));
  EXPECT_FALSE(
    checkBijectivity(rounding, planeProjectionMap(rounding).uv).bijective());
  const checkedMap kept = planeProjection(rounding, 1e-6);
  ASSERT_EQ(kept.attempts.size(), 1u);
  EXPECT_EQ(kept.attempts[0].map, (int)compoundParametrization::plane);
  EXPECT_TRUE(kept.bijective);
  EXPECT_EQ(kept.attempts[0].flipped, 0u);
  EXPECT_EQ(kept.attempts[0].degenerate, 1u);

  const discretePatch turned = makePatchOrDie(squareWithTurnedSliver(0.01));
  const checkedMap folded = planeProjection(turned, 1e-6);
  EXPECT_FALSE(folded.bijective);
  EXPECT_EQ(folded.attempts[0].flipped, 1u);
}

TEST(planeProjection, parametrizeMapsAPlanarPatchOnItsPlaneWithItsHoles)
{
  const discretePatch p = makePatchOrDie(
    tilted(polarDiskWithHoles(10, 40, {{{3, 6, 0, 6}}, {{3, 6, 20, 26}}})));
  parametrizeOptions o;
  o.planeTolerance = 1e-6;
  const parametrization plane = parametrize(p, o);
  ASSERT_TRUE(plane.ok());
  EXPECT_EQ(plane.chosen().map, (int)compoundParametrization::plane);
  EXPECT_EQ(plane.holes, 2u);
  EXPECT_EQ(plane.filledHoles, 0);
  EXPECT_TRUE(checkBijectivity(p, plane.result.map.uv).bijective());
  // without the tolerance, the chain on the filled patch
  o.planeTolerance = 0.;
  const parametrization chain = parametrize(p, o);
  ASSERT_TRUE(chain.ok());
  EXPECT_EQ(chain.chosen().map, (int)compoundParametrization::spectral);
  EXPECT_EQ(chain.filledHoles, 2);
}

TEST(planeProjection, aPlanarPatchFoldedOntoItselfIsMappedAsAnyOther)
{
  // a sliver turned over by 1 % of the square: the projection is tried
  // first, the chain's map kept
  const discretePatch p = makePatchOrDie(squareWithTurnedSliver(0.01));
  parametrizeOptions o;
  o.planeTolerance = 1e-6;
  const parametrization m = parametrize(p, o);
  ASSERT_TRUE(m.ok());
  ASSERT_GE(m.result.attempts.size(), 2u);
  EXPECT_EQ(m.result.attempts[0].map, (int)compoundParametrization::plane);
  EXPECT_FALSE(m.result.attempts[0].bijective());
  EXPECT_EQ(m.chosen().map, (int)compoundParametrization::spectral);
  EXPECT_TRUE(checkBijectivity(p, m.result.map.uv).bijective());
}
