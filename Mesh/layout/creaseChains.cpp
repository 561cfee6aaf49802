// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include "closestTriangle.h"
#include "SVector3.h"
#include "creaseChains.h"
#include "triangleAdjacency.h"

namespace reparam {

namespace {

  typedef std::map<int, std::vector<int> > creaseGraph;

  creaseGraph creaseEdges(const std::vector<std::array<int, 3> > &triangles,
                          const std::function<bool(int, int)> &isCrease)
  {
    std::set<std::pair<int, int> > edges;
    for(const auto &t : triangles)
      for(int j = 0; j < 3; j++)
        edges.insert(
          {std::min(t[j], t[(j + 1) % 3]), std::max(t[j], t[(j + 1) % 3])});
    creaseGraph graph;
    for(const auto &e : edges)
      if(isCrease(e.first, e.second)) {
        graph[e.first].push_back(e.second);
        graph[e.second].push_back(e.first);
      }
    return graph;
  }

  // The chains between branch points and ends (closed loops of creases
  // without either: from any of their nodes, back to it)
  std::vector<std::vector<int> > walkChains(const creaseGraph &graph)
  {
    std::set<std::pair<int, int> > used;
    auto take = [&used](int a, int b) {
      return used.insert({std::min(a, b), std::max(a, b)}).second;
    };
    std::vector<std::vector<int> > chains;
    auto walk = [&](int start, int next) {
      std::vector<int> chain = {start};
      int previous = start, node = next;
      while(true) {
        chain.push_back(node);
        const std::vector<int> &around = graph.at(node);
        if(around.size() != 2 || node == start) break;
        const int following = around[0] == previous ? around[1] : around[0];
        if(!take(node, following)) break;
        previous = node;
        node = following;
      }
      chains.push_back(chain);
    };
    for(int pass = 0; pass < 2; pass++)
      for(const auto &n : graph) {
        // ends and branch points first, then what is left (loops)
        if(pass == 0 && n.second.size() == 2) continue;
        for(int next : n.second)
          if(take(n.first, next)) walk(n.first, next);
      }
    return chains;
  }

  double length(const std::vector<SPoint3> &points, const std::vector<int> &c)
  {
    double l = 0.;
    for(std::size_t i = 0; i + 1 < c.size(); i++)
      l += points[c[i]].distance(points[c[i + 1]]);
    return l;
  }

  // Whether the polyline comes back beside itself: a point of it nearer
  // than `gap` to an earlier segment, or a segment of it nearer than that
  // to an earlier point, more than three times that distance back along it
  // (a hairpin, not a turn)
  bool foldsBack(const std::vector<SPoint3> &line, double gap)
  {
    std::vector<double> arc(line.size(), 0.);
    for(std::size_t i = 1; i < line.size(); i++)
      arc[i] = arc[i - 1] + line[i - 1].distance(line[i]);
    auto fold = [gap](double distance, double along) {
      return distance < gap && along > 3. * distance;
    };
    for(std::size_t i = 2; i < line.size(); i++)
      for(std::size_t j = 0; j + 1 < i; j++) {
        const SPoint3 q = closestPointOnSegment(line[i], line[j], line[j + 1]);
        const SPoint3 r = closestPointOnSegment(line[j], line[i - 1], line[i]);
        if(fold(line[i].distance(q), arc[i] - arc[j] - line[j].distance(q)) ||
           fold(line[j].distance(r),
                arc[i - 1] + line[i - 1].distance(r) - arc[j]))
          return true;
      }
    return false;
  }

} // namespace

std::vector<int>
creaseCorners(const std::vector<SPoint3> &points,
              const std::vector<std::array<int, 3> > &triangles,
              const std::function<bool(int, int)> &isCrease)
{
  // (not where two turn: a scan's creases zig-zag;
  // bench/README.md#tips-and-creases)
  std::vector<int> corners;
  for(const auto &n : creaseEdges(triangles, isCrease))
    if(n.second.size() >= 3 && n.first < (int)points.size())
      corners.push_back(n.first);
  return corners;
}

std::vector<std::vector<int> >
creaseChains(const std::vector<SPoint3> &points,
             const std::vector<std::array<int, 3> > &triangles,
             const std::function<bool(int, int)> &isCrease,
             const std::vector<SPoint3> &avoid, double margin, double minLength)
{
  std::vector<std::vector<int> > kept;
  const creaseGraph graph = creaseEdges(triangles, isCrease);
  if(graph.empty()) return kept;
  auto tooNear = [&](int n) {
    for(const SPoint3 &p : avoid)
      if(points[n].distance(p) < margin) return true;
    return false;
  };
  for(std::vector<int> chain : walkChains(graph)) {
    // the longest run of nodes far enough from the boundary
    std::vector<int> best, run;
    for(int n : chain) {
      if(tooNear(n)) {
        if(length(points, run) > length(points, best)) best = run;
        run.clear();
        continue;
      }
      run.push_back(n);
    }
    if(length(points, run) > length(points, best)) best = run;
    if(best.size() >= 2 && length(points, best) >= minLength)
      kept.push_back(best);
  }
  return kept;
}

bool creaseTooSmallForMesh(const std::vector<SPoint3> &crease,
                           const std::vector<std::vector<SPoint3> > &others,
                           double size)
{
  if(crease.size() < 2 || !(size > 0.)) return false;
  if(foldsBack(crease, 0.5 * size)) return true;
  double length = 0.;
  for(std::size_t i = 0; i + 1 < crease.size(); i++)
    length += crease[i].distance(crease[i + 1]);
  if(!(length < 3. * size)) return false;
  if(crease.front().distance(crease.back()) < 0.8 * length) return true;
  for(const auto &other : others)
    for(const SPoint3 &end : {crease.front(), crease.back()})
      if(distanceToPolyline(end, other) < 0.5 * size) return true;
  return false;
}

bool creaseWithin(const std::vector<SPoint3> &points,
                  const std::vector<std::array<int, 3> > &triangles,
                  const std::vector<SPoint3> &polyline, double distance,
                  double angle)
{
  if(polyline.size() < 2 || triangles.empty()) return false;
  SPoint3 lo = polyline.front(), hi = polyline.front();
  for(const SPoint3 &p : polyline)
    for(int k = 0; k < 3; k++) {
      lo[k] = std::min(lo[k], p[k] - distance);
      hi[k] = std::max(hi[k], p[k] + distance);
    }
  auto normal = [&](int t) {
    const std::array<int, 3> &c = triangles[t];
    SVector3 n = crossprod(SVector3(points[c[0]], points[c[1]]),
                           SVector3(points[c[0]], points[c[2]]));
    const double length = n.norm();
    return length > 0. ? n * (1. / length) : n;
  };
  const double cosAngle = std::cos(angle);
  const triangleAdjacency adjacency = makeTriangleAdjacency(triangles);
  for(std::size_t e = 0; e < adjacency.edges.size(); e++) {
    if(adjacency.numTriangles((int)e) != 2) continue;
    const SPoint3 &a = points[adjacency.edges[e][0]];
    const SPoint3 &b = points[adjacency.edges[e][1]];
    bool inside = true;
    for(int k = 0; k < 3; k++)
      inside = inside && std::max(a[k], b[k]) >= lo[k] &&
               std::min(a[k], b[k]) <= hi[k];
    if(!inside) continue;
    const int s = adjacency.edgeStart[e];
    if(dot(normal(adjacency.edgeTriangles[s]),
           normal(adjacency.edgeTriangles[s + 1])) > cosAngle)
      continue;
    // the crease edge's ends and points a quarter of it apart
    for(double t : {0., 0.25, 0.5, 0.75, 1.})
      for(std::size_t i = 0; i + 1 < polyline.size(); i++) {
        const SPoint3 p = a + (b - a) * t;
        const SPoint3 q =
          closestPointOnSegment(p, polyline[i], polyline[i + 1]);
        if(p.distance(q) < distance) return true;
      }
  }
  return false;
}
} // namespace reparam

