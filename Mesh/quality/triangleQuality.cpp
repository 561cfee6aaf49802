// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

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

} // namespace reparam

