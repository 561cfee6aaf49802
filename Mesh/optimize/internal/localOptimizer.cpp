// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include "localOptimizer.h"
#include "meshFidelity.h"
#include "ringGeometry.h"
#include "triangleQuality.h"

namespace reparam::optimizeInternal {

localOptimizer::localOptimizer(optimizableMesh &m, const surfaceMesh &input,
                               const closestTriangleSearch &onInput,
                               const meshOptimizationOptions &o,
                               std::size_t &searches, std::size_t budget)
  : _m(m), _input(input), _onInput(onInput), _o(o), _around(m.points.size()),
    _searches(searches), _budget(budget)
{
  for(std::size_t t = 0; t < m.triangles.size(); t++)
    for(int v : m.triangles[t]) _around[v].push_back((int)t);
  _m.landing.resize(m.points.size(), -1);
  _m.inputNode.resize(m.points.size(), -1);
  _m.movable.resize(m.points.size(), false);
  _dirty.assign(m.points.size(), true);
  _atCentroid.resize(m.triangles.size());
  _known.assign(m.triangles.size(), false);
}

double localOptimizer::kappa(int t) const
{
  const std::array<int, 3> &c = _m.triangles[t];
  return triangleKappa(_m.points[c[0]], _m.points[c[1]], _m.points[c[2]]);
}

std::vector<int> localOptimizer::trianglesBelowTarget() const
{
  std::vector<std::pair<double, int> > below;
  for(std::size_t t = 0; t < _m.triangles.size(); t++) {
    // against the input first, then worst first
    const double k = _m.against[t] ? -1. : kappa((int)t);
    if(k < _o.target) below.push_back(std::make_pair(k, (int)t));
  }
  std::sort(below.begin(), below.end()); // worst first
  std::vector<int> list;
  for(const auto &b : below) list.push_back(b.second);
  return list;
}

void localOptimizer::addNeighbours(int v, std::set<int> &to) const
{
  to.insert(v);
  for(int t : _around[v])
    for(int w : _m.triangles[t]) to.insert(w);
}

void localOptimizer::changedAround(int v)
{
  for(int t : _around[v]) {
    _known[t] = false;
    for(int w : _m.triangles[t]) _dirty[w] = true;
  }
}

const closestTriangleHit &localOptimizer::centroidHit(int t) const
{
  if(!_known[t]) {
    const std::array<int, 3> &c = _m.triangles[t];
    _searches++;
    int near = -1;
    for(int k = 0; k < 3 && near < 0; k++) near = _m.landing[c[k]];
    _atCentroid[t] = _onInput.closest(
      centroidOf(_m.points[c[0]], _m.points[c[1]], _m.points[c[2]]), near);
    _known[t] = true;
  }
  return _atCentroid[t];
}

bool localOptimizer::against(const SPoint3 &a, const SPoint3 &b,
                             const SPoint3 &c) const
{
  _searches += 4;
  return triangleAgainstInput(a, b, c, _input, _onInput) != _o.reversed;
}

double localOptimizer::distanceToInput(const SPoint3 &p) const
{
  _searches++;
  return _onInput.closest(p).distance;
}

// The triangle other than t on edge (a, b), -1 if none or several
int localOptimizer::neighbourAcross(int t, int a, int b) const
{
  int found = -1;
  for(int s : _around[a]) {
    if(s == t) continue;
    const std::array<int, 3> &c = _m.triangles[s];
    if(std::find(c.begin(), c.end(), b) == c.end()) continue;
    if(found >= 0) return -1; // non-manifold edge: leave it
    found = s;
  }
  return found;
}

void localOptimizer::replaceCorner(int t, int from, int to)
{
  for(int &v : _m.triangles[t])
    if(v == from) v = to;
  std::vector<int> &old = _around[from];
  old.erase(std::remove(old.begin(), old.end(), t), old.end());
  _around[to].push_back(t);
}

} // namespace reparam::optimizeInternal
