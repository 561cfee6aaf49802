// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include "closestTriangle.h"
#include "quadFidelity.h"

namespace reparam {

double distanceToQuadrangles(const SPoint3 &p,
                             const std::vector<std::array<int, 4> > &qs,
                             const std::vector<SPoint3> &x)
{
  double d = 1e300;
  for(const std::array<int, 4> &q : qs)
    for(int j = 0; j < 4; j++)
      d = std::min(d, p.distance(closestPointOnTriangle(
                        p, x[q[j]], x[q[(j + 1) % 4]], x[q[(j + 2) % 4]])));
  return d;
}

double farthestCentreFromInput(const std::vector<std::array<int, 4> > &qs,
                               const std::vector<SPoint3> &x,
                               const closestTriangleSearch &onInput)
{
  double d = 0.;
  for(const std::array<int, 4> &q : qs)
    for(int j = 0; j < 2; j++)
      d = std::max(d, onInput.closest((x[q[j]] + x[q[j + 2]]) * 0.5).distance);
  return d;
}
} // namespace reparam

