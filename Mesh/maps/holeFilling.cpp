// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include "SVector3.h"
#include "holeFilling.h"

namespace reparam {

namespace {

  typedef std::pair<int, int> edgeKey;
  edgeKey key(int a, int b) { return a < b ? edgeKey(a, b) : edgeKey(b, a); }

  bool isPatchEdge(const discretePatch &patch, int a, int b)
  {
    std::array<int, 2> e{{std::min(a, b), std::max(a, b)}};
    return std::binary_search(patch.edges.begin(), patch.edges.end(), e);
  }

  // q inside the counterclockwise triangle (a, b, c) or on its sides: a
  // node on the diagonal (a, c) of an ear blocks it too, or the clipping of
  // a rectangular hole with nodes along its sides cuts off its last corner
  // and leaves the nodes of one side, in a line, as the polygon
  bool insideOrOn(const double *a, const double *b, const double *c,
                  const double *q)
  {
    return signedArea2(a[0], a[1], b[0], b[1], q[0], q[1]) >= 0. &&
           signedArea2(b[0], b[1], c[0], c[1], q[0], q[1]) >= 0. &&
           signedArea2(c[0], c[1], a[0], a[1], q[0], q[1]) >= 0.;
  }

  // d clearly inside the circumcircle of the counterclockwise (a, b, c)
  bool inCircumcircle(const double *a, const double *b, const double *c,
                      const double *d)
  {
    double ax = a[0] - d[0], ay = a[1] - d[1], bx = b[0] - d[0],
           by = b[1] - d[1], cx = c[0] - d[0], cy = c[1] - d[1];
    double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by,
           c2 = cx * cx + cy * cy;
    double det = a2 * (bx * cy - cx * by) - b2 * (ax * cy - cx * ay) +
                 c2 * (ax * by - bx * ay);
    // Holes are often circles: their nodes are cocircular up to rounding,
    // and without a tolerance the flips would cycle
    double scale = std::max(a2, std::max(b2, c2));
    return det > 1e-10 * scale * scale;
  }

  // Lawson's flips among the hole's own triangles, in the projection plane.
  // A hole has few triangles: sorted vectors, no node-based containers
  void delaunayFlips(const discretePatch &patch,
                     const std::vector<std::array<double, 2> > &q,
                     const std::map<int, int> &local,
                     std::vector<std::array<int, 3> > &tris)
  {
    auto P = [&](int node) { return q[local.find(node)->second].data(); };
    std::vector<std::pair<edgeKey, int> > sides;
    std::vector<edgeKey> present;
    for(int pass = 0; pass < 100; pass++) {
      sides.clear();
      for(std::size_t t = 0; t < tris.size(); t++)
        for(int k = 0; k < 3; k++)
          sides.push_back({key(tris[t][k], tris[t][(k + 1) % 3]), (int)t});
      std::sort(sides.begin(), sides.end());
      present.clear();
      for(const auto &side : sides) present.push_back(side.first);
      auto isPresent = [&](const edgeKey &e) {
        return std::binary_search(present.begin(), present.end(), e);
      };
      std::vector<edgeKey> created;
      bool flipped = false;
      std::vector<char> touched(tris.size(), 0);
      for(std::size_t s = 0; s + 1 < sides.size(); s++) {
        if(sides[s].first != sides[s + 1].first) continue;
        const edgeKey e = sides[s].first;
        int t1 = sides[s].second, t2 = sides[s + 1].second;
        if(touched[t1] || touched[t2]) continue;
        // t1 = (a, b, c) with the edge (a, b); d the apex of t2
        int k1 = 0;
        while(key(tris[t1][k1], tris[t1][(k1 + 1) % 3]) != e) k1++;
        int a = tris[t1][k1], b = tris[t1][(k1 + 1) % 3],
            c = tris[t1][(k1 + 2) % 3];
        int d = -1;
        for(int k = 0; k < 3; k++)
          if(tris[t2][k] != a && tris[t2][k] != b) d = tris[t2][k];
        if(!inCircumcircle(P(a), P(b), P(c), P(d))) continue;
        // the new triangles (c, a, d) and (d, b, c) must keep the orientation
        if(signedArea2(P(c)[0], P(c)[1], P(a)[0], P(a)[1], P(d)[0], P(d)[1]) <=
             0. ||
           signedArea2(P(d)[0], P(d)[1], P(b)[0], P(b)[1], P(c)[0], P(c)[1]) <=
             0.)
          continue;
        const edgeKey cd = key(c, d);
        if(isPatchEdge(patch, c, d) || isPresent(cd) ||
           std::find(created.begin(), created.end(), cd) != created.end())
          continue;
        tris[t1] = {{c, a, d}};
        tris[t2] = {{d, b, c}};
        touched[t1] = touched[t2] = 1;
        created.push_back(cd);
        flipped = true;
      }
      if(!flipped) return;
    }
  }

} // namespace

namespace {

  // Newell's normal of a polygon: the polygon turns counterclockwise about
  // it, and its length is twice the area the polygon bounds
  SVector3 newellNormal(const discretePatch &patch,
                        const std::vector<int> &poly)
  {
    SVector3 normal(0., 0., 0.);
    const std::size_t m = poly.size();
    for(std::size_t i = 0; i < m; i++) {
      const SPoint3 &p = patch.points[poly[i]],
                    &r = patch.points[poly[(i + 1) % m]];
      normal += SVector3((p.y() - r.y()) * (p.z() + r.z()),
                         (p.z() - r.z()) * (p.x() + r.x()),
                         (p.x() - r.x()) * (p.y() + r.y()));
    }
    return normal;
  }

  // The mean normal of the patch's triangles with a corner on the polygon
  // (area-weighted, the patch's orientation): the way the surface around a
  // hole faces. Zero when it faces no one way: its area-weighted normals
  // cancel to less than half their total, as around the end of a tube,
  // which a filling would close into a sock
  SVector3 surroundingNormal(const discretePatch &patch,
                             const std::vector<int> &poly)
  {
    std::set<int> onLoop(poly.begin(), poly.end());
    SVector3 sum(0., 0., 0.);
    double total = 0.;
    for(const std::array<int, 3> &t : patch.triangles) {
      if(!onLoop.count(t[0]) && !onLoop.count(t[1]) && !onLoop.count(t[2]))
        continue;
      const SVector3 n =
        crossprod(SVector3(patch.points[t[0]], patch.points[t[1]]),
                  SVector3(patch.points[t[0]], patch.points[t[2]]));
      sum += n;
      total += n.norm();
    }
    if(!(sum.norm() > 0.5 * total)) return SVector3(0., 0., 0.);
    return sum;
  }

  // The polygon projected on the plane through its centroid normal to
  // `normal` (nonzero)
  std::vector<std::array<double, 2> > projected(const discretePatch &patch,
                                                const std::vector<int> &poly,
                                                SVector3 normal)
  {
    const std::size_t m = poly.size();
    SPoint3 center(0., 0., 0.);
    for(int node : poly) center += patch.points[node];
    center /= (double)m;
    normal.normalize();
    SVector3 e1 = SVector3(center, patch.points[poly[0]]);
    e1 -= normal * dot(e1, normal);
    if(!(e1.norm() > 0.)) e1 = crossprod(normal, SVector3(1., 0., 0.));
    if(!(e1.norm() > 1e-8)) e1 = crossprod(normal, SVector3(0., 1., 0.));
    e1.normalize();
    SVector3 e2 = crossprod(normal, e1);
    std::vector<std::array<double, 2> > q(m);
    for(std::size_t i = 0; i < m; i++) {
      SVector3 d(center, patch.points[poly[i]]);
      q[i] = {{dot(d, e1), dot(d, e2)}};
    }
    return q;
  }

  // Ear clipping, O(m^2), of the polygon whose projection is q
  // (counterclockwise); no diagonal may duplicate an edge of the patch
  bool clipEars(const discretePatch &patch, const std::vector<int> &poly,
                const std::vector<std::array<double, 2> > &q,
                std::vector<std::array<int, 3> > &tris)
  {
    const std::size_t m = poly.size();
    std::vector<int> prev(m), next(m);
    for(std::size_t i = 0; i < m; i++) {
      prev[i] = (int)((i + m - 1) % m);
      next[i] = (int)((i + 1) % m);
    }
    std::set<edgeKey> added;
    std::size_t left = m;
    int i = 0, sinceLastEar = 0;
    while(left > 3) {
      int a = prev[i], b = next[i];
      bool ear = signedArea2(q[a][0], q[a][1], q[i][0], q[i][1], q[b][0],
                             q[b][1]) > 0. &&
                 !isPatchEdge(patch, poly[a], poly[b]) &&
                 !added.count(key(poly[a], poly[b]));
      for(int j = next[b]; ear && j != a; j = next[j])
        if(insideOrOn(q[a].data(), q[i].data(), q[b].data(), q[j].data()))
          ear = false;
      if(ear) {
        tris.push_back({{poly[a], poly[i], poly[b]}});
        added.insert(key(poly[a], poly[b]));
        next[a] = b;
        prev[b] = a;
        left--;
        i = b;
        sinceLastEar = 0;
      }
      else {
        i = next[i];
        if(++sinceLastEar > (int)left) return false;
      }
    }
    int a = prev[i], b = next[i];
    if(!(signedArea2(q[a][0], q[a][1], q[i][0], q[i][1], q[b][0], q[b][1]) >
         0.))
      return false;
    tris.push_back({{poly[a], poly[i], poly[b]}});
    return true;
  }

  // The triangulation of the polygon of least total area among those whose
  // diagonals are no edges of the patch (dynamic programming over its
  // sub-polygons, O(m^3): loops of up to maxNodes nodes). No projection: it
  // fills a loop that crosses itself seen from any plane (the rim of a scan's
  // hole folded over). False if every triangulation needs a patch edge or
  // a degenerate triangle
  bool leastAreaTriangulation(const discretePatch &patch,
                              const std::vector<int> &poly,
                              std::vector<std::array<int, 3> > &tris)
  {
    const std::size_t maxNodes = 200;
    const int m = (int)poly.size();
    if(m < 3 || (std::size_t)m > maxNodes) return false;
    double length = 0.;
    for(int i = 0; i < m; i++)
      length += patch.points[poly[i]].distance(patch.points[poly[(i + 1) % m]]);
    const double tiny = 1e-10 * length * length;
    const double none = std::numeric_limits<double>::infinity();
    auto side = [&](int i, int j) {
      return j == i + 1 || (i == 0 && j == m - 1) ||
             !isPatchEdge(patch, poly[i], poly[j]);
    };
    auto area = [&](int i, int k, int j) {
      const SPoint3 &a = patch.points[poly[i]], &b = patch.points[poly[k]],
                    &c = patch.points[poly[j]];
      return 0.5 * crossprod(SVector3(a, b), SVector3(a, c)).norm();
    };
    // cost[i][j]: the sub-polygon i, i + 1, ..., j; split[i][j]: its apex
    std::vector<std::vector<double> > cost(m, std::vector<double>(m, 0.));
    std::vector<std::vector<int> > split(m, std::vector<int>(m, -1));
    for(int gap = 2; gap < m; gap++)
      for(int i = 0; i + gap < m; i++) {
        const int j = i + gap;
        cost[i][j] = none;
        if(!side(i, j)) continue;
        for(int k = i + 1; k < j; k++) {
          const double a = area(i, k, j);
          if(!(a > tiny)) continue;
          const double c = cost[i][k] + cost[k][j] + a;
          if(c < cost[i][j]) {
            cost[i][j] = c;
            split[i][j] = k;
          }
        }
      }
    if(!(cost[0][m - 1] < none)) return false;
    std::vector<std::array<int, 2> > todo{{{0, m - 1}}};
    while(!todo.empty()) {
      const int i = todo.back()[0], j = todo.back()[1];
      todo.pop_back();
      if(j - i < 2) continue;
      const int k = split[i][j];
      tris.push_back({{poly[i], poly[k], poly[j]}});
      todo.push_back({{i, k}});
      todo.push_back({{k, j}});
    }
    return true;
  }

} // namespace

bool triangulateHole(const discretePatch &patch, int loop,
                     std::vector<std::array<int, 3> > &triangles)
{
  // The patch is on the left of its loops: reversed, the hole is
  const std::vector<int> poly(patch.boundaryLoops[loop].rbegin(),
                              patch.boundaryLoops[loop].rend());
  const std::size_t m = poly.size();
  if(m < 3) return false;
  std::map<int, int> local;
  for(std::size_t i = 0; i < m; i++) local[poly[i]] = (int)i;
  auto onPlane = [&](const SVector3 &normal) {
    if(!(normal.norm() > 0.)) return false;
    const std::vector<std::array<double, 2> > q =
      projected(patch, poly, normal);
    std::vector<std::array<int, 3> > tris;
    if(!clipEars(patch, poly, q, tris)) return false;
    delaunayFlips(patch, q, local, tris);
    triangles.insert(triangles.end(), tris.begin(), tris.end());
    return true;
  };
  // On its mean plane first; a hole of a scan whose rim winds up and down
  // projects there onto a polygon that crosses itself, but onto a simple one
  // along the way the surface around it faces (a pass over the patch's
  // triangles, only for the holes the mean plane does not take)
  if(onPlane(newellNormal(patch, poly))) return true;
  const SVector3 around = surroundingNormal(patch, poly);
  if(!(around.norm() > 0.)) return false; // the end of a tube
  if(onPlane(around)) return true;
  // else in space
  std::vector<std::array<int, 3> > tris;
  if(!leastAreaTriangulation(patch, poly, tris)) return false;
  triangles.insert(triangles.end(), tris.begin(), tris.end());
  return true;
}

namespace {

  double areaOf(const std::vector<SPoint3> &points,
                const std::vector<std::array<int, 3> > &triangles)
  {
    double area = 0.;
    for(const std::array<int, 3> &t : triangles)
      area += 0.5 * crossprod(SVector3(points[t[0]], points[t[1]]),
                              SVector3(points[t[0]], points[t[2]]))
                      .norm();
    return area;
  }

} // namespace

holeFilling fillHoles(const discretePatch &patch)
{
  holeFilling filling;
  double area = -1.;
  for(int loop = 0; loop < (int)patch.boundaryLoops.size(); loop++) {
    if(loop == patch.outerLoop) continue;
    std::vector<std::array<int, 3> > tris;
    bool filled = triangulateHole(patch, loop, tris);
    if(filled) {
      if(area < 0.) area = areaOf(patch.points, patch.triangles);
      filled = !(areaOf(patch.points, tris) > maxHoleToPatchArea * area);
    }
    if(filled) {
      filling.triangles.insert(filling.triangles.end(), tris.begin(),
                               tris.end());
      filling.filledHoles++;
    }
    else
      filling.skippedHoles++;
  }
  return filling;
}
} // namespace reparam

