// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include "SVector3.h"
#include "conePoints.h"
#include "edgeUses.h"

namespace reparam {

namespace {

  double angleAt(const SPoint3 &a, const SPoint3 &b, const SPoint3 &c)
  {
    SVector3 u(a, b), v(a, c);
    const double l = u.norm() * v.norm();
    if(l <= 0.) return 0.;
    return std::acos(std::min(1., std::max(-1., dot(u, v) / l)));
  }

} // namespace

std::vector<int> conePoints(const std::vector<SPoint3> &points,
                            const std::vector<std::array<int, 3> > &triangles,
                            double maxAngleSum)
{
  std::vector<double> angleSum(points.size(), 0.);
  std::vector<bool> onBoundary(points.size(), false);
  for(const auto &t : triangles)
    for(int j = 0; j < 3; j++) {
      const int a = t[j], b = t[(j + 1) % 3], c = t[(j + 2) % 3];
      angleSum[a] += angleAt(points[a], points[b], points[c]);
    }
  for(const auto &e : edgeUsesOf(triangles))
    if(e.second != 2) onBoundary[e.first.first] = onBoundary[e.first.second] = true;
  std::vector<bool> used(points.size(), false);
  for(const auto &t : triangles)
    for(int n : t) used[n] = true;
  std::vector<int> tips;
  for(std::size_t i = 0; i < points.size(); i++)
    if(used[i] && !onBoundary[i] && angleSum[i] < maxAngleSum)
      tips.push_back((int)i);
  return tips;
}
} // namespace reparam

