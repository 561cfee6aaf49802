// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Edge flips: around the triangles below the target (both new triangles
// better), and in the smoothing sweeps towards the valences of a mesh of
// equilateral triangles.

#include <algorithm>
#include <cmath>
#include "SVector3.h"
#include "localOptimizer.h"
#include "ringGeometry.h"
#include "triangleQuality.h"

namespace reparam::optimizeInternal {

// How many points v shares an edge with
int localOptimizer::valenceOf(int v) const
{
  std::vector<int> n;
  for(int t : _around[v])
    for(int w : _m.triangles[t])
      if(w != v) n.push_back(w);
  std::sort(n.begin(), n.end());
  return (int)(std::unique(n.begin(), n.end()) - n.begin());
}

// The valence v would have in a mesh of equilateral triangles: 6 where
// its triangles close around it, else one more than their angles at v
// summed over 60 degrees, rounded (4 on a straight border), at least 2
int localOptimizer::idealValenceOf(int v) const
{
  std::vector<std::pair<int, int> > sides;
  double angle = 0.;
  for(int t : _around[v]) {
    const std::array<int, 3> &c = _m.triangles[t];
    int k = 0;
    while(c[k] != v) k++;
    const int next = c[(k + 1) % 3], previous = c[(k + 2) % 3];
    sides.push_back(std::make_pair(std::min(v, next), std::max(v, next)));
    sides.push_back(
      std::make_pair(std::min(v, previous), std::max(v, previous)));
    const SVector3 u(_m.points[v], _m.points[next]);
    const SVector3 w(_m.points[v], _m.points[previous]);
    angle += std::atan2(crossprod(u, w).norm(), dot(u, w));
  }
  std::sort(sides.begin(), sides.end());
  bool closed = !sides.empty();
  for(std::size_t i = 0; i < sides.size(); i += 2)
    closed = closed && i + 1 < sides.size() && sides[i] == sides[i + 1];
  if(closed) return 6;
  return std::max(2, (int)std::lround(angle / (M_PI / 3.)) + 1);
}

// Edge k of t (corners k, k + 1) flipped if both new triangles are better
// or, forValence, if the four corners' valences come closer to their
// ideal (idealValenceOf) and no new triangle falls below valenceFloor
// unless the pair's worst was below it and the flip does not lower it
bool localOptimizer::tryFlip(int t, int k, bool forValence)
{
  if(spent()) return false;
  const int a = _m.triangles[t][k], b = _m.triangles[t][(k + 1) % 3];
  const int p = _m.triangles[t][(k + 2) % 3];
  if(_m.lockedEdges.count(std::make_pair(std::min(a, b), std::max(a, b))))
    return false;
  const int s = neighbourAcross(t, a, b);
  if(s < 0) return false;
  int q = -1;
  for(int v : _m.triangles[s])
    if(v != a && v != b) q = v;
  // s must run b -> a (consistent orientation), and pq must be new
  const std::array<int, 3> &cs = _m.triangles[s];
  int ib = 0;
  while(cs[ib] != b) ib++;
  if(q < 0 || q == p || cs[(ib + 1) % 3] != a) return false;
  if(forValence && valenceCost(a, -1) + valenceCost(b, -1) + valenceCost(p, 1) +
                       valenceCost(q, 1) >=
                     0.)
    return false;
  for(int r : _around[p]) {
    const std::array<int, 3> &c = _m.triangles[r];
    if(std::find(c.begin(), c.end(), q) != c.end()) return false;
  }
  const std::vector<SPoint3> &x = _m.points;
  // a triangle against the input counts as worse than any along it: the
  // flip that turns it back is better (signed quality)
  const double before =
    _m.against[t] || _m.against[s] ? -1. : std::min(kappa(t), kappa(s));
  // (a, b, p) and (b, a, q) become (a, q, p) and (q, b, p)
  const double after =
    std::min(triangleKappa(x[a], x[q], x[p]), triangleKappa(x[q], x[b], x[p]));
  if(forValence) {
    // where a corner is fixed the node moves after cannot even out what
    // the flip made worse
    const bool free =
      _m.movable[a] && _m.movable[b] && _m.movable[p] && _m.movable[q];
    if(after < (free ? std::min(before, valenceFloor) : before)) return false;
  }
  else if(after < before + minimalGain)
    return false;
  if(against(x[a], x[q], x[p]) || against(x[q], x[b], x[p])) return false;
  const double wasFar =
    std::max(distanceToInput(centroidOf(x[a], x[b], x[p])),
             std::max(distanceToInput(centroidOf(x[b], x[a], x[q])),
                      distanceToInput((x[a] + x[b]) * 0.5)));
  const double far =
    std::max(distanceToInput(centroidOf(x[a], x[q], x[p])),
             std::max(distanceToInput(centroidOf(x[q], x[b], x[p])),
                      distanceToInput((x[p] + x[q]) * 0.5)));
  const double tolerance =
    before < _o.sliver ? _o.sliverTolerance : _o.tolerance;
  if(far > wasFar + tolerance * x[p].distance(x[q])) return false;
  replaceCorner(t, b, q); // (a, b, p) -> (a, q, p)
  replaceCorner(s, a, p); // (b, a, q) -> (b, p, q) = (q, b, p)
  if(!_valence.empty()) {
    _valence[a]--;
    _valence[b]--;
    _valence[p]++;
    _valence[q]++;
  }
  _known[t] = _known[s] = false;
  _m.against[t] = _m.against[s] = false;
  for(int v : {a, b, p, q}) _dirty[v] = true;
  return true;
}

bool localOptimizer::tryFlips(int t, bool forValence)
{
  for(int k = 0; k < 3; k++)
    if(tryFlip(t, k, forValence)) return true;
  return false;
}

// How much farther v gets from its ideal valence (squared) when its
// valence changes by `change` (negative: closer)
double localOptimizer::valenceCost(int v, int change) const
{
  if(_valence.empty()) {
    for(std::size_t w = 0; w < _m.points.size(); w++) {
      _valence.push_back(valenceOf((int)w));
      _idealValence.push_back(idealValenceOf((int)w));
    }
  }
  const double before = _valence[v] - _idealValence[v];
  return (before + change) * (before + change) - before * before;
}

} // namespace reparam::optimizeInternal
