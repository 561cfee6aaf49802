// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <cmath>
#include "maxMinPlacement.h"
#include "triangleQuality.h"

namespace reparam {

namespace {

  double side(const SPoint3 &x, const std::array<SPoint3, 2> &o,
              const SVector3 &normal)
  {
    return dot(crossprod(SVector3(x, o[0]), SVector3(x, o[1])), normal);
  }

} // namespace

double worstRingKappa(const SPoint3 &x, const SPoint3 &start,
                      const std::vector<std::array<SPoint3, 2> > &opposite,
                      const SVector3 &normal)
{
  double worst = 1.;
  for(const auto &o : opposite) {
    if((side(x, o, normal) > 0.) != (side(start, o, normal) > 0.)) return -1.;
    worst = std::min(worst, triangleKappa(x, o[0], o[1]));
  }
  return worst;
}

SPoint3 maxMinKappaPoint(const SPoint3 &start,
                         const std::vector<std::array<SPoint3, 2> > &opposite,
                         const SVector3 &normal, double step)
{
  SVector3 n = normal;
  if(!(n.norm() > 0.) || opposite.empty() || !(step > 0.)) return start;
  n.normalize();
  // two directions in the plane
  SVector3 u = crossprod(n, SVector3(1., 0., 0.));
  if(u.norm() < 0.5) u = crossprod(n, SVector3(0., 1., 0.));
  u.normalize();
  const SVector3 w = crossprod(n, u);
  SPoint3 best = start;
  double bestWorst = worstRingKappa(start, start, opposite, n);
  for(double h = step; h > step / 40.; h *= 0.5) {
    bool moved = true;
    // at most a few steps at each length: the search stays near the start
    for(int k = 0; moved && k < 4; k++) {
      moved = false;
      SPoint3 from = best;
      for(int d = 0; d < 8; d++) {
        const double a = d * M_PI / 4.;
        const SVector3 e = u * (h * std::cos(a)) + w * (h * std::sin(a));
        const SPoint3 x(from.x() + e.x(), from.y() + e.y(), from.z() + e.z());
        const double worst = worstRingKappa(x, start, opposite, n);
        if(worst > bestWorst + 1e-9) {
          bestWorst = worst;
          best = x;
          moved = true;
        }
      }
    }
  }
  return best;
}
} // namespace reparam

