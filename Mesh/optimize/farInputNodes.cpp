// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <map>
#include "closestTriangle.h"
#include "edgeUses.h"
#include "farInputNodes.h"
#include "meshFidelity.h"
#include "optimizableMesh.h"
#include "triangleQuality.h"
#include "triangleSplit.h"

namespace reparam {

namespace {

  // Input nodes on an edge used by one triangle (or more than two)
  std::vector<bool> boundaryNodes(const surfaceMesh &input)
  {
    const edgeUses uses = edgeUsesOf(input.triangles);
    std::vector<bool> boundary(input.points.size(), false);
    for(const auto &e : uses)
      if(e.second != 2)
        boundary[e.first.first] = boundary[e.first.second] = true;
    return boundary;
  }

  struct farNode {
    double distance;
    int node; // of the input
    int triangle; // of the mesh, closest
    SPoint3 onMesh;
  };

  double meanEdge(const optimizableMesh &m, int triangle)
  {
    const std::array<int, 3> &t = m.triangles[triangle];
    return (m.points[t[0]].distance(m.points[t[1]]) +
            m.points[t[1]].distance(m.points[t[2]]) +
            m.points[t[2]].distance(m.points[t[0]])) /
           3.;
  }

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
      if(hit.distance > share * meanEdge(m, hit.triangle))
        far.push_back({hit.distance, (int)i, hit.triangle, hit.point});
    }
    std::sort(far.begin(), far.end(), [](const farNode &a, const farNode &b) {
      return a.distance > b.distance;
    });
    return far;
  }

  // an inner node of the closest triangle nearer to the input node than this
  // share of the triangle's mean edge takes its place
  const double snapShare = 0.4;
  // ... unless a triangle around it would fall below this
  const double snapFloor = 0.2;

  // The corner of f's triangle nearest to its input node, if within
  // snapShare of the triangle's mean edge (-1: none)
  int nearCorner(const optimizableMesh &m, const surfaceMesh &input,
                 const farNode &f)
  {
    const std::array<int, 3> &c = m.triangles[f.triangle];
    const SPoint3 &x = input.points[f.node];
    int nearest = -1;
    double d = snapShare * meanEdge(m, f.triangle);
    for(int v : c)
      if(m.points[v].distance(x) < d) {
        d = m.points[v].distance(x);
        nearest = v;
      }
    return nearest;
  }

  // Where f's input node goes as a new node: into its triangle (edge -1),
  // onto edge k (corners k, k + 1) when next to it, or nowhere (false: the
  // mesh passes through a corner there already)
  bool splitPlace(const optimizableMesh &m, const farNode &f, int &edge)
  {
    const std::array<int, 3> &c = m.triangles[f.triangle];
    double l[3];
    triangleBarycentric(f.onMesh, m.points[c[0]], m.points[c[1]],
                        m.points[c[2]], l);
    const double inside = 0.02;
    int low = 0;
    for(int k = 0; k < 3; k++) low += l[k] < inside;
    edge = -1;
    if(!low) return true;
    if(low > 1) return false;
    edge = 0; // the edge opposite the corner of low weight
    while(l[(edge + 2) % 3] >= inside) edge++;
    return true;
  }

  // The worst kappa of the triangles the new node at x would make (-1: the
  // edge has no second triangle)
  double worstOfSplit(triangleSplitter &split, const optimizableMesh &m, int t,
                      int edge, const SPoint3 &x)
  {
    const std::array<int, 3> &c = m.triangles[t];
    const auto k = [&](int a, int b) {
      return triangleKappa(m.points[a], m.points[b], x);
    };
    if(edge < 0)
      return std::min(k(c[0], c[1]), std::min(k(c[1], c[2]), k(c[2], c[0])));
    const int a = c[edge], b = c[(edge + 1) % 3], p = c[(edge + 2) % 3];
    const std::vector<int> &on = split.edgeTriangles(a, b);
    if(on.size() != 2) return -1.;
    const int s = on[0] == t ? on[1] : on[0];
    double worst = std::min(k(b, p), k(p, a));
    for(int q : m.triangles[s])
      if(q != a && q != b) worst = std::min(worst, std::min(k(a, q), k(q, b)));
    return worst;
  }

  // f's input node into the mesh where it passes closest: inserted into
  // that triangle, or onto an edge if next to it; but if a corner of the
  // triangle is nearer than snapShare of its edges, that inner node moves
  // there instead (where that leaves its triangles better than the new
  // node's), and next to a node that may not move it is left out (the mesh
  // passes that near it already)
  bool insert(triangleSplitter &split, const optimizableMesh &m,
              const surfaceMesh &input, const farNode &f, std::size_t &moved)
  {
    const int t = f.triangle;
    if(!split.untouched(t)) return false;
    const SPoint3 &x = input.points[f.node];
    int edge;
    const bool place = splitPlace(m, f, edge);
    const int near = nearCorner(m, input, f);
    if(near >= 0 && !m.movable[near]) return false;
    if(near >= 0) {
      const double floor =
        std::max(snapFloor, place ? worstOfSplit(split, m, t, edge, x) : -1.);
      if(split.moveNode(near, x, f.node, floor)) {
        moved++;
        return true;
      }
    }
    if(!place) return false;
    // the node marks the input's shape: it stays
    if(edge < 0) return split.splitTriangle(t, x, false, f.node);
    return split.splitEdge(t, edge, x, false, f.node);
  }

} // namespace

std::size_t insertFarInputNodes(optimizableMesh &m, const surfaceMesh &input,
                                const closestTriangleSearch &onInput,
                                bool reversed, double share, std::size_t *moved)
{
  std::size_t inserted = 0, movedHere = 0;
  if(moved) *moved = 0;
  if(m.triangles.empty()) return 0;
  const std::vector<farNode> far = farInputNodes(m, input, share);
  if(far.empty()) return 0;
  triangleSplitter split(m, input, onInput, reversed);
  for(const farNode &f : far) inserted += insert(split, m, input, f, movedHere);
  if(moved) *moved = movedHere;
  return inserted;
}
} // namespace reparam

