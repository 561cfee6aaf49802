// Reparam - a regular hexagon fan to test the optimizer's internal steps
// on: the input is the flat hexagon, the mesh the same fan with its center
// node (6) moved within the plane, and an optimizer on it

#ifndef OPTIMIZE_TEST_HEXAGON_FAN_H
#define OPTIMIZE_TEST_HEXAGON_FAN_H

#include <cmath>
#include "closestTriangle.h"
#include "localOptimizer.h"
#include "optimizableMesh.h"

namespace optimizeTest {

  using namespace reparam;

  // Radius 1 in z = 0 around node 6 at `center`, triangles (6, k, k + 1)
  // counterclockwise from +z; only node 6 movable, none against the input
  inline optimizableMesh hexagonFan(const SPoint3 &center = SPoint3(0., 0., 0.))
  {
    optimizableMesh m;
    for(int k = 0; k < 6; k++)
      m.points.push_back(
        SPoint3(std::cos(k * M_PI / 3.), std::sin(k * M_PI / 3.), 0.));
    m.points.push_back(center);
    for(int k = 0; k < 6; k++) m.triangles.push_back({{6, k, (k + 1) % 6}});
    m.movable.assign(7, false);
    m.movable[6] = true;
    m.against.assign(6, false);
    return m;
  }

  // The input under it: the fan with its center at the origin
  struct hexagonInput {
    const surfaceMesh mesh = hexagonFan();
    const closestTriangleSearch search{mesh.points, mesh.triangles};
  };

  // The fan with its center at `center`, its input, and an optimizer on it
  // allowed `budget` searches of the input
  struct fanOptimizer {
    hexagonInput input;
    optimizableMesh m;
    std::size_t searches = 0;
    optimizeInternal::localOptimizer opt;
    explicit fanOptimizer(const SPoint3 &center = SPoint3(0., 0., 0.),
                          std::size_t budget = 1000)
      : m(hexagonFan(center)), opt(m, input.mesh, input.search,
                                   meshOptimizationOptions(), searches, budget)
    {
    }
  };

} // namespace optimizeTest

#endif
