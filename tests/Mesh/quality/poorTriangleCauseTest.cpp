// Reparam - why a triangle is poor: curves meeting at a sharp angle, short
// curve segments, strips narrower than the size, or inside

#include <cmath>
#include <gtest/gtest.h>
#include "poorTriangleCause.h"

using namespace reparam;

namespace {

  triangleCorners corners(const SPoint3 &a, const SPoint3 &b, const SPoint3 &c,
                          int da, int db, int dc, bool e0, bool e1, bool e2)
  {
    triangleCorners t;
    t.x[0] = a;
    t.x[1] = b;
    t.x[2] = c;
    t.dim[0] = da;
    t.dim[1] = db;
    t.dim[2] = dc;
    t.edgeOnCurve[0] = e0;
    t.edgeOnCurve[1] = e1;
    t.edgeOnCurve[2] = e2;
    return t;
  }

} // namespace

TEST(poorTriangleCause, eachCause)
{
  // corner 0 on a model point, both its edges on curves meeting at 10 deg
  const double a = 10. * M_PI / 180.;
  const SPoint3 o(0., 0., 0.), p(1., 0., 0.), q(std::cos(a), std::sin(a), 0.);
  EXPECT_EQ(poorTriangleCauseOf(corners(o, p, q, 0, 1, 1, true, false, true)),
            poorTriangleCause::sharpCurveAngle);
  // the same at 40 degrees is no sharp angle; its third edge inside
  const double b = 40. * M_PI / 180.;
  const SPoint3 r(std::cos(b), std::sin(b), 0.);
  EXPECT_EQ(poorTriangleCauseOf(corners(o, p, r, 0, 1, 1, true, false, true)),
            poorTriangleCause::narrowStrip);
  // the sharp corner inside the surface is not the curves' (its short edge
  // p-q is not on a curve either)
  EXPECT_EQ(poorTriangleCauseOf(corners(o, p, q, 2, 1, 1, true, false, true)),
            poorTriangleCause::inside);
  // a needle whose short edge is a curve segment
  const SPoint3 s(0.1, 0., 0.), t(0.05, 1., 0.);
  EXPECT_EQ(poorTriangleCauseOf(corners(o, s, t, 1, 1, 2, true, false, false)),
            poorTriangleCause::shortCurveSegment);
  // the same needle with its short edge inside: a fold inside
  EXPECT_EQ(poorTriangleCauseOf(corners(o, s, t, 2, 2, 2, false, false, false)),
            poorTriangleCause::inside);
  // a flat triangle between two curves (no inner node): a narrow strip
  const SPoint3 u(0., 0., 0.), v(1., 0., 0.), w(0.5, 0.05, 0.);
  EXPECT_EQ(poorTriangleCauseOf(corners(u, v, w, 1, 1, 1, true, false, false)),
            poorTriangleCause::narrowStrip);
  EXPECT_STREQ(poorTriangleCauseName(poorTriangleCause::narrowStrip),
               "in strips narrower than the mesh size");
}
