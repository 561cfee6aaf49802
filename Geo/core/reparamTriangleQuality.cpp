// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include "MTriangle.h"
#include "reparamTriangleQuality.h"

namespace reparam {

kappaStatistics computeKappaStatistics(const std::vector<MTriangle *> &t)
{
  kappaStatistics s;
  s.triangles = t.size();
  if(t.empty()) return s;
  s.min = 1.;
  std::size_t below = 0;
  for(MTriangle *e : t) {
    double k = triangleKappa(e->getVertex(0)->point(), e->getVertex(1)->point(),
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
