// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include "SVector3.h"
#include "poorTriangleCause.h"

namespace reparam {

namespace {

  // The angle of t at corner k, in degrees
  double cornerAngle(const triangleCorners &t, int k)
  {
    const SVector3 a(t.x[k], t.x[(k + 1) % 3]), b(t.x[k], t.x[(k + 2) % 3]);
    const double la = a.norm(), lb = b.norm();
    if(la <= 0. || lb <= 0.) return 0.;
    return std::acos(std::max(-1., std::min(1., dot(a, b) / (la * lb)))) *
           180. / M_PI;
  }

} // namespace

poorTriangleCause poorTriangleCauseOf(const triangleCorners &t)
{
  for(int k = 0; k < 3; k++)
    // the edges at corner k: k (to k + 1) and k + 2 (from k + 2)
    if(t.dim[k] == 0 && t.edgeOnCurve[k] && t.edgeOnCurve[(k + 2) % 3] &&
       cornerAngle(t, k) < 30.)
      return poorTriangleCause::sharpCurveAngle;
  double longest = 0.;
  for(int k = 0; k < 3; k++)
    longest = std::max(longest, t.x[k].distance(t.x[(k + 1) % 3]));
  for(int k = 0; k < 3; k++)
    if(t.edgeOnCurve[k] && t.x[k].distance(t.x[(k + 1) % 3]) < 0.3 * longest)
      return poorTriangleCause::shortCurveSegment;
  if(t.dim[0] < 2 && t.dim[1] < 2 && t.dim[2] < 2)
    return poorTriangleCause::narrowStrip;
  return poorTriangleCause::inside;
}

const char *poorTriangleCauseName(poorTriangleCause c)
{
  switch(c) {
  case poorTriangleCause::sharpCurveAngle:
    return "where curves meet at a sharp angle";
  case poorTriangleCause::shortCurveSegment: return "on short curve segments";
  case poorTriangleCause::narrowStrip:
    return "in strips narrower than the mesh size";
  default: return "inside surfaces";
  }
}
} // namespace reparam

