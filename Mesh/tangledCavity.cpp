// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include "SVector3.h"
#include "closestTriangle.h"
#include "flipRepair.h"
#include "meshFidelity.h"
#include "surfaceMeshOptimizer.h"
#include "tangledCavity.h"
#include "triangleQuality.h"

namespace {

  // A cavity: its triangles, the movable nodes it removes, its boundary as
  // directed edges in the triangles' turn
  struct cavity {
    std::set<int> triangles, removed;
    std::vector<std::array<int, 2> > boundary;
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

    // the new node, -1 if t's cavity was left
    int remesh(int t);
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

    bool cavityOf(int t, cavity &c) const;
    bool fanCenter(const cavity &c, closestTriangleHit &center) const;
  };

  bool cavityMesher::cavityOf(int t, cavity &c) const
  {
    for(int v : _m.triangles[t])
      if(_m.movable[v]) c.removed.insert(v);
    if(c.removed.empty()) return false;
    for(int v : c.removed)
      for(int s : _around[v]) c.triangles.insert(s);
    // edges used twice inside are inner; an inner one locked: left alone
    std::map<std::pair<int, int>, int> uses;
    for(int s : c.triangles)
      for(int k = 0; k < 3; k++) {
        const int a = _m.triangles[s][k], b = _m.triangles[s][(k + 1) % 3];
        uses[std::make_pair(std::min(a, b), std::max(a, b))]++;
      }
    for(const auto &u : uses)
      if(u.second > 2 || (u.second == 2 && _m.lockedEdges.count(u.first)))
        return false;
    for(int s : c.triangles)
      for(int k = 0; k < 3; k++) {
        const int a = _m.triangles[s][k], b = _m.triangles[s][(k + 1) % 3];
        if(uses[std::make_pair(std::min(a, b), std::max(a, b))] == 1)
          c.boundary.push_back({{a, b}});
      }
    // one loop, through no removed node: each boundary node starts one edge
    std::map<int, int> next;
    for(const auto &e : c.boundary) {
      if(c.removed.count(e[0]) || c.removed.count(e[1]) ||
         !next.insert(std::make_pair(e[0], e[1])).second)
        return false;
    }
    if(c.boundary.size() < 3) return false;
    std::size_t length = 0;
    int v = c.boundary[0][0];
    do {
      auto it = next.find(v);
      if(it == next.end()) return false;
      v = it->second;
      length++;
    } while(v != c.boundary[0][0] && length <= c.boundary.size());
    return length == c.boundary.size();
  }

  // The centroid of the kernel of the cavity's boundary in the plane of the
  // input under its nodes' centroid, on the input
  bool cavityMesher::fanCenter(const cavity &c,
                               closestTriangleHit &center) const
  {
    const std::vector<SPoint3> &x = _m.points;
    SPoint3 origin(0., 0., 0.);
    for(const auto &e : c.boundary) origin += x[e[0]];
    origin *= 1. / c.boundary.size();
    const closestTriangleHit under = _onInput.closest(origin);
    if(under.triangle < 0) return false;
    const std::array<int, 3> &it = _input.triangles[under.triangle];
    SVector3 n = crossprod(SVector3(_input.points[it[0]], _input.points[it[1]]),
                           SVector3(_input.points[it[0]], _input.points[it[2]]));
    if(norm(n) == 0.) return false;
    n.normalize();
    SVector3 e1 = crossprod(n, std::fabs(n.x()) < 0.9 ? SVector3(1., 0., 0.) :
                                                        SVector3(0., 1., 0.));
    e1.normalize();
    const SVector3 e2 = crossprod(n, e1);
    std::vector<std::array<double, 4> > edges;
    std::array<double, 4> box = {{1e300, 1e300, -1e300, -1e300}};
    for(const auto &e : c.boundary) {
      const SVector3 a(origin, x[e[0]]), b(origin, x[e[1]]);
      edges.push_back({{dot(a, e1), dot(a, e2), dot(b, e1), dot(b, e2)}});
      box[0] = std::min(box[0], dot(a, e1));
      box[1] = std::min(box[1], dot(a, e2));
      box[2] = std::max(box[2], dot(a, e1));
      box[3] = std::max(box[3], dot(a, e2));
    }
    // the triangles along the input turn counterclockwise about n: the
    // cavity is on the left of its boundary
    const std::vector<std::array<double, 2> > kernel =
      starKernel(edges, box, _reversed ? -1 : 1);
    if(kernel.empty()) return false;
    double u = 0., w = 0.;
    for(const auto &p : kernel) {
      u += p[0] / kernel.size();
      w += p[1] / kernel.size();
    }
    const SVector3 shift = e1 * u + e2 * w;
    center = _onInput.closest(
      SPoint3(origin.x() + shift.x(), origin.y() + shift.y(),
              origin.z() + shift.z()));
    return center.triangle >= 0;
  }

  int cavityMesher::remesh(int t)
  {
    cavity c;
    closestTriangleHit center;
    if(!cavityOf(t, c) || !fanCenter(c, center)) return -1;
    const std::vector<SPoint3> &x = _m.points;
    for(const auto &e : c.boundary) {
      const SPoint3 &a = x[e[0]], &b = x[e[1]];
      if(triangleKappa(center.point, a, b) <= 0. ||
         triangleAgainstInput(center.point, a, b, _input, _onInput) !=
           _reversed)
        return -1;
    }
    for(int s : c.triangles) _deadTriangle[s] = true;
    for(int v : c.removed) _deadPoint[v] = true;
    const int n = (int)_m.points.size();
    double size = 0.;
    for(const auto &e : c.boundary) size += _m.size[e[0]] / c.boundary.size();
    _m.points.push_back(center.point);
    _m.movable.push_back(true);
    _m.landing.push_back(center.triangle);
    _m.inputNode.push_back(-1);
    _m.size.push_back(size);
    _m.origin.push_back(-1);
    _deadPoint.push_back(false);
    _around.emplace_back();
    for(const auto &e : c.boundary) {
      const int s = (int)_m.triangles.size();
      _m.triangles.push_back({{n, e[0], e[1]}});
      _m.triangleOrigin.push_back(-1);
      _m.against.push_back(false);
      _deadTriangle.push_back(false);
      for(int v : _m.triangles[s]) _around[v].push_back(s);
    }
    for(const auto &e : c.boundary)
      for(int v : e) {
        std::vector<int> &l = _around[v];
        l.erase(std::remove_if(l.begin(), l.end(),
                               [&](int s) { return c.triangles.count(s) > 0; }),
                l.end());
      }
    return n;
  }

} // namespace

std::size_t remeshTangledCavities(optimizableMesh &m, const surfaceMesh &input,
                                  const closestTriangleSearch &onInput,
                                  bool reversed, std::vector<int> *centers)
{
  if(m.against.size() != m.triangles.size() ||
     m.size.size() != m.points.size())
    return 0;
  std::vector<int> tangled;
  for(std::size_t t = 0; t < m.triangles.size(); t++)
    if(m.against[t]) tangled.push_back((int)t);
  if(tangled.empty()) return 0;
  cavityMesher mesher(m, input, onInput, reversed);
  std::vector<int> made;
  for(int t : tangled) {
    if(mesher.dead(t)) continue;
    const int center = mesher.remesh(t);
    if(center >= 0) made.push_back(center);
  }
  if(made.empty()) return 0;
  const std::vector<int> newIndex = mesher.compact();
  if(centers)
    for(int v : made) centers->push_back(newIndex[v]);
  return made.size();
}
