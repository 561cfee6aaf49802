// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Smoothing sweeps: every movable node to the place its ring's kappa sum
// prefers, where the worst triangle does not fall and the ring holds the
// input it held (bench/README.md, Smoothing).

#include <algorithm>
#include <cmath>
#include "SVector3.h"
#include "localOptimizer.h"
#include "optimizationPasses.h"
#include "ringGeometry.h"
#include "triangleQuality.h"

namespace reparam::optimizeInternal {

// A smoothing move's ring: the worst not lower, no more triangles below
// the target, the sum of the kappas higher by sumGain
bool localOptimizer::smoothedBetter(const ringQuality &before,
                                    const ringQuality &after, double sumGain)
{
  return after.worst >= before.worst && after.below <= before.below &&
         after.sum >= before.sum + sumGain;
}

// The mean over the triangles around v of the point that makes each
// equilateral (over the middle of the edge opposite v, on v's side, in the
// plane of the ring)
SPoint3 localOptimizer::ringApexMean(int v) const
{
  const std::vector<SPoint3> &x = _m.points;
  SVector3 normal = ringNormal(v);
  if(norm(normal) == 0.) return x[v];
  normal.normalize();
  SPoint3 mean(0., 0., 0.);
  for(int t : _around[v]) {
    const std::array<int, 3> &c = _m.triangles[t];
    int k = 0;
    while(c[k] != v) k++;
    // (v, a, b) in the triangle's order: v lies on the side n x (b - a)
    const SPoint3 &a = x[c[(k + 1) % 3]], &b = x[c[(k + 2) % 3]];
    SVector3 side = crossprod(normal, SVector3(a, b));
    if(norm(side) > 0.)
      side *= 0.5 * std::sqrt(3.) * a.distance(b) / norm(side);
    const SPoint3 middle = (a + b) * 0.5;
    mean += SPoint3(middle.x() + side.x(), middle.y() + side.y(),
                    middle.z() + side.z());
  }
  return mean * (1. / _around[v].size());
}

// Where smoothing may move v, best first: the neighbours' centroid (which
// evens the edges), the mean of the points that make each triangle around
// equilateral (which evens the angles), and halfway to each, those where
// the ring's kappa sum rises by sumGain, its worst does not fall and none
// falls below the target
std::vector<SPoint3> localOptimizer::smoothingTargets(int v,
                                                      const ringQuality &before,
                                                      double sumGain) const
{
  const SPoint3 here = _m.points[v], centroid = ringCentroid(v),
                apex = ringApexMean(v);
  std::vector<std::pair<double, SPoint3> > better;
  for(const SPoint3 &to :
      {apex, centroid, (here + apex) * 0.5, (here + centroid) * 0.5}) {
    const ringQuality after = ringAt(v, to);
    if(smoothedBetter(before, after, sumGain))
      better.push_back(std::make_pair(-after.sum, to));
  }
  std::sort(
    better.begin(), better.end(),
    [](const std::pair<double, SPoint3> &a,
       const std::pair<double, SPoint3> &b) { return a.first < b.first; });
  std::vector<SPoint3> targets;
  for(const auto &b : better) targets.push_back(b.second);
  return targets;
}

// Whether the input's points v's ring held stay held with v at `to`:
// where v was (a point of the input: a tip) and the points of the input
// closest to the ring's centroids (`held`: on a crease under the feature
// angle, points of the crease) no farther from the ring than they were,
// but for a small share of its size
bool localOptimizer::holdsInput(
  int v, const SPoint3 &to, const std::vector<closestTriangleHit> &held) const
{
  const double tolerance = _o.smoothTolerance * ringLongestEdge(v);
  if(distanceToRing(v, to, _m.points[v]) > tolerance) return false;
  for(const closestTriangleHit &h : held)
    if(distanceToRing(v, to, h.point) > h.distance + tolerance) return false;
  return true;
}

// v moved where smoothingTargets says, on the input (its closest point),
// if that is still better there, no triangle of its ring points against
// the input nor gets farther from it (as tryMove: beyond a share of its
// size, the sag of a larger triangle on a curved input), and the ring
// holds the input it held. Most nodes of a frontal mesh gain nothing: a
// position is searched on the input only if it would be better before
// the search (the search moves it by the input's sag, small against the
// triangles around)
bool localOptimizer::trySmooth(int v, double gain)
{
  if(spent()) return false;
  if(!_m.movable[v] || _around[v].empty() || !_dirty[v]) return false;
  _dirty[v] = false;
  for(int t : _around[v])
    if(_m.against[t]) return false; // tryMove's
  const SPoint3 here = _m.points[v];
  const ringQuality before = ringAt(v, here);
  const double sumGain = gain * _around[v].size();
  double farthestHere = -1.;
  bool valid;
  std::vector<closestTriangleHit> held;
  for(const SPoint3 &to : smoothingTargets(v, before, sumGain)) {
    _searches++;
    const int t0 = _around[v][0];
    const closestTriangleHit hit =
      _onInput.closest(to, _m.landing[v] >= 0 ? _m.landing[v] :
                           _known[t0]         ? _atCentroid[t0].triangle :
                                                -1);
    if(hit.triangle < 0 ||
       !smoothedBetter(before, ringAt(v, hit.point), sumGain))
      continue;
    if(farthestHere < 0.) { // none against the input here
      farthestHere = 0.;
      held.clear();
      for(int t : _around[v]) {
        const std::array<int, 3> &c = _m.triangles[t];
        held.push_back(centroidHit(t));
        farthestHere = std::max(
          farthestHere,
          held.back().distance -
            _o.moveTolerance *
              longestEdge(_m.points[c[0]], _m.points[c[1]], _m.points[c[2]]));
      }
    }
    std::vector<closestTriangleHit> hits;
    if(ringFarthest(v, hit.point, _o.moveTolerance, true, valid, &hits) >
         farthestHere ||
       !valid || !holdsInput(v, hit.point, held))
      continue;
    _m.points[v] = hit.point;
    _m.landing[v] = hit.triangle;
    changedAround(v);
    for(std::size_t k = 0; k < hits.size(); k++) {
      _atCentroid[_around[v][k]] = hits[k];
      _known[_around[v][k]] = true;
    }
    return true;
  }
  return false;
}

// Sweeps of trySmooth over every movable node, until one moves none
void smoothMesh(optimizableMesh &m, const surfaceMesh &input,
                const closestTriangleSearch &onInput,
                const meshOptimizationOptions &o, meshOptimizationResult &r)
{
  std::size_t searches = 0;
  localOptimizer opt(m, input, onInput, o, searches,
                     o.searchesPerTriangle * m.triangles.size() + 1000);
  opt.valenceFloor = std::max(o.target, worstKappa(m));
  for(int pass = 0; pass < o.smoothPasses && !opt.spent(); pass++) {
    std::size_t changes = 0;
    if(o.valenceFlips)
      for(std::size_t t = 0; t < m.triangles.size(); t++) {
        const bool flipped = opt.tryFlips((int)t, true);
        r.flips += flipped;
        changes += flipped;
      }
    for(std::size_t v = 0; v < m.points.size(); v++)
      changes += opt.trySmooth((int)v, o.smoothGain);
    r.moves += changes;
    if(!changes) break;
  }
  r.searches += searches;
}

} // namespace reparam::optimizeInternal
