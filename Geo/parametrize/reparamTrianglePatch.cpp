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

  // The triangles in the order of their Gmsh numbers, on canonical nodes
  std::vector<std::array<int, 3> >
  canonicalTriangles(const std::vector<MTriangle *> &triangles,
                     const std::vector<std::array<int, 3> > &tris,
                     const std::vector<int> &canonical)
  {
    std::vector<int> order(tris.size());
    for(std::size_t t = 0; t < tris.size(); t++) order[t] = (int)t;
    std::sort(order.begin(), order.end(), [&triangles](int a, int b) {
      return triangles[a]->getNum() < triangles[b]->getNum();
    });
    std::vector<std::array<int, 3> > sorted(tris.size());
    for(std::size_t k = 0; k < order.size(); k++)
      for(int j = 0; j < 3; j++) sorted[k][j] = canonical[tris[order[k]][j]];
    return sorted;
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
  p.error = makeDiscretePatch(permutedPoints(p.points, p.canonical),
                              canonicalTriangles(triangles, p.triangles,
                                                 p.canonical),
                              p.patch);
  return p;
}

MVertex *nodeOfPatch(const trianglePatch &p, int patchNode)
{
  const auto it = std::find(p.canonical.begin(), p.canonical.end(), patchNode);
  return it == p.canonical.end() ? nullptr : p.nodes[it - p.canonical.begin()];
}

} // namespace reparam
