// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <set>
#include <tuple>
#include "SVector3.h"
#include "closestTriangle.h"
#include "inputNodesNear.h"
#include "meshFidelity.h"
#include "optimizableMesh.h"
#include "shortEdgeCollapse.h"
#include "triangleQuality.h"

namespace reparam {

namespace {

  SVector3 normalOf(const SPoint3 &a, const SPoint3 &b, const SPoint3 &c)
  {
    SVector3 n = crossprod(SVector3(a, b), SVector3(a, c));
    const double l = n.norm();
    return l > 0. ? n * (1. / l) : n;
  }

  class collapser {
  public:
    collapser(optimizableMesh &m, const surfaceMesh &input,
              const closestTriangleSearch &onInput, bool reversed,
              double tolerance)
      : _m(m), _input(input), _onInput(onInput), _reversed(reversed),
        _tolerance(tolerance), _near(input), _around(m.points.size()),
        _deadTriangle(m.triangles.size(), false),
        _deadPoint(m.points.size(), false)
    {
      for(std::size_t t = 0; t < m.triangles.size(); t++)
        for(int v : m.triangles[t]) _around[v].push_back((int)t);
    }
    bool collapse(int a, int b);
    // returns the new index of each point (-1: removed)
    std::vector<int> compact();

  private:
    optimizableMesh &_m;
    const surfaceMesh &_input;
    const closestTriangleSearch &_onInput;
    const bool _reversed;
    const double _tolerance;
    const inputNodesNear _near;
    std::vector<std::vector<int> > _around;
    std::vector<bool> _deadTriangle, _deadPoint;

    std::set<int> neighbours(int v) const
    {
      std::set<int> n;
      for(int t : _around[v])
        for(int w : _m.triangles[t])
          if(w != v) n.insert(w);
      return n;
    }
    bool acceptable(int keep, int gone, const SPoint3 &at,
                    const std::vector<int> &ring,
                    const std::vector<int> &removed) const;
    bool keepsInputNodes(int keep, int gone, const SPoint3 &at,
                         const std::vector<int> &ring,
                         const std::vector<int> &removed, double size) const;
  };

  double distanceTo(const SPoint3 &p, const SPoint3 &a, const SPoint3 &b,
                    const SPoint3 &c)
  {
    return p.distance(closestPointOnTriangle(p, a, b, c));
  }

  // Whether the input nodes under the triangles around the collapse stay
  // within the tolerance of the new triangles, or no farther than they were
  // from the old ones: checking the removed point only, a collapse on a
  // coarse curved input cut across the input between (bench/README.md,
  // Optimization on the input)
  bool collapser::keepsInputNodes(int keep, int gone, const SPoint3 &at,
                                  const std::vector<int> &ring,
                                  const std::vector<int> &removed,
                                  double size) const
  {
    const std::vector<SPoint3> &x = _m.points;
    double radius = 0.;
    for(const std::vector<int> *part : {&ring, &removed})
      for(int t : *part)
        for(int v : _m.triangles[t])
          radius = std::max(radius, x[v].distance(x[gone]));
    const int start = gone < (int)_m.landing.size() && _m.landing[gone] >= 0 ?
                        _m.landing[gone] :
                        _onInput.closest(x[gone]).triangle;
    for(int n : _near.within(start, x[gone], radius)) {
      const SPoint3 &p = _input.points[n];
      double before = 1e300, after = 1e300;
      for(const std::vector<int> *part : {&ring, &removed})
        for(int t : *part) {
          const std::array<int, 3> &c = _m.triangles[t];
          before = std::min(before, distanceTo(p, x[c[0]], x[c[1]], x[c[2]]));
        }
      for(int t : ring) {
        const std::array<int, 3> &c = _m.triangles[t];
        SPoint3 q[3];
        for(int k = 0; k < 3; k++)
          q[k] = c[k] == gone || c[k] == keep ? at : x[c[k]];
        after = std::min(after, distanceTo(p, q[0], q[1], q[2]));
      }
      if(after > before * (1. + 1e-9) && after > _tolerance * size)
        return false;
    }
    return true;
  }

  // The triangles of `ring` with `gone` replaced by `keep` at `at`: valid,
  // no worse, not much longer, still through the point removed
  bool collapser::acceptable(int keep, int gone, const SPoint3 &at,
                             const std::vector<int> &ring,
                             const std::vector<int> &removed) const
  {
    const std::vector<SPoint3> &x = _m.points;
    double before = 1., after = 1., farthest = 1e300;
    for(int t : removed) {
      const std::array<int, 3> &c = _m.triangles[t];
      before = std::min(before, triangleKappa(x[c[0]], x[c[1]], x[c[2]]));
    }
    const double size = _m.size[keep];
    for(int t : ring) {
      const std::array<int, 3> &c = _m.triangles[t];
      if(_m.against.size() == _m.triangles.size() && _m.against[t])
        return false;
      SPoint3 p[3];
      for(int k = 0; k < 3; k++)
        p[k] = c[k] == gone || c[k] == keep ? at : x[c[k]];
      before = std::min(before, triangleKappa(x[c[0]], x[c[1]], x[c[2]]));
      after = std::min(after, triangleKappa(p[0], p[1], p[2]));
      // turned by 45 degrees or more: a fold, or against the input
      if(dot(normalOf(p[0], p[1], p[2]), normalOf(x[c[0]], x[c[1]], x[c[2]])) <
         0.7)
        return false;
      for(int k = 0; k < 3; k++)
        if(p[k].distance(p[(k + 1) % 3]) > 1.4 * size) return false;
      farthest = std::min(farthest, x[gone].distance(closestPointOnTriangle(
                                      x[gone], p[0], p[1], p[2])));
    }
    if(after < std::min(before, 0.75) || farthest > _tolerance * size)
      return false;
    if(!keepsInputNodes(keep, gone, at, ring, removed, size)) return false;
    // last, as it searches the input: none against it (the report's test)
    for(int t : ring) {
      const std::array<int, 3> &c = _m.triangles[t];
      SPoint3 p[3];
      for(int k = 0; k < 3; k++)
        p[k] = c[k] == gone || c[k] == keep ? at : x[c[k]];
      if(triangleAgainstInput(p[0], p[1], p[2], _input, _onInput) != _reversed)
        return false;
    }
    return true;
  }

  bool collapser::collapse(int a, int b)
  {
    if(_deadPoint[a] || _deadPoint[b]) return false;
    if(!_m.movable[b]) std::swap(a, b);
    if(!_m.movable[b]) return false; // both fixed
    if(_m.lockedEdges.count(std::make_pair(std::min(a, b), std::max(a, b))))
      return false;
    std::vector<int> removed, ring;
    for(int t : _around[b]) {
      const std::array<int, 3> &c = _m.triangles[t];
      (std::find(c.begin(), c.end(), a) != c.end() ? removed : ring)
        .push_back(t);
    }
    if(removed.size() != 2) return false; // a boundary or non-manifold edge
    // manifold after: a and b share exactly the two opposite corners
    std::set<int> common, na = neighbours(a), nb = neighbours(b);
    std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(),
                          std::inserter(common, common.begin()));
    if(common.size() != 2) return false;
    SPoint3 at = _m.points[a];
    int landing = -1;
    if(_m.movable[a]) {
      const closestTriangleHit hit =
        _onInput.closest((_m.points[a] + _m.points[b]) * 0.5);
      if(hit.triangle < 0) return false;
      at = hit.point;
      landing = hit.triangle;
    }
    for(int t : _around[a])
      if(std::find(removed.begin(), removed.end(), t) == removed.end())
        ring.push_back(t);
    if(!acceptable(a, b, at, ring, removed)) return false;
    for(int t : removed) {
      _deadTriangle[t] = true;
      for(int v : _m.triangles[t]) {
        std::vector<int> &l = _around[v];
        l.erase(std::remove(l.begin(), l.end(), t), l.end());
      }
    }
    for(int t : _around[b]) {
      for(int &v : _m.triangles[t])
        if(v == b) v = a;
      _around[a].push_back(t);
      if(_m.against.size() == _m.triangles.size()) _m.against[t] = false;
    }
    _around[b].clear();
    _deadPoint[b] = true;
    if(landing >= 0) {
      _m.points[a] = at;
      _m.landing[a] = landing;
    }
    return true;
  }

  std::vector<int> collapser::compact()
  {
    return removeDeadParts(_m, _deadPoint, _deadTriangle);
  }

} // namespace

std::size_t collapseShortEdges(optimizableMesh &m, const surfaceMesh &input,
                               const closestTriangleSearch &onInput,
                               bool reversed, double ratio, double tolerance,
                               std::vector<int> *kept)
{
  if(m.size.size() != m.points.size() || m.triangles.empty()) return 0;
  m.origin.resize(m.points.size(), -1);
  m.triangleOrigin.resize(m.triangles.size(), -1);
  // (length over the size, a, b), each edge once
  std::vector<std::tuple<double, int, int> > shortEdges;
  for(const std::array<int, 3> &t : m.triangles)
    for(int k = 0; k < 3; k++) {
      const int a = t[k], b = t[(k + 1) % 3];
      if(a > b) continue;
      const double size = 0.5 * (m.size[a] + m.size[b]);
      const double length = m.points[a].distance(m.points[b]);
      if(size > 0. && length < ratio * size)
        shortEdges.push_back(std::make_tuple(length / size, a, b));
    }
  if(shortEdges.empty()) return 0;
  std::sort(shortEdges.begin(), shortEdges.end());
  collapser c(m, input, onInput, reversed, tolerance);
  std::size_t collapsed = 0;
  std::vector<int> into;
  for(const auto &e : shortEdges) {
    int a = std::get<1>(e), b = std::get<2>(e);
    if(!c.collapse(a, b)) continue;
    collapsed++;
    into.push_back(a);
    into.push_back(b); // one of them stays
  }
  if(!collapsed) return 0;
  const std::vector<int> newIndex = c.compact();
  if(kept)
    for(int v : into)
      if(newIndex[v] >= 0) kept->push_back(newIndex[v]);
  return collapsed;
}
} // namespace reparam

