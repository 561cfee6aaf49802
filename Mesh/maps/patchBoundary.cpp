// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <cmath>
#include "patchBoundary.h"

namespace reparam {

void mapLoopToUnitCircle(const discretePatch &patch, int loop,
                         std::vector<double> &uv, std::vector<char> &isFixed)
{
  const std::vector<int> &nodes = patch.boundaryLoops[loop];
  const double length = boundaryLoopLength(patch, loop);
  double arc = 0.;
  for(std::size_t i = 0; i < nodes.size(); i++) {
    if(i) arc += patch.points[nodes[i]].distance(patch.points[nodes[i - 1]]);
    double angle = 2. * M_PI * arc / length;
    uv[2 * nodes[i]] = std::cos(angle);
    uv[2 * nodes[i] + 1] = std::sin(angle);
    isFixed[nodes[i]] = 1;
  }
}
} // namespace reparam

