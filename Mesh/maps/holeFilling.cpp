// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
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

  // q strictly inside the counterclockwise triangle (a, b, c)
  bool strictlyInside(const double *a, const double *b, const double *c,
                      const double *q)
  {
    return signedArea2(a[0], a[1], b[0], b[1], q[0], q[1]) > 0. &&
           signedArea2(b[0], b[1], c[0], c[1], q[0], q[1]) > 0. &&
           signedArea2(c[0], c[1], a[0], a[1], q[0], q[1]) > 0.;
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

bool triangulateHole(const discretePatch &patch, int loop,
                     std::vector<std::array<int, 3> > &triangles)
{
  // The patch is on the left of its loops: reversed, the hole is
  const std::vector<int> poly(patch.boundaryLoops[loop].rbegin(),
                              patch.boundaryLoops[loop].rend());
  const std::size_t m = poly.size();
  if(m < 3) return false;

  // Mean plane: Newell's normal, oriented so that the polygon turns
  // counterclockwise about it
  SVector3 normal(0., 0., 0.);
  SPoint3 center(0., 0., 0.);
  for(std::size_t i = 0; i < m; i++) {
    const SPoint3 &p = patch.points[poly[i]], &r = patch.points[poly[(i + 1) % m]];
    normal += SVector3((p.y() - r.y()) * (p.z() + r.z()),
                       (p.z() - r.z()) * (p.x() + r.x()),
                       (p.x() - r.x()) * (p.y() + r.y()));
    center += p;
  }
  center /= (double)m;
  if(!(normal.norm() > 0.)) return false;
  normal.normalize();
  SVector3 e1 = SVector3(center, patch.points[poly[0]]);
  e1 -= normal * dot(e1, normal);
  if(!(e1.norm() > 0.)) e1 = crossprod(normal, SVector3(1., 0., 0.));
  if(!(e1.norm() > 1e-8)) e1 = crossprod(normal, SVector3(0., 1., 0.));
  e1.normalize();
  SVector3 e2 = crossprod(normal, e1);
  std::vector<std::array<double, 2> > q(m);
  std::map<int, int> local;
  for(std::size_t i = 0; i < m; i++) {
    SVector3 d(center, patch.points[poly[i]]);
    q[i] = {{dot(d, e1), dot(d, e2)}};
    local[poly[i]] = (int)i;
  }

  // Ear clipping, O(m^2)
  std::vector<int> prev(m), next(m);
  for(std::size_t i = 0; i < m; i++) {
    prev[i] = (int)((i + m - 1) % m);
    next[i] = (int)((i + 1) % m);
  }
  std::set<edgeKey> added;
  std::vector<std::array<int, 3> > tris;
  std::size_t left = m;
  int i = 0, sinceLastEar = 0;
  while(left > 3) {
    int a = prev[i], b = next[i];
    bool ear = signedArea2(q[a][0], q[a][1], q[i][0], q[i][1], q[b][0],
                           q[b][1]) > 0. &&
               !isPatchEdge(patch, poly[a], poly[b]) &&
               !added.count(key(poly[a], poly[b]));
    for(int j = next[b]; ear && j != a; j = next[j])
      if(strictlyInside(q[a].data(), q[i].data(), q[b].data(), q[j].data()))
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
  if(!(signedArea2(q[a][0], q[a][1], q[i][0], q[i][1], q[b][0], q[b][1]) > 0.))
    return false;
  tris.push_back({{poly[a], poly[i], poly[b]}});

  delaunayFlips(patch, q, local, tris);
  triangles.insert(triangles.end(), tris.begin(), tris.end());
  return true;
}

holeFilling fillHoles(const discretePatch &patch)
{
  holeFilling filling;
  for(int loop = 0; loop < (int)patch.boundaryLoops.size(); loop++) {
    if(loop == patch.outerLoop) continue;
    std::vector<std::array<int, 3> > tris;
    if(triangulateHole(patch, loop, tris)) {
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

