// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include "SVector3.h"
#include "quadQuality.h"
#include "surfaceMesh.h"

namespace reparam {

double quadEta(const SPoint3 &p0, const SPoint3 &p1, const SPoint3 &p2,
               const SPoint3 &p3)
{
  const SPoint3 *p[4] = {&p0, &p1, &p2, &p3};
  SVector3 normal = crossprod(SVector3(p0, p2), SVector3(p1, p3));
  double worst = 0.;
  for(int k = 0; k < 4; k++) {
    SVector3 next(*p[k], *p[(k + 1) % 4]), previous(*p[k], *p[(k + 3) % 4]);
    SVector3 turn = crossprod(next, previous);
    // a corner turning against the quad's normal is reflex
    if(dot(turn, normal) <= 0.) return 0.;
    double alpha = std::atan2(turn.norm(), dot(next, previous));
    worst = std::max(worst, std::fabs(M_PI / 2. - alpha));
  }
  return std::max(1. - 2. / M_PI * worst, 0.);
}

SVector3 quadNormal(const std::array<int, 4> &q, const std::vector<SPoint3> &p)
{
  SVector3 n =
    crossprod(SVector3(p[q[0]], p[q[2]]), SVector3(p[q[1]], p[q[3]]));
  const double length = n.norm();
  return length > 0. ? n * (1. / length) : n;
}

void etaOfQuadrangles(const surfaceMesh &m, double &worst, double &mean)
{
  worst = 1.;
  double sum = 0.;
  for(const std::array<int, 4> &q : m.quadrangles) {
    const double eta =
      quadEta(m.points[q[0]], m.points[q[1]], m.points[q[2]], m.points[q[3]]);
    worst = std::min(worst, eta);
    sum += eta;
  }
  mean = m.quadrangles.empty() ? 1. : sum / m.quadrangles.size();
}
} // namespace reparam

