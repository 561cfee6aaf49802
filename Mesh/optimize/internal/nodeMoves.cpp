// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Node moves around the triangles below the target: the places a node is
// tried at (the neighbours' centroid, the worst triangle's apex, the
// max-min place of its ring, the kernel of a tangled ring), on the input.

#include <algorithm>
#include <cmath>
#include "SVector3.h"
#include "localOptimizer.h"
#include "maxMinPlacement.h"
#include "tangledCavity.h"

namespace reparam::optimizeInternal {

// Where v makes the worst triangle around it equilateral: over the
// middle of the opposite edge, across it from nothing, in the plane of
// the ring (the mean of its triangles' normals, as oriented)
SPoint3 localOptimizer::worstTriangleApex(int v) const
{
  const std::vector<SPoint3> &x = _m.points;
  SVector3 normal = ringNormal(v);
  int worst = -1;
  double worstKappa = 2.;
  for(int t : _around[v]) {
    const double k = kappa(t);
    if(k < worstKappa) {
      worstKappa = k;
      worst = t;
    }
  }
  if(worst < 0 || norm(normal) == 0.) return x[v];
  normal.normalize();
  // (v, a, b) in the triangle's order: v lies on the side n x (b - a)
  const std::array<int, 3> &c = _m.triangles[worst];
  int k = 0;
  while(c[k] != v) k++;
  const SPoint3 &a = x[c[(k + 1) % 3]], &b = x[c[(k + 2) % 3]];
  SVector3 side = crossprod(normal, SVector3(a, b));
  if(norm(side) == 0.) return x[v];
  side.normalize();
  side *= 0.5 * std::sqrt(3.) * a.distance(b);
  const SPoint3 middle = (a + b) * 0.5;
  return SPoint3(middle.x() + side.x(), middle.y() + side.y(),
                 middle.z() + side.z());
}

// Where v lifts the worst triangle around it most, in the plane of its
// ring (Mesh/optimize/maxMinPlacement.h), from steps of a quarter of its
// mean edge
SPoint3 localOptimizer::maxMinPoint(int v) const
{
  const std::vector<SPoint3> &x = _m.points;
  std::vector<std::array<SPoint3, 2> > opposite;
  double edges = 0.;
  for(int t : _around[v]) {
    const std::array<int, 3> &c = _m.triangles[t];
    int k = 0;
    while(c[k] != v) k++;
    opposite.push_back({{x[c[(k + 1) % 3]], x[c[(k + 2) % 3]]}});
    edges += x[v].distance(x[c[(k + 1) % 3]]);
  }
  if(opposite.empty()) return x[v];
  return maxMinKappaPoint(x[v], opposite, ringNormal(v),
                          0.25 * edges / opposite.size());
}

// The centroid of the kernel of v's ring projected on the plane of the
// input under v (the region from which every opposite edge is seen on the
// side the input's orientation asks), lifted back to 3D; false if empty
bool localOptimizer::starKernelPoint(int v, SPoint3 &at) const
{
  const std::vector<SPoint3> &x = _m.points;
  tangentFrame plane;
  if(!inputTangentFrame(_input, _onInput, x[v], _o.reversed, plane))
    return false;
  // (v, a, b) along the input turns counterclockwise in the plane: v on
  // the left of a -> b
  std::vector<std::array<double, 4> > edges;
  for(int t : _around[v]) {
    const std::array<int, 3> &c = _m.triangles[t];
    int k = 0;
    while(c[k] != v) k++;
    const std::array<double, 2> a = plane.of(x[c[(k + 1) % 3]]),
                                b = plane.of(x[c[(k + 2) % 3]]);
    edges.push_back({{a[0], a[1], b[0], b[1]}});
  }
  std::array<double, 2> middle;
  if(!kernelCentroid(edges, middle)) return false;
  at = plane.at(middle[0], middle[1]);
  return true;
}

// v moved to its neighbours' centroid or halfway there, on the input, if
// the triangles around it get better (the searches on the input only for
// positions that would be better)
bool localOptimizer::tryMove(int v)
{
  if(spent()) return false;
  if(!_m.movable[v] || _around[v].empty() || !_dirty[v]) return false;
  _dirty[v] = false; // until something around it changes
  const SPoint3 centroid = ringCentroid(v);
  const SPoint3 here = _m.points[v];
  // better: the worst triangle around v better, or as good and the mean
  // better (the worst may be held by nodes that do not move)
  std::pair<double, double> before = ringKappa(v, here);
  // a triangle against the input counts as worse than any along it: the
  // move that turns it back is better (signed quality)
  for(int t : _around[v])
    if(_m.against[t]) before.first = -1.;
  // the centroid (Laplacian smoothing) evens the ring, the apex of the
  // worst triangle lifts a cap (v near the middle of the opposite edge)
  // that the centroid leaves: both, and halfway there
  const SPoint3 apex = worstTriangleApex(v);
  std::vector<SPoint3> targets = {centroid, (here + centroid) * 0.5, apex,
                                  (here + apex) * 0.5};
  // the place that lifts the worst triangle most: where each of those
  // trades one triangle of a tight ring for another
  if(before.first >= 0.) targets.push_back(maxMinPoint(v));
  // a tangled ring (a triangle folded over its neighbours): the point
  // every triangle around sees on the right side, in the input's tangent
  // plane, when there is one
  SPoint3 kernel;
  if(before.first < 0. && starKernelPoint(v, kernel)) targets.push_back(kernel);
  std::vector<std::pair<double, closestTriangleHit> > better;
  for(const SPoint3 &to : targets) {
    const closestTriangleHit hit = _onInput.closest(to);
    if(hit.triangle < 0) continue;
    const std::pair<double, double> after = ringKappa(v, hit.point);
    if(after.first >= before.first + minimalGain ||
       (after.first >= before.first &&
        after.second >= before.second + minimalGain))
      better.push_back(std::make_pair(after.first + after.second, hit));
  }
  if(better.empty()) return false;
  std::sort(better.begin(), better.end(),
            [](const std::pair<double, closestTriangleHit> &a,
               const std::pair<double, closestTriangleHit> &b) {
              return a.first > b.first;
            });
  bool valid;
  const double farthestHere =
    std::max(ringFarthest(v, here, _o.moveTolerance, true, valid), 0.);
  for(const auto &b : better) {
    const double farthest =
      ringFarthest(v, b.second.point, _o.moveTolerance, true, valid);
    if(!valid || farthest > farthestHere) continue;
    _m.points[v] = b.second.point;
    _m.landing[v] = b.second.triangle;
    for(int t : _around[v]) _m.against[t] = false;
    changedAround(v);
    return true;
  }
  return false;
}

} // namespace reparam::optimizeInternal
