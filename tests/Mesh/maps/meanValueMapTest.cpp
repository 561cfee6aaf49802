// Reparam - the mean-value convex map (Eq. 14, 24, 26)

#include <cmath>
#include <gtest/gtest.h>
#include "SVector3.h"
#include "meanValueMap.h"
#include "patchAssembly.h"
#include "patchBoundary.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  // Eq. (14) computed the textbook way (acos), independent of meanValueWeights
  double referenceWeight(const SPoint3 &xi, const SPoint3 &xk,
                         const SPoint3 &third)
  {
    SVector3 e(xi, xk), a(xi, third);
    double alpha = std::acos(dot(e, a) / (e.norm() * a.norm()));
    return std::tan(0.5 * alpha) / e.norm();
  }

  // Largest distance between uv and the best similarity image of the xy
  // coordinates (least squares in the complex plane: uv = a z + b)
  double distanceToSimilarity(const discretePatch &patch,
                              const std::vector<double> &uv)
  {
    typedef std::complex<double> C;
    const std::size_t n = patch.points.size();
    C mz(0, 0), mw(0, 0);
    for(std::size_t i = 0; i < n; i++) {
      mz += C(patch.points[i].x(), patch.points[i].y());
      mw += C(uv[2 * i], uv[2 * i + 1]);
    }
    mz /= (double)n;
    mw /= (double)n;
    C num(0, 0);
    double den = 0.;
    for(std::size_t i = 0; i < n; i++) {
      C z = C(patch.points[i].x(), patch.points[i].y()) - mz;
      C w = C(uv[2 * i], uv[2 * i + 1]) - mw;
      num += std::conj(z) * w;
      den += std::norm(z);
    }
    C a = num / den;
    double worst = 0.;
    for(std::size_t i = 0; i < n; i++) {
      C z = C(patch.points[i].x(), patch.points[i].y()) - mz;
      C w = C(uv[2 * i], uv[2 * i + 1]) - mw;
      worst = std::max(worst, std::abs(a * z - w));
    }
    return worst;
  }

} // namespace

TEST(meanValueMap, weightsOfEquilateralTriangle)
{
  // every angle is 60 degrees, every side 2: w = tan(30 deg) / 2
  triangleWeights w = meanValueWeights(SPoint3(0, 0, 0), SPoint3(2, 0, 0),
                                       SPoint3(1, std::sqrt(3.), 0));
  for(int i = 0; i < 3; i++)
    for(int j = 0; j < 3; j++)
      if(i != j) EXPECT_NEAR(w[i][j], std::tan(M_PI / 6.) / 2., 1e-15);
}

TEST(meanValueMap, weightsMatchTextbookFormula)
{
  SPoint3 x0(0.1, 0.2, 0.3), x1(1.7, -0.4, 0.9), x2(0.4, 1.1, -0.6);
  triangleWeights w = meanValueWeights(x0, x1, x2);
  EXPECT_NEAR(w[0][1], referenceWeight(x0, x1, x2), 1e-14);
  EXPECT_NEAR(w[0][2], referenceWeight(x0, x2, x1), 1e-14);
  EXPECT_NEAR(w[1][0], referenceWeight(x1, x0, x2), 1e-14);
  EXPECT_NEAR(w[2][1], referenceWeight(x2, x1, x0), 1e-14);
}

TEST(meanValueMap, assembledRowsSumToZero)
{
  discretePatch patch = makePatchOrDie(hemisphere(5, 16));
  Eigen::SparseMatrix<double> A =
    assembleWeightedLaplacian(patch, meanValueWeights);
  Eigen::VectorXd ones = Eigen::VectorXd::Ones(A.cols());
  EXPECT_LT((A * ones).cwiseAbs().maxCoeff(), 1e-12);
  // off-diagonal entries are negative (convex combination)
  for(int k = 0; k < A.outerSize(); k++)
    for(Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it)
      if(it.row() != it.col()) EXPECT_LT(it.value(), 0.);
}

TEST(meanValueMap, boundaryOnUnitCircleByArcLength)
{
  // rim of a polar disk: 24 equal chords -> angles 2 pi k / 24
  discretePatch patch = makePatchOrDie(polarDisk(3, 24));
  std::vector<double> uv(2 * patch.points.size(), 0.);
  std::vector<char> fixed(patch.points.size(), 0);
  mapLoopToUnitCircle(patch, patch.outerLoop, uv, fixed);
  const auto &loop = patch.boundaryLoops[patch.outerLoop];
  double a0 = std::atan2(uv[2 * loop[0] + 1], uv[2 * loop[0]]);
  for(std::size_t k = 0; k < loop.size(); k++) {
    EXPECT_TRUE(fixed[loop[k]]);
    double u = uv[2 * loop[k]], v = uv[2 * loop[k] + 1];
    EXPECT_NEAR(u * u + v * v, 1., 1e-14);
    double expected = a0 + 2. * M_PI * k / loop.size();
    EXPECT_NEAR(u, std::cos(expected), 1e-12);
    EXPECT_NEAR(v, std::sin(expected), 1e-12);
  }
  EXPECT_EQ(std::count(fixed.begin(), fixed.end(), 1), 24);
}

TEST(meanValueMap, planarRegularPolygonMapsBySimilarity)
{
  // The rim is a regular polygon, so Eq. (26) places it by a similarity; mean
  // value coordinates reproduce linear functions, so the whole map is that
  // similarity, up to round-off
  testTriangulation t = polarDisk(6, 20, 1.3, 0.4);
  discretePatch patch = makePatchOrDie(t);
  patchMap map = meanValueMap(patch);
  ASSERT_TRUE(map.error.ok()) << map.error.what();
  EXPECT_LT(distanceToSimilarity(patch, map.uv), 1e-12);
}

TEST(meanValueMap, interiorNodesAreWeightedAverages)
{
  testTriangulation t = liftPlanar(polarDisk(8, 30, 0.7, 0.3), 0.4);
  discretePatch patch = makePatchOrDie(t);
  patchMap map = meanValueMap(patch);
  ASSERT_TRUE(map.error.ok()) << map.error.what();
  const std::size_t n = patch.points.size();
  std::vector<double> wsum(n, 0.), su(n, 0.), sv(n, 0.);
  for(const auto &tri : patch.triangles) {
    for(int i = 0; i < 3; i++) {
      for(int k = 1; k < 3; k++) {
        int a = tri[i], b = tri[(i + k) % 3], c = tri[(i + 3 - k) % 3];
        double w = referenceWeight(patch.points[a], patch.points[b], patch.points[c]);
        wsum[a] += w;
        su[a] += w * map.uv[2 * b];
        sv[a] += w * map.uv[2 * b + 1];
      }
    }
  }
  std::vector<char> onBoundary(n, 0);
  for(int v : patch.boundaryLoops[patch.outerLoop]) onBoundary[v] = 1;
  int checked = 0;
  for(std::size_t i = 0; i < n; i++) {
    if(onBoundary[i]) continue;
    EXPECT_NEAR(map.uv[2 * i], su[i] / wsum[i], 1e-12);
    EXPECT_NEAR(map.uv[2 * i + 1], sv[i] / wsum[i], 1e-12);
    checked++;
  }
  EXPECT_EQ(checked, 1 + 7 * 30);
}

TEST(meanValueMap, noFlipOnSlivers)
{
  testTriangulation t = liftPlanar(sliverGrid(16, 0.002), 0.3);
  ASSERT_LT(minKappa(t), 0.01);
  discretePatch patch = makePatchOrDie(t);
  patchMap map = meanValueMap(patch);
  ASSERT_TRUE(map.error.ok()) << map.error.what();
  int flipped = 0;
  double smallest = 1.;
  for(const auto &tri : patch.triangles) {
    double a = uvArea2(map.uv, tri);
    if(a <= 0.) flipped++;
    smallest = std::min(smallest, a);
  }
  EXPECT_EQ(flipped, 0);
  EXPECT_GT(smallest, 0.);
}

TEST(meanValueMap, holesAreFreeAndStayInsideTheDisk)
{
  testTriangulation t = liftPlanar(
    polarDiskWithHoles(10, 40, {{{3, 5, 0, 6}}, {{6, 8, 15, 25}}}), 0.2);
  discretePatch patch = makePatchOrDie(t);
  ASSERT_EQ(patch.boundaryLoops.size(), 3u);
  patchMap map = meanValueMap(patch);
  ASSERT_TRUE(map.error.ok()) << map.error.what();
  for(std::size_t i = 0; i < patch.points.size(); i++)
    EXPECT_LE(std::hypot(map.uv[2 * i], map.uv[2 * i + 1]), 1. + 1e-12);
  for(const auto &tri : patch.triangles) EXPECT_GT(uvArea2(map.uv, tri), 0.);
}
