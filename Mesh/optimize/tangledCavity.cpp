// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include "SVector3.h"
#include "closestTriangle.h"
#include "edgeUses.h"
#include "flipRepair.h"
#include "meshFidelity.h"
#include "optimizableMesh.h"
#include "tangledCavity.h"
#include "triangleQuality.h"

namespace reparam {

namespace {

  // A cavity: its triangles, the movable nodes it removes, its boundary
  // loop in the triangles' turn
  struct cavity {
    std::set<int> triangles, removed;
    std::vector<int> loop;
  };

  class cavityMesher {
  public:
    cavityMesher(optimizableMesh &m, const surfaceMesh &input,
                 const closestTriangleSearch &onInput, bool reversed)
      : _m(m), _input(input), _onInput(onInput), _reversed(reversed),
        _around(m.points.size()), _deadPoint(m.points.size(), false),
        _deadTriangle(m.triangles.size(), false)
    {
      for(std::size_t t = 0; t < m.triangles.size(); t++)
        for(int v : m.triangles[t]) _around[v].push_back((int)t);
    }

    // whether t's cavity was re-meshed; the new node (or -1) in `center`
    bool remesh(int t, int &center);
    std::vector<int> compact()
    {
      return removeDeadParts(_m, _deadPoint, _deadTriangle);
    }
    bool dead(int t) const { return _deadTriangle[t]; }

  private:
    optimizableMesh &_m;
    const surfaceMesh &_input;
    const closestTriangleSearch &_onInput;
    const bool _reversed;
    std::vector<std::vector<int> > _around;
    std::vector<bool> _deadPoint, _deadTriangle;

    bool cavityOf(int t, bool wide, cavity &c) const;
    bool planeOf(const cavity &c, tangentFrame &plane) const;
    bool fanCenter(const cavity &c, const tangentFrame &plane,
                   closestTriangleHit &center) const;
    // A triangle of kappa below 0.01 (sides of 1 and about 0.01 apart) is
    // no better than the fold it would replace: a cavity of a speck the
    // size of a voxel, its fan's center on its boundary, left a triangle of
    // kappa 5e-29 in place of one of 0.47 against the input (a noisy CT
    // segmentation)
    bool validTriangle(const SPoint3 &a, const SPoint3 &b,
                       const SPoint3 &c) const
    {
      return triangleKappa(a, b, c) >= sliverKappa &&
             triangleAgainstInput(a, b, c, _input, _onInput) == _reversed;
    }
    bool fan(const cavity &c, const closestTriangleHit &center,
             std::vector<std::array<int, 3> > &triangles) const;
    bool polygon(const cavity &c, const tangentFrame &plane,
                 std::vector<std::array<int, 3> > &triangles) const;
    int replace(const cavity &c, const closestTriangleHit *center,
                const std::vector<std::array<int, 3> > &triangles);
  };

  // wide: the triangles around t's movable corners (removed) and t's
  // neighbours across its edges not locked; else t and those neighbours
  bool cavityMesher::cavityOf(int t, bool wide, cavity &c) const
  {
    if(wide)
      for(int v : _m.triangles[t])
        if(_m.movable[v]) c.removed.insert(v);
    for(int v : c.removed)
      for(int s : _around[v]) c.triangles.insert(s);
    c.triangles.insert(t);
    for(int k = 0; k < 3; k++) {
      const int a = _m.triangles[t][k], b = _m.triangles[t][(k + 1) % 3];
      if(_m.lockedEdges.count(std::make_pair(std::min(a, b), std::max(a, b))))
        continue;
      for(int s : _around[a]) {
        const std::array<int, 3> &cs = _m.triangles[s];
        if(s != t && std::find(cs.begin(), cs.end(), b) != cs.end())
          c.triangles.insert(s);
      }
    }
    // edges used twice are inside: none locked, none used more
    edgeUses uses;
    for(int s : c.triangles)
      uses.addTriangle(_m.triangles[s][0], _m.triangles[s][1],
                       _m.triangles[s][2]);
    for(const auto &u : uses)
      if(u.second > 2 || (u.second == 2 && _m.lockedEdges.count(u.first)))
        return false;
    // the boundary: one loop through no removed node, each of its nodes
    // starting one edge
    std::map<int, int> next;
    for(int s : c.triangles)
      for(int k = 0; k < 3; k++) {
        const int a = _m.triangles[s][k], b = _m.triangles[s][(k + 1) % 3];
        if(uses.of(a, b) != 1) continue;
        if(c.removed.count(a) || !next.insert(std::make_pair(a, b)).second)
          return false;
      }
    if(next.size() < 3) return false;
    int v = next.begin()->first;
    do {
      c.loop.push_back(v);
      auto it = next.find(v);
      if(it == next.end()) return false;
      v = it->second;
    } while(v != c.loop[0] && c.loop.size() <= next.size());
    return c.loop.size() == next.size() && v == c.loop[0];
  }

  bool cavityMesher::planeOf(const cavity &c, tangentFrame &plane) const
  {
    SPoint3 origin(0., 0., 0.);
    for(int v : c.loop) origin += _m.points[v];
    origin *= 1. / c.loop.size();
    return inputTangentFrame(_input, _onInput, origin, _reversed, plane);
  }

  // The centroid of the kernel of the cavity's boundary in the plane, on
  // the input
  bool cavityMesher::fanCenter(const cavity &c, const tangentFrame &plane,
                               closestTriangleHit &center) const
  {
    std::vector<std::array<double, 4> > edges;
    for(std::size_t k = 0; k < c.loop.size(); k++) {
      const std::array<double, 2> a = plane.of(_m.points[c.loop[k]]),
                                  b = plane.of(
                                    _m.points[c.loop[(k + 1) % c.loop.size()]]);
      edges.push_back({{a[0], a[1], b[0], b[1]}});
    }
    // the cavity is on the left of its boundary
    std::array<double, 2> middle;
    if(!kernelCentroid(edges, middle)) return false;
    center = _onInput.closest(plane.at(middle[0], middle[1]));
    return center.triangle >= 0;
  }

  // The fan from the center (index -1) to the boundary, if all its
  // triangles are valid
  bool cavityMesher::fan(const cavity &c, const closestTriangleHit &center,
                         std::vector<std::array<int, 3> > &triangles) const
  {
    triangles.clear();
    for(std::size_t k = 0; k < c.loop.size(); k++) {
      const int a = c.loop[k], b = c.loop[(k + 1) % c.loop.size()];
      if(!validTriangle(center.point, _m.points[a], _m.points[b])) return false;
      triangles.push_back({{-1, a, b}});
    }
    return true;
  }

  // The triangulation of the boundary loop alone with the best worst kappa
  // (dynamic programming over its sub-polygons), every triangle turning
  // the loop's way in the plane and along the input
  bool cavityMesher::polygon(const cavity &c, const tangentFrame &plane,
                             std::vector<std::array<int, 3> > &triangles) const
  {
    const int n = (int)c.loop.size();
    if(n > 24) return false;
    const std::vector<SPoint3> &x = _m.points;
    std::vector<std::array<double, 2> > p(n);
    for(int i = 0; i < n; i++) p[i] = plane.of(x[c.loop[i]]);
    auto quality = [&](int i, int k, int j) {
      const double turn = (p[k][0] - p[i][0]) * (p[j][1] - p[i][1]) -
                          (p[k][1] - p[i][1]) * (p[j][0] - p[i][0]);
      const SPoint3 &a = x[c.loop[i]], &b = x[c.loop[k]], &d = x[c.loop[j]];
      if(turn <= 0. || !validTriangle(a, b, d)) return -1.;
      return triangleKappa(a, b, d);
    };
    // best[i][j]: the worst kappa of the best triangulation of i..j
    std::vector<std::vector<double> > best(n, std::vector<double>(n, -1.));
    std::vector<std::vector<int> > split(n, std::vector<int>(n, -1));
    for(int i = 0; i + 1 < n; i++) best[i][i + 1] = 2.;
    for(int length = 2; length < n; length++)
      for(int i = 0; i + length < n; i++) {
        const int j = i + length;
        for(int k = i + 1; k < j; k++) {
          if(best[i][k] < 0. || best[k][j] < 0.) continue;
          const double q = quality(i, k, j);
          const double worst = std::min(q, std::min(best[i][k], best[k][j]));
          if(q > 0. && worst > best[i][j]) {
            best[i][j] = worst;
            split[i][j] = k;
          }
        }
      }
    if(best[0][n - 1] <= 0.) return false;
    triangles.clear();
    std::vector<std::pair<int, int> > todo = {{0, n - 1}};
    while(!todo.empty()) {
      const std::pair<int, int> s = todo.back();
      todo.pop_back();
      if(s.second - s.first < 2) continue;
      const int k = split[s.first][s.second];
      triangles.push_back({{c.loop[s.first], c.loop[k], c.loop[s.second]}});
      todo.push_back(std::make_pair(s.first, k));
      todo.push_back(std::make_pair(k, s.second));
    }
    return true;
  }

  // The cavity's triangles and removed nodes dead, the new ones added
  // (corner -1: the new center); returns the center's index, or -1
  int cavityMesher::replace(const cavity &c, const closestTriangleHit *center,
                            const std::vector<std::array<int, 3> > &triangles)
  {
    for(int s : c.triangles) _deadTriangle[s] = true;
    for(int v : c.removed) _deadPoint[v] = true;
    for(int v : c.loop) {
      std::vector<int> &l = _around[v];
      l.erase(std::remove_if(l.begin(), l.end(),
                             [&](int s) { return c.triangles.count(s) > 0; }),
              l.end());
    }
    int n = -1;
    if(center) {
      n = (int)_m.points.size();
      double size = 0.;
      for(int v : c.loop) size += _m.size[v] / c.loop.size();
      _m.points.push_back(center->point);
      _m.movable.push_back(true);
      _m.landing.push_back(center->triangle);
      _m.inputNode.push_back(-1);
      _m.size.push_back(size);
      _m.origin.push_back(-1);
      _deadPoint.push_back(false);
      _around.emplace_back();
    }
    for(std::array<int, 3> t : triangles) {
      for(int &v : t)
        if(v < 0) v = n;
      const int s = (int)_m.triangles.size();
      _m.triangles.push_back(t);
      _m.triangleOrigin.push_back(-1);
      _m.against.push_back(false);
      _deadTriangle.push_back(false);
      for(int v : t) _around[v].push_back(s);
    }
    return n;
  }

  bool cavityMesher::remesh(int t, int &center)
  {
    // where a fan's center may go: the kernel's centroid, else (a cavity
    // curved too much for one plane: a strip narrower than the size rolled
    // over a sharp bend) the input under the triangle's centroid and under
    // its edges' midpoints
    const std::vector<SPoint3> &x = _m.points;
    const std::array<int, 3> &tri = _m.triangles[t];
    std::vector<closestTriangleHit> others;
    for(const SPoint3 &p :
        {(x[tri[0]] + x[tri[1]] + x[tri[2]]) * (1. / 3.),
         (x[tri[0]] + x[tri[1]]) * 0.5, (x[tri[1]] + x[tri[2]]) * 0.5,
         (x[tri[2]] + x[tri[0]]) * 0.5}) {
      const closestTriangleHit hit = _onInput.closest(p);
      if(hit.triangle >= 0) others.push_back(hit);
    }
    for(bool wide : {true, false}) {
      cavity c;
      tangentFrame plane;
      if(!cavityOf(t, wide, c) || !planeOf(c, plane)) continue;
      std::vector<std::array<int, 3> > triangles;
      closestTriangleHit hit;
      if(fanCenter(c, plane, hit) && fan(c, hit, triangles)) {
        center = replace(c, &hit, triangles);
        return true;
      }
      if(polygon(c, plane, triangles)) {
        center = replace(c, nullptr, triangles);
        return true;
      }
      for(const closestTriangleHit &other : others)
        if(fan(c, other, triangles)) {
          center = replace(c, &other, triangles);
          return true;
        }
    }
    return false;
  }

} // namespace

bool inputTangentFrame(const surfaceMesh &input,
                       const closestTriangleSearch &onInput,
                       const SPoint3 &origin, bool reversed,
                       tangentFrame &frame)
{
  const closestTriangleHit under = onInput.closest(origin);
  if(under.triangle < 0) return false;
  const std::array<int, 3> &t = input.triangles[under.triangle];
  SVector3 n = crossprod(SVector3(input.points[t[0]], input.points[t[1]]),
                         SVector3(input.points[t[0]], input.points[t[2]]));
  if(norm(n) == 0.) return false;
  n.normalize();
  if(reversed) n *= -1.;
  frame.origin = origin;
  frame.e1 = crossprod(n, std::fabs(n.x()) < 0.9 ? SVector3(1., 0., 0.) :
                                                   SVector3(0., 1., 0.));
  frame.e1.normalize();
  frame.e2 = crossprod(n, frame.e1);
  return true;
}

bool kernelCentroid(const std::vector<std::array<double, 4> > &edges,
                    std::array<double, 2> &centroid)
{
  std::array<double, 4> box = {{1e300, 1e300, -1e300, -1e300}};
  for(const auto &e : edges)
    for(int k : {0, 2})
      box = {{std::min(box[0], e[k]), std::min(box[1], e[k + 1]),
              std::max(box[2], e[k]), std::max(box[3], e[k + 1])}};
  const std::vector<std::array<double, 2> > kernel = starKernel(edges, box, 1);
  if(kernel.empty()) return false;
  centroid = {{0., 0.}};
  for(const auto &p : kernel) {
    centroid[0] += p[0] / kernel.size();
    centroid[1] += p[1] / kernel.size();
  }
  return true;
}

std::size_t remeshTangledCavities(optimizableMesh &m, const surfaceMesh &input,
                                  const closestTriangleSearch &onInput,
                                  bool reversed, std::vector<int> *centers)
{
  if(m.against.size() != m.triangles.size() || m.size.size() != m.points.size())
    return 0;
  std::vector<int> tangled;
  for(std::size_t t = 0; t < m.triangles.size(); t++)
    if(m.against[t]) tangled.push_back((int)t);
  if(tangled.empty()) return 0;
  cavityMesher mesher(m, input, onInput, reversed);
  std::vector<int> made;
  std::size_t cavities = 0;
  for(int t : tangled) {
    int center = -1;
    if(mesher.dead(t) || !mesher.remesh(t, center)) continue;
    cavities++;
    if(center >= 0) made.push_back(center);
  }
  if(!cavities) return 0;
  const std::vector<int> newIndex = mesher.compact();
  if(centers)
    for(int v : made) centers->push_back(newIndex[v]);
  return cavities;
}
} // namespace reparam

