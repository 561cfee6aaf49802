// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Measures of a node's ring (the triangles around it) with the node
// somewhere else: their kappa, their distance to the input, their size.

#include <algorithm>
#include <set>
#include "localOptimizer.h"
#include "meshFidelity.h"
#include "ringGeometry.h"
#include "triangleQuality.h"

namespace reparam::optimizeInternal {

// The worst and the mean kappa of the triangles around v with v at `at`
std::pair<double, double> localOptimizer::ringKappa(int v,
                                                    const SPoint3 &at) const
{
  double worst = 1., sum = 0.;
  for(int t : _around[v]) {
    SPoint3 c[3];
    cornersWith(_m.triangles[t], v, at, _m.points, c);
    const double k = triangleKappa(c[0], c[1], c[2]);
    worst = std::min(worst, k);
    sum += k;
  }
  return std::make_pair(worst, sum / _around[v].size());
}

// The worst, the sum and the count below the target of the kappas of the
// triangles around v with v at `at`
localOptimizer::ringQuality localOptimizer::ringAt(int v,
                                                   const SPoint3 &at) const
{
  ringQuality r;
  for(int t : _around[v]) {
    SPoint3 c[3];
    cornersWith(_m.triangles[t], v, at, _m.points, c);
    const double k = triangleKappa(c[0], c[1], c[2]);
    r.worst = std::min(r.worst, k);
    r.sum += k;
    r.below += k < _o.target;
  }
  return r;
}

// The largest distance of the centroids of the triangles around v (v at
// `at`) to the input, less `tolerance` times their longest edge; `valid`:
// none of them points against the input (tested only if `checkAgainst`)
double localOptimizer::ringFarthest(int v, const SPoint3 &at, double tolerance,
                                    bool checkAgainst, bool &valid,
                                    std::vector<closestTriangleHit> *hits) const
{
  double farthest = 0.;
  valid = true;
  if(hits) hits->clear();
  for(int t : _around[v]) {
    SPoint3 c[3];
    cornersWith(_m.triangles[t], v, at, _m.points, c);
    _searches++;
    // the centroid moved a little: start from where it was
    const closestTriangleHit hit = _onInput.closest(
      centroidOf(c[0], c[1], c[2]), _known[t] ? _atCentroid[t].triangle : -1);
    if(hits) hits->push_back(hit);
    if(checkAgainst) {
      _searches += 3;
      if(triangleAgainstInput(c[0], c[1], c[2], _input, _onInput, hit) !=
         _o.reversed)
        valid = false;
    }
    farthest = std::max(farthest, hit.distance -
                                    tolerance * longestEdge(c[0], c[1], c[2]));
  }
  return farthest;
}

// The distance of p to the triangles around v with v at `at`
double localOptimizer::distanceToRing(int v, const SPoint3 &at,
                                      const SPoint3 &p) const
{
  double nearest = -1.;
  for(int t : _around[v]) {
    SPoint3 c[3];
    cornersWith(_m.triangles[t], v, at, _m.points, c);
    const double d = p.distance(closestPointOnTriangle(p, c[0], c[1], c[2]));
    if(nearest < 0. || d < nearest) nearest = d;
  }
  return nearest;
}

// The centroid of v's neighbours
SPoint3 localOptimizer::ringCentroid(int v) const
{
  SPoint3 centroid(0., 0., 0.);
  std::set<int> neighbours;
  for(int t : _around[v])
    for(int w : _m.triangles[t])
      if(w != v) neighbours.insert(w);
  for(int w : neighbours) centroid += _m.points[w];
  centroid *= 1. / neighbours.size();
  return centroid;
}

// The longest edge of the triangles around v
double localOptimizer::ringLongestEdge(int v) const
{
  double l = 0.;
  for(int t : _around[v]) {
    const std::array<int, 3> &c = _m.triangles[t];
    l = std::max(
      l, longestEdge(_m.points[c[0]], _m.points[c[1]], _m.points[c[2]]));
  }
  return l;
}

// The plane of v's ring (ringGeometry.h)
SVector3 localOptimizer::ringNormal(int v) const
{
  return optimizeInternal::ringNormal(_m.points, _m.triangles, _around[v]);
}

} // namespace reparam::optimizeInternal
