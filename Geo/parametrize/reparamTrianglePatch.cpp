// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <unordered_map>
#include "MTriangle.h"
#include "MVertex.h"
#include "reparamTrianglePatch.h"

namespace reparam {

namespace {

  // canonical[i]: the rank of nodes[i] among the nodes sorted by number
  std::vector<int> canonicalNodeOrder(const std::vector<MVertex *> &nodes)
  {
    std::vector<int> order(nodes.size());
    for(std::size_t i = 0; i < nodes.size(); i++) order[i] = (int)i;
    std::sort(order.begin(), order.end(), [&nodes](int a, int b) {
      return nodes[a]->getNum() < nodes[b]->getNum();
    });
    std::vector<int> canonical(nodes.size());
    for(std::size_t k = 0; k < order.size(); k++) canonical[order[k]] = (int)k;
    return canonical;
  }

  std::vector<SPoint3> permutedPoints(const std::vector<SPoint3> &points,
                                      const std::vector<int> &canonical)
  {
    std::vector<SPoint3> p(points.size());
    for(std::size_t i = 0; i < points.size(); i++) p[canonical[i]] = points[i];
    return p;
  }

  // The triangles in the order of their Gmsh numbers: order[k] is the k-th
  std::vector<int>
  triangleNumberOrder(const std::vector<MTriangle *> &triangles)
  {
    std::vector<int> order(triangles.size());
    for(std::size_t t = 0; t < triangles.size(); t++) order[t] = (int)t;
    std::sort(order.begin(), order.end(), [&triangles](int a, int b) {
      return triangles[a]->getNum() < triangles[b]->getNum();
    });
    return order;
  }

  // The triangles in that order, on canonical nodes
  std::vector<std::array<int, 3> >
  canonicalTriangles(const std::vector<std::array<int, 3> > &tris,
                     const std::vector<int> &order,
                     const std::vector<int> &canonical)
  {
    std::vector<std::array<int, 3> > sorted(tris.size());
    for(std::size_t k = 0; k < order.size(); k++)
      for(int j = 0; j < 3; j++) sorted[k][j] = canonical[tris[order[k]][j]];
    return sorted;
  }

  std::vector<int> identity(std::size_t n)
  {
    std::vector<int> order(n);
    for(std::size_t i = 0; i < n; i++) order[i] = (int)i;
    return order;
  }

  void makePatch(trianglePatch &p)
  {
    p.error = makeDiscretePatch(
      permutedPoints(p.points, p.canonical),
      canonicalTriangles(p.triangles, p.triangleOrder, p.canonical), p.patch);
  }

} // namespace

trianglePatch patchOfTriangles(const std::vector<MTriangle *> &triangles)
{
  trianglePatch p;
  // nodes numbered in order of first appearance, as Gmsh's own code does
  std::unordered_map<MVertex *, int> nodeIndex;
  nodeIndex.reserve(triangles.size());
  p.triangles.resize(triangles.size());
  for(std::size_t t = 0; t < triangles.size(); t++) {
    for(int j = 0; j < 3; j++) {
      MVertex *v = triangles[t]->getVertex(j);
      auto it = nodeIndex.insert(std::make_pair(v, (int)p.nodes.size()));
      if(it.second) {
        p.nodes.push_back(v);
        p.points.push_back(v->point());
      }
      p.triangles[t][j] = it.first->second;
    }
  }
  p.canonical = canonicalNodeOrder(p.nodes);
  p.triangleOrder = triangleNumberOrder(triangles);
  makePatch(p);
  return p;
}

trianglePatch patchOfArrays(const std::vector<SPoint3> &points,
                            const std::vector<int> &triangleNodes,
                            std::vector<int> canonical,
                            std::vector<int> triangleOrder)
{
  trianglePatch p;
  p.points = points;
  p.triangles.resize(triangleNodes.size() / 3);
  for(std::size_t t = 0; t < p.triangles.size(); t++)
    for(int j = 0; j < 3; j++) p.triangles[t][j] = triangleNodes[3 * t + j];
  p.canonical = canonical.size() == points.size() ? std::move(canonical) :
                                                    identity(points.size());
  p.triangleOrder = triangleOrder.size() == p.triangles.size() ?
                      std::move(triangleOrder) :
                      identity(p.triangles.size());
  makePatch(p);
  return p;
}

MVertex *nodeOfPatch(const trianglePatch &p, int patchNode)
{
  const auto it = std::find(p.canonical.begin(), p.canonical.end(), patchNode);
  const std::size_t i = it - p.canonical.begin();
  return i < p.nodes.size() ? p.nodes[i] : nullptr;
}

} // namespace reparam
