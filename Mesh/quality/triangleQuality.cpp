// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include "MTriangle.h"
#include "SVector3.h"
#include "triangleQuality.h"

namespace reparam {

double triangleKappa(const SPoint3 &p0, const SPoint3 &p1, const SPoint3 &p2)
{
  const SPoint3 *p[3] = {&p0, &p1, &p2};
  double sines[3];
  for(int i = 0; i < 3; i++) {
    SVector3 a(*p[i], *p[(i + 1) % 3]), b(*p[i], *p[(i + 2) % 3]);
    double la = a.norm(), lb = b.norm();
    if(la == 0. || lb == 0.) return 0.;
    sines[i] = crossprod(a, b).norm() / (la * lb);
  }
  double sum = sines[0] + sines[1] + sines[2];
  if(sum == 0.) return 0.;
  return 4. * sines[0] * sines[1] * sines[2] / sum;
}

kappaStatistics computeKappaStatistics(const std::vector<MTriangle *> &t)
{
  kappaStatistics s;
  s.triangles = t.size();
  if(t.empty()) return s;
  s.min = 1.;
  std::size_t below = 0;
  for(MTriangle *e : t) {
    double k = triangleKappa(e->getVertex(0)->point(),
                             e->getVertex(1)->point(),
                             e->getVertex(2)->point());
    s.min = std::min(s.min, k);
    s.mean += k;
    if(k < 0.3) below++;
  }
  s.mean /= t.size();
  s.shareBelow03 = (double)below / t.size();
  return s;
}
} // namespace reparam

