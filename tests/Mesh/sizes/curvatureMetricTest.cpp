// Reparam - principal curvatures of a triangulation (Gmsh's estimator) and
// the anisotropic sizes made from them, on analytic surfaces

#include <cmath>
#include <gtest/gtest.h>
#include "curvatureMetric.h"
#include "testPatches.h"

using namespace reparam;

namespace {

  // the larger and smaller |k| at node i, and the direction of the larger
  void largerFirst(const principalCurvatures &c, double &kMax, double &kMin,
                   SVector3 &dMax)
  {
    const int big = c.curvature[0] >= c.curvature[1] ? 0 : 1;
    kMax = c.curvature[big];
    kMin = c.curvature[1 - big];
    dMax = c.direction[big];
  }

  // the node of t nearest to p
  std::size_t nearest(const testTriangulation &t, const SPoint3 &p)
  {
    std::size_t best = 0;
    for(std::size_t i = 1; i < t.points.size(); i++)
      if(t.points[i].distance(p) < t.points[best].distance(p)) best = i;
    return best;
  }

  // the size of metric m along the unit vector d
  double sizeAlong(const SMetric3 &m, const SVector3 &d)
  {
    double q = 0.;
    for(int i = 0; i < 3; i++)
      for(int j = 0; j < 3; j++) q += d[i] * m(i, j) * d[j];
    return 1. / std::sqrt(q);
  }

} // namespace

TEST(curvatureMetric, sphereHasItsRadiusEverywhere)
{
  // radius 2: |k| = 0.5 both ways at the inner nodes, within 2 % (at the
  // pole of the polar grid, where 64 needles meet, 10 %)
  testTriangulation t = sphericalCap(16, 64, 1.2);
  for(SPoint3 &p : t.points) p *= 2.;
  const std::vector<principalCurvatures> c = curvaturesOf(asSurfaceMesh(t));
  for(double theta : {0.3, 0.6, 0.9}) {
    const std::size_t i =
      nearest(t, SPoint3(2. * std::sin(theta), 0., 2. * std::cos(theta)));
    EXPECT_NEAR(c[i].curvature[0], 0.5, 0.01) << theta;
    EXPECT_NEAR(c[i].curvature[1], 0.5, 0.01) << theta;
  }
  const std::size_t pole = nearest(t, SPoint3(0., 0., 2.));
  EXPECT_NEAR(c[pole].curvature[0], 0.5, 0.05);
}

TEST(curvatureMetric, cylinderCurvesAroundNotAlong)
{
  // unit radius, axis z: |k| = 1 around (in the x-y plane), 0 along z
  const testTriangulation t = halfCylinder(48, 24, 3.);
  const std::vector<principalCurvatures> c = curvaturesOf(asSurfaceMesh(t));
  const std::size_t i = nearest(t, SPoint3(0., 1., 1.5));
  double kMax, kMin;
  SVector3 dMax;
  largerFirst(c[i], kMax, kMin, dMax);
  EXPECT_NEAR(kMax, 1., 0.03);
  EXPECT_NEAR(kMin, 0., 0.03);
  EXPECT_NEAR(std::fabs(dMax.x()), 1., 0.01); // around, not along the axis
  // the sizes: 2 pi / 20 around, hMax along
  curvatureSizes sizes;
  sizes.elementsPerCircle = 20.;
  sizes.hMin = 0.01;
  sizes.hMax = 1.;
  const SMetric3 m = curvatureMetric(c[i], sizes);
  EXPECT_NEAR(sizeAlong(m, dMax), 2. * M_PI / 20., 0.01);
  EXPECT_NEAR(sizeAlong(m, SVector3(0., 0., 1.)), 1., 0.01);
  // the field at a point between the nodes, off the surface: the same
  const curvatureMetricField field(asSurfaceMesh(t), sizes);
  const SPoint3 x(1.01 * std::sin(0.3), 1.01 * std::cos(0.3), 1.52);
  EXPECT_NEAR(sizeAlong(field.at(x), SVector3(0., 0., 1.)), 1., 0.02);
  EXPECT_NEAR(field.smallestSizeAt(x), 2. * M_PI / 20., 0.01);
  EXPECT_NEAR(
    sizeAlong(field.at(x), SVector3(std::cos(0.3), -std::sin(0.3), 0.)),
    2. * M_PI / 20., 0.01);
}

TEST(curvatureMetric, saddleCurvesBothWays)
{
  // z = amplitude ((x - L/2)^2 - (y - 1/2)^2): at the centre k = +-2 a
  // along x and y
  const double a = 0.5;
  const testTriangulation t = saddleStrip(40, 40, 1., a);
  const std::vector<principalCurvatures> c = curvaturesOf(asSurfaceMesh(t));
  const std::size_t i = nearest(t, SPoint3(0.5, 0.5, 0.));
  EXPECT_NEAR(c[i].curvature[0], 2. * a, 0.05);
  EXPECT_NEAR(c[i].curvature[1], 2. * a, 0.05);
  for(int k = 0; k < 2; k++)
    EXPECT_NEAR(std::fabs(c[i].direction[k].x() * c[i].direction[k].y()), 0.,
                0.05);
}

TEST(curvatureMetric, sizesWithinTheBounds)
{
  curvatureSizes sizes;
  sizes.elementsPerCircle = 10.;
  sizes.hMin = 0.1;
  sizes.hMax = 2.;
  EXPECT_DOUBLE_EQ(sizes.along(0.), 2.);
  EXPECT_DOUBLE_EQ(sizes.along(1e6), 0.1);
  EXPECT_NEAR(sizes.along(-1.), 2. * M_PI / 10., 1e-12);
  // no direction: isotropic at the smaller size
  principalCurvatures flat;
  flat.curvature[0] = 1.;
  const SMetric3 m = curvatureMetric(flat, sizes);
  EXPECT_NEAR(sizeAlong(m, SVector3(1., 0., 0.)), 2. * M_PI / 10., 1e-12);
  EXPECT_NEAR(sizeAlong(m, SVector3(0., 0., 1.)), 2. * M_PI / 10., 1e-12);
}
