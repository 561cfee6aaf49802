// Reparam - the maps onto the unit disk: finite element harmonic (cotangent
// weights) and barycentric (Tutte); what they share with the mean value map

#include <cmath>
#include <gtest/gtest.h>
#include "SVector3.h"
#include "barycentricMap.h"
#include "conformalAssembly.h"
#include "harmonicMap.h"
#include "mapDistortion.h"
#include "meanValueMap.h"
#include "patchAssembly.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  std::vector<char> boundaryNodes(const discretePatch &p)
  {
    std::vector<char> onBoundary(p.points.size(), 0);
    for(const auto &loop : p.boundaryLoops)
      for(int i : loop) onBoundary[i] = 1;
    return onBoundary;
  }

  // 1/2 sum over triangles of area |grad u|^2 + |grad v|^2, the gradients of
  // the linear interpolants from the triangle's geometry: grad phi_i = n x e_i
  // / (2 area), e_i the side opposite node i, run counterclockwise
  double energyFromGradients(const discretePatch &p, const std::vector<double> &uv)
  {
    double energy = 0.;
    for(const auto &t : p.triangles) {
      const SPoint3 &a = p.points[t[0]], &b = p.points[t[1]], &c = p.points[t[2]];
      SVector3 normal = crossprod(SVector3(a, b), SVector3(a, c));
      double area2 = normal.norm();
      normal.normalize();
      SVector3 side[3] = {SVector3(b, c), SVector3(c, a), SVector3(a, b)};
      for(int coord = 0; coord < 2; coord++) {
        SVector3 grad(0., 0., 0.);
        for(int i = 0; i < 3; i++)
          grad += crossprod(normal, side[i]) * (uv[2 * t[i] + coord] / area2);
        energy += 0.5 * 0.5 * area2 * dot(grad, grad);
      }
    }
    return energy;
  }

} // namespace

TEST(diskMaps, cotangentWeightsOfKnownTriangles)
{
  // equilateral: cot(60 deg) / 2 on every edge
  triangleWeights w = cotangentWeights(SPoint3(0, 0, 0), SPoint3(1, 0, 0),
                                       SPoint3(0.5, std::sqrt(3.) / 2, 0));
  for(int i = 0; i < 3; i++)
    for(int j = 0; j < 3; j++)
      if(i != j) EXPECT_NEAR(w[i][j], 0.5 / std::sqrt(3.), 1e-15);
  // right angle at node 0: the hypotenuse (1, 2) weighs 0, the legs 1/2
  w = cotangentWeights(SPoint3(0, 0, 0), SPoint3(2, 0, 0), SPoint3(0, 2, 0));
  EXPECT_NEAR(w[1][2], 0., 1e-15);
  EXPECT_NEAR(w[0][1], 0.5, 1e-15);
  EXPECT_NEAR(w[0][2], 0.5, 1e-15);
  // an obtuse angle (120 deg at node 2) weighs its opposite edge negatively
  w = cotangentWeights(SPoint3(-1, 0, 0), SPoint3(1, 0, 0),
                       SPoint3(0, 1. / std::sqrt(3.), 0));
  EXPECT_NEAR(w[0][1], -0.5 / std::sqrt(3.), 1e-15);
}

TEST(diskMaps, barycentricWeightsAreOneHalf)
{
  triangleWeights w =
    barycentricWeights(SPoint3(0, 0, 0), SPoint3(3, 0, 0), SPoint3(0, 1, 7));
  for(int i = 0; i < 3; i++)
    for(int j = 0; j < 3; j++)
      if(i != j) EXPECT_EQ(w[i][j], 0.5);
}

TEST(diskMaps, outerLoopOnTheCircleExactly)
{
  discretePatch p = makePatchOrDie(liftPlanar(polarDisk(8, 32, 1.3, 0.2), 0.3));
  for(auto map : {harmonicMap, barycentricMap, meanValueMap}) {
    patchMap m = map(p);
    ASSERT_TRUE(m.error.ok()) << m.error.what();
    for(int i : p.boundaryLoops[p.outerLoop])
      EXPECT_NEAR(std::hypot(m.uv[2 * i], m.uv[2 * i + 1]), 1., 1e-15);
    for(std::size_t i = 0; i < p.points.size(); i++)
      EXPECT_LE(std::hypot(m.uv[2 * i], m.uv[2 * i + 1]), 1. + 1e-15);
  }
}

TEST(diskMaps, harmonicLaplacianVanishesAtInteriorNodes)
{
  discretePatch p = makePatchOrDie(hemisphere(10, 40));
  patchMap m = harmonicMap(p);
  ASSERT_TRUE(m.error.ok());
  Eigen::SparseMatrix<double> A = assembleWeightedLaplacian(p, cotangentWeights);
  Eigen::VectorXd u = Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<2> >(
    m.uv.data(), (Eigen::Index)p.points.size());
  Eigen::VectorXd v = Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<2> >(
    m.uv.data() + 1, (Eigen::Index)p.points.size());
  Eigen::VectorXd Au = A * u, Av = A * v;
  std::vector<char> onBoundary = boundaryNodes(p);
  int interior = 0;
  for(std::size_t i = 0; i < p.points.size(); i++) {
    if(onBoundary[i]) continue;
    // relative to the size of the row's terms
    EXPECT_LT(std::fabs(Au[i]), 1e-12 * A.coeff(i, i)) << i;
    EXPECT_LT(std::fabs(Av[i]), 1e-12 * A.coeff(i, i)) << i;
    interior++;
  }
  EXPECT_EQ(interior, 1 + 9 * 40);
}

TEST(diskMaps, harmonicEnergyMatchesPerTriangleGradients)
{
  discretePatch p = makePatchOrDie(liftPlanar(polarDisk(8, 32, 1.3, 0.2), 0.3));
  patchMap m = harmonicMap(p);
  ASSERT_TRUE(m.error.ok());
  double fromGradients = energyFromGradients(p, m.uv);
  EXPECT_NEAR(dirichletEnergy(p, m.uv), fromGradients, 1e-12 * fromGradients);
  // and the harmonic map has the least energy of the maps with that boundary
  patchMap mv = meanValueMap(p), tutte = barycentricMap(p);
  EXPECT_LT(fromGradients, energyFromGradients(p, mv.uv));
  EXPECT_LT(fromGradients, energyFromGradients(p, tutte.uv));
  // of a map onto the unit disk: at least the area of the disk (E_D >= A)
  EXPECT_GT(fromGradients, M_PI * 0.99);
}

TEST(diskMaps, tutteNodesAreTheAverageOfTheirNeighbours)
{
  discretePatch p = makePatchOrDie(liftPlanar(polarDisk(8, 32, 1.3, 0.2), 0.3));
  patchMap m = barycentricMap(p);
  ASSERT_TRUE(m.error.ok());
  std::vector<Eigen::Vector2d> sum(p.points.size(), Eigen::Vector2d::Zero());
  std::vector<int> degree(p.points.size(), 0);
  for(const auto &e : p.edges) {
    for(int k = 0; k < 2; k++) {
      int i = e[k], j = e[1 - k];
      sum[i] += Eigen::Vector2d(m.uv[2 * j], m.uv[2 * j + 1]);
      degree[i]++;
    }
  }
  std::vector<char> onBoundary = boundaryNodes(p);
  for(std::size_t i = 0; i < p.points.size(); i++) {
    if(onBoundary[i]) continue;
    Eigen::Vector2d avg = sum[i] / degree[i];
    EXPECT_NEAR(m.uv[2 * i], avg.x(), 1e-12);
    EXPECT_NEAR(m.uv[2 * i + 1], avg.y(), 1e-12);
  }
}

// The fixture of the bijectivity checks: a sliver patch on which the
// harmonic map flips (negative cotangent weights) and the convex maps do not
TEST(diskMaps, harmonicFlipsOnSliversWhereConvexMapsDoNot)
{
  testTriangulation t = jitteredGrid(10, 0.95, 2);
  ASSERT_LT(minKappa(t), 0.01);
  discretePatch p = makePatchOrDie(t);
  patchMap h = harmonicMap(p), tutte = barycentricMap(p), mv = meanValueMap(p);
  ASSERT_TRUE(h.error.ok() && tutte.error.ok() && mv.error.ok());
  EXPECT_GE(angleDistortionStats(p, h.uv).flipped, 1u);
  EXPECT_EQ(angleDistortionStats(p, tutte.uv).flipped, 0u);
  EXPECT_EQ(angleDistortionStats(p, mv.uv).flipped, 0u);
}
