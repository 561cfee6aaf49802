// Reparam - sharp edges that are sharp at the input's scale only (a voxel
// staircase) are no features; a CAD edge, sharp at every scale, is one

#include <cmath>
#include <utility>
#include <vector>
#include <gtest/gtest.h>
#include "SVector3.h"
#include "featureScale.h"
#include "patchLayout.h"
#include "triangleAdjacency.h"

using namespace reparam;

namespace {

  // A profile polyline in the (x, z) plane swept along y over [0, width]
  // in ny cells; each profile segment in `pieces` pieces
  layoutMesh
  sweptProfile(const std::vector<std::pair<double, double> > &profile,
               int pieces, int ny, double width)
  {
    std::vector<std::pair<double, double> > fine;
    for(std::size_t i = 0; i + 1 < profile.size(); i++)
      for(int k = 0; k < pieces; k++) {
        const double s = (double)k / pieces;
        fine.push_back(
          {profile[i].first * (1 - s) + profile[i + 1].first * s,
           profile[i].second * (1 - s) + profile[i + 1].second * s});
      }
    fine.push_back(profile.back());
    layoutMesh m;
    const int nx = (int)fine.size();
    for(int i = 0; i < nx; i++)
      for(int j = 0; j <= ny; j++)
        m.points.push_back(
          SPoint3(fine[i].first, width * j / ny, fine[i].second));
    auto node = [&](int i, int j) { return i * (ny + 1) + j; };
    for(int i = 0; i + 1 < nx; i++)
      for(int j = 0; j < ny; j++) {
        m.triangles.push_back(
          {{node(i, j), node(i + 1, j), node(i + 1, j + 1)}});
        m.triangles.push_back(
          {{node(i, j), node(i + 1, j + 1), node(i, j + 1)}});
      }
    return m;
  }

  // Stairs of `steps` unit treads and unit risers (90 degree edges, turning
  // up then back), what a voxel mask of an inclined plane looks like
  layoutMesh staircase(int steps)
  {
    std::vector<std::pair<double, double> > p;
    for(int s = 0; s < steps; s++) {
      p.push_back({s, s});
      p.push_back({s + 1, s});
    }
    p.push_back({steps, steps});
    return sweptProfile(p, 4, 4 * steps, steps);
  }

  // A plate folded at 90 degrees along x = 5: one CAD edge
  layoutMesh foldedPlate()
  {
    return sweptProfile({{0, 0}, {5, 0}, {5, 5}}, 20, 20, 5);
  }

  // The edges whose two triangles' normals differ by more than 40 degrees
  // (ClassifySurfaces' test), as flags of the adjacency's edges
  std::vector<char> sharpEdges(const layoutMesh &m, const triangleAdjacency &a)
  {
    std::vector<char> sharp(a.edges.size(), 0);
    for(std::size_t e = 0; e < a.edges.size(); e++) {
      if(a.numTriangles((int)e) != 2) continue;
      SVector3 n[2];
      for(int i = 0; i < 2; i++) {
        const auto &t = m.triangles[a.edgeTriangles[a.edgeStart[e] + i]];
        n[i] = crossprod(SVector3(m.points[t[0]], m.points[t[1]]),
                         SVector3(m.points[t[0]], m.points[t[2]]));
        n[i].normalize();
      }
      sharp[e] = dot(n[0], n[1]) < std::cos(40. * M_PI / 180.);
    }
    return sharp;
  }

  int count(const std::vector<char> &flags)
  {
    int n = 0;
    for(char f : flags) n += f;
    return n;
  }

} // namespace

TEST(featureScale, aStaircaseIsSmoothAtThreeSteps)
{
  const layoutMesh m = staircase(12);
  const triangleAdjacency a = makeTriangleAdjacency(m.triangles);
  std::vector<char> sharp = sharpEdges(m, a);
  // 23 step edges (12 risers, each between two treads), 48 segments each
  ASSERT_EQ(count(sharp), 23 * 48);
  // seen over a radius of 3 steps, an edge in the middle turns less than
  // 45 degrees: the treads and risers on each side average to the slope
  const int middle = a.find((int)((12 * 4) * (4 * 12 + 1) + 24),
                            (int)((12 * 4) * (4 * 12 + 1) + 25));
  ASSERT_GE(middle, 0);
  ASSERT_TRUE(sharp[middle]);
  const double atScale = dihedralAtScale(m, a, middle, 3.);
  EXPECT_GE(atScale, 0.);
  EXPECT_LT(atScale, 0.25 * M_PI) << atScale * 180. / M_PI;
  // at a radius below a step it is as sharp as it is
  EXPECT_NEAR(dihedralAtScale(m, a, middle, 0.2), 0.5 * M_PI, 1e-9);
  const std::size_t dropped = dropFeaturesBelowScale(m, a, 3., sharp);
  // all but the edges within about a radius of the stairs' two ends
  EXPECT_GE(dropped, 19u * 48u);
  EXPECT_EQ(count(sharp) + (int)dropped, 23 * 48);
}

TEST(featureScale, aFoldIsSharpAtAnyScale)
{
  const layoutMesh m = foldedPlate();
  const triangleAdjacency a = makeTriangleAdjacency(m.triangles);
  std::vector<char> sharp = sharpEdges(m, a);
  ASSERT_EQ(count(sharp), 20);
  for(double radius : {0.5, 2., 10.}) {
    for(std::size_t e = 0; e < sharp.size(); e++)
      if(sharp[e])
        EXPECT_NEAR(dihedralAtScale(m, a, (int)e, radius), 0.5 * M_PI, 1e-9);
    std::vector<char> kept = sharp;
    EXPECT_EQ(dropFeaturesBelowScale(m, a, radius, kept), 0u);
    EXPECT_EQ(kept, sharp);
  }
  // radius 0: nothing looked at
  std::vector<char> kept = sharp;
  EXPECT_EQ(dropFeaturesBelowScale(m, a, 0., kept), 0u);
}

TEST(featureScale, theLayoutKeepsOnePatchOfAStaircase)
{
  layoutMesh m = staircase(12);
  const triangleAdjacency a = makeTriangleAdjacency(m.triangles);
  const std::vector<char> sharp = sharpEdges(m, a);
  for(std::size_t e = 0; e < sharp.size(); e++)
    if(sharp[e]) m.featureEdges.push_back(a.edges[e]);
  partVerifier anyPart = [](const std::vector<int> &) { return partCheck(); };
  layoutParameters p;
  const layoutResult every = computePatchLayout(m, p, anyPart);
  EXPECT_EQ(every.featurePatches, 24); // every tread and riser
  EXPECT_EQ(every.features.size(), m.featureEdges.size());
  p.featureRadius = 3.;
  const layoutResult atScale = computePatchLayout(m, p, anyPart);
  // the steps near the ends stay (their far side is short): a few patches
  EXPECT_LE(atScale.featurePatches, 6);
  EXPECT_EQ(atScale.features.size() + atScale.featuresBelowScale,
            m.featureEdges.size());
}
