// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <set>
#include "closestTriangle.h"
#include "inputNodesNear.h"
#include "surfaceMesh.h"

namespace reparam {

inputNodesNear::inputNodesNear(const surfaceMesh &input)
  : _input(input), _around(input.points.size())
{
  for(std::size_t t = 0; t < input.triangles.size(); t++)
    for(int v : input.triangles[t]) _around[v].push_back((int)t);
}

std::vector<int> inputNodesNear::within(int start, const SPoint3 &center,
                                        double radius) const
{
  std::vector<int> nodes;
  if(start < 0 || start >= (int)_input.triangles.size()) return nodes;
  std::set<int> seen{start}, taken;
  std::vector<int> stack{start};
  while(!stack.empty()) {
    const int t = stack.back();
    stack.pop_back();
    const std::array<int, 3> &c = _input.triangles[t];
    const SPoint3 &a = _input.points[c[0]], &b = _input.points[c[1]],
                  &d = _input.points[c[2]];
    // the walk goes on through the triangles that reach into the ball
    if(t != start &&
       closestPointOnTriangle(center, a, b, d).distance(center) > radius)
      continue;
    for(int v : c) {
      if(_input.points[v].distance(center) <= radius && taken.insert(v).second)
        nodes.push_back(v);
      for(int s : _around[v])
        if(seen.insert(s).second) stack.push_back(s);
    }
  }
  return nodes;
}
} // namespace reparam

