// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <cmath>
#include <limits>
#include "SVector3.h"
#include "mapDistortion.h"

namespace reparam {

double angleDistortion(const SPoint3 &x0, const SPoint3 &x1, const SPoint3 &x2,
                       const double *uv0, const double *uv1, const double *uv2)
{
  // The triangle in an orthonormal frame of its plane: p1 = (a, 0), p2 = (b, c)
  SVector3 e1(x0, x1), e2(x0, x2);
  const double a = e1.norm();
  const double b = dot(e1, e2) / a;
  const double c = crossprod(e1, e2).norm() / a;
  // J maps (a, 0) -> q1 and (b, c) -> q2
  const double q1u = uv1[0] - uv0[0], q1v = uv1[1] - uv0[1];
  const double q2u = uv2[0] - uv0[0], q2v = uv2[1] - uv0[1];
  const double j11 = q1u / a, j21 = q1v / a;
  const double j12 = (q2u - b * j11) / c, j22 = (q2v - b * j21) / c;
  const double det = j11 * j22 - j12 * j21;
  if(!(det > 0.)) return std::numeric_limits<double>::infinity();
  // From |J|_F^2 = f = s1^2 + s2^2 and det = s1 s2: s1^2 = (f + r) / 2 and
  // s1 / s2 = s1^2 / det, with r^2 = f^2 - 4 det^2 = (f - 2 det)(f + 2 det)
  // written as sums of squares: no cancellation for near-conformal maps
  const double f = j11 * j11 + j12 * j12 + j21 * j21 + j22 * j22;
  const double fMinus = (j11 - j22) * (j11 - j22) + (j12 + j21) * (j12 + j21);
  const double fPlus = (j11 + j22) * (j11 + j22) + (j12 - j21) * (j12 - j21);
  const double r = std::sqrt(fMinus * fPlus);
  return (f + r) / (2. * det);
}

mapDistortionStats angleDistortionStats(const discretePatch &patch,
                                        const std::vector<double> &uv,
                                        const std::vector<int> &which)
{
  mapDistortionStats stats;
  std::size_t counted = 0;
  const std::size_t n = which.empty() ? patch.triangles.size() : which.size();
  for(std::size_t k = 0; k < n; k++) {
    const auto &t = patch.triangles[which.empty() ? k : which[k]];
    double d = angleDistortion(patch.points[t[0]], patch.points[t[1]],
                               patch.points[t[2]], &uv[2 * t[0]],
                               &uv[2 * t[1]], &uv[2 * t[2]]);
    if(std::isinf(d)) {
      stats.flipped++;
      continue;
    }
    stats.mean += d;
    stats.max = std::max(stats.max, d);
    counted++;
  }
  if(counted) stats.mean /= (double)counted;
  return stats;
}
} // namespace reparam

