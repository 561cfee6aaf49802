// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include "triangleAdjacency.h"

namespace reparam {

int triangleAdjacency::find(int a, int b) const
{
  std::array<int, 2> key = {std::min(a, b), std::max(a, b)};
  auto it = std::lower_bound(edges.begin(), edges.end(), key);
  return (it != edges.end() && *it == key) ? (int)(it - edges.begin()) : -1;
}

triangleAdjacency
makeTriangleAdjacency(const std::vector<std::array<int, 3> > &triangles)
{
  // (lo, hi, triangle, side), sorted: equal edges become consecutive
  struct side {
    int lo, hi, triangle, k;
    bool operator<(const side &o) const
    {
      if(lo != o.lo) return lo < o.lo;
      if(hi != o.hi) return hi < o.hi;
      return triangle < o.triangle;
    }
  };
  std::vector<side> sides;
  sides.reserve(3 * triangles.size());
  for(std::size_t t = 0; t < triangles.size(); t++)
    for(int k = 0; k < 3; k++) {
      int a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      sides.push_back({std::min(a, b), std::max(a, b), (int)t, k});
    }
  std::sort(sides.begin(), sides.end());

  triangleAdjacency adj;
  adj.triangleEdges.resize(triangles.size());
  adj.edgeTriangles.reserve(sides.size());
  for(std::size_t i = 0; i < sides.size(); i++) {
    if(i == 0 || sides[i].lo != sides[i - 1].lo ||
       sides[i].hi != sides[i - 1].hi) {
      adj.edges.push_back({sides[i].lo, sides[i].hi});
      adj.edgeStart.push_back((int)i);
    }
    adj.edgeTriangles.push_back(sides[i].triangle);
    adj.triangleEdges[sides[i].triangle][sides[i].k] =
      (int)adj.edges.size() - 1;
  }
  adj.edgeStart.push_back((int)sides.size());
  return adj;
}

std::vector<std::array<int, 3> >
partNeighbours(const triangleAdjacency &adjacency, const std::vector<int> &part,
               std::size_t numTriangles)
{
  // the mesh's triangles by their index in the part: a scratch array per
  // thread, all -1 between calls
  // (allocated first: nothing may throw while the scratch is written)
  std::vector<std::array<int, 3> > neighbours(part.size());
  thread_local std::vector<int> local;
  if(local.size() < numTriangles) local.resize(numTriangles, -1);
  for(std::size_t i = 0; i < part.size(); i++) local[part[i]] = (int)i;
  for(std::size_t i = 0; i < part.size(); i++)
    for(int k = 0; k < 3; k++) {
      const int t = part[i];
      const int o = adjacency.across(adjacency.triangleEdges[t][k], t);
      neighbours[i][k] = o < 0 ? -1 : local[o];
    }
  for(int t : part) local[t] = -1;
  return neighbours;
}
} // namespace reparam
