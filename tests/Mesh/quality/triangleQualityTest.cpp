// Reparam - triangle aspect ratio kappa (Eq. 3)

#include <cmath>
#include <gtest/gtest.h>
#include "triangleQuality.h"

using namespace reparam;

TEST(triangleQuality, equilateralIsOne)
{
  EXPECT_NEAR(triangleKappa(SPoint3(0, 0, 0), SPoint3(1, 0, 0),
                            SPoint3(0.5, std::sqrt(3.) / 2., 0)),
              1., 1e-15);
}

TEST(triangleQuality, rightIsoscelesClosedForm)
{
  // sines 1, 1/sqrt2, 1/sqrt2: kappa = 2 / (1 + sqrt2)
  EXPECT_NEAR(triangleKappa(SPoint3(0, 0, 0), SPoint3(1, 0, 0), SPoint3(0, 1, 0)),
              2. / (1. + std::sqrt(2.)), 1e-15);
  EXPECT_NEAR(triangleKappa(SPoint3(1, 1, 1), SPoint3(1, 1, 3), SPoint3(1, 3, 1)),
              2. / (1. + std::sqrt(2.)), 1e-15);
}

TEST(triangleQuality, flatIsZeroAndSliverIsSmall)
{
  EXPECT_EQ(triangleKappa(SPoint3(0, 0, 0), SPoint3(1, 0, 0), SPoint3(2, 0, 0)), 0.);
  EXPECT_EQ(triangleKappa(SPoint3(0, 0, 0), SPoint3(0, 0, 0), SPoint3(2, 0, 0)), 0.);
  // isosceles cap of height h over base 1: base angles b = atan(2h)
  for(double h : {0.3, 0.01}) {
    double b = std::atan(2. * h), sa = std::sin(M_PI - 2. * b), sb = std::sin(b);
    double k = triangleKappa(SPoint3(0, 0, 0), SPoint3(1, 0, 0), SPoint3(0.5, h, 0));
    EXPECT_NEAR(k, 4. * sa * sb * sb / (sa + 2. * sb), 1e-15);
  }
  // and kappa ~ 8 h^2 for a flat cap
  EXPECT_NEAR(triangleKappa(SPoint3(0, 0, 0), SPoint3(1, 0, 0), SPoint3(0.5, 1e-3, 0)),
              8e-6, 1e-8);
}
