// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <map>
#include "closestTriangle.h"
#include "farInputNodes.h"
#include "meshFidelity.h"
#include "surfaceMeshOptimizer.h"
#include "triangleSplit.h"

namespace {

  // Input nodes on an edge used by one triangle (or more than two)
  std::vector<bool> boundaryNodes(const surfaceMesh &input)
  {
    std::map<std::pair<int, int>, int> uses;
    for(const std::array<int, 3> &t : input.triangles)
      for(int k = 0; k < 3; k++) {
        const int a = t[k], b = t[(k + 1) % 3];
        uses[std::make_pair(std::min(a, b), std::max(a, b))]++;
      }
    std::vector<bool> boundary(input.points.size(), false);
    for(const auto &e : uses)
      if(e.second != 2) boundary[e.first.first] = boundary[e.first.second] =
          true;
    return boundary;
  }

  struct farNode {
    double distance;
    int node; // of the input
    int triangle; // of the mesh, closest
    SPoint3 onMesh;
  };

  std::vector<farNode> farInputNodes(const optimizableMesh &m,
                                     const surfaceMesh &input, double share)
  {
    const closestTriangleSearch onMesh(m.points, m.triangles);
    const std::vector<bool> boundary = boundaryNodes(input);
    std::vector<farNode> far;
    for(std::size_t i = 0; i < input.points.size(); i++) {
      if(boundary[i]) continue;
      const closestTriangleHit hit = onMesh.closest(input.points[i]);
      if(hit.triangle < 0) continue;
      const std::array<int, 3> &t = m.triangles[hit.triangle];
      const double edges = (m.points[t[0]].distance(m.points[t[1]]) +
                            m.points[t[1]].distance(m.points[t[2]]) +
                            m.points[t[2]].distance(m.points[t[0]])) /
                           3.;
      if(hit.distance > share * edges)
        far.push_back({hit.distance, (int)i, hit.triangle, hit.point});
    }
    std::sort(far.begin(), far.end(), [](const farNode &a, const farNode &b) {
      return a.distance > b.distance;
    });
    return far;
  }

  // f's input node into the mesh where it passes closest: into that
  // triangle, or onto an edge if next to it
  bool insert(triangleSplitter &split, const optimizableMesh &m,
              const surfaceMesh &input, const farNode &f)
  {
    const int t = f.triangle;
    if(!split.untouched(t)) return false;
    const std::array<int, 3> c = m.triangles[t];
    double l[3];
    triangleBarycentric(f.onMesh, m.points[c[0]], m.points[c[1]],
                        m.points[c[2]], l);
    // next to a corner: the mesh passes through a node there already
    const double inside = 0.02;
    int low = 0;
    for(int k = 0; k < 3; k++) low += l[k] < inside;
    // the node marks the input's shape: it stays
    if(!low) return split.splitTriangle(t, input.points[f.node], false, f.node);
    if(low > 1) return false;
    int k = 0; // the edge opposite the corner of low weight
    while(l[(k + 2) % 3] >= inside) k++;
    return split.splitEdge(t, k, input.points[f.node], false, f.node);
  }

} // namespace

std::size_t insertFarInputNodes(optimizableMesh &m, const surfaceMesh &input,
                                const closestTriangleSearch &onInput,
                                bool reversed, double share)
{
  if(m.triangles.empty()) return 0;
  const std::vector<farNode> far = farInputNodes(m, input, share);
  if(far.empty()) return 0;
  triangleSplitter split(m, input, onInput, reversed);
  std::size_t inserted = 0;
  for(const farNode &f : far) inserted += insert(split, m, input, f);
  return inserted;
}
