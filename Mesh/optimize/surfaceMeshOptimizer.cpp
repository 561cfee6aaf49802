// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include "SVector3.h"
#include "closestTriangle.h"
#include "farInputNodes.h"
#include "longEdgeSplit.h"
#include "maxMinPlacement.h"
#include "shortEdgeCollapse.h"
#include "tangledCavity.h"
#include "meshFidelity.h"
#include "surfaceMeshOptimizer.h"
#include "triangleQuality.h"

namespace reparam {

namespace {

  // A kept change must raise the worst kappa by this much: no cycles, no
  // work for rounding
  const double minimalGain = 1e-2;

  SPoint3 centroidOf(const SPoint3 &a, const SPoint3 &b, const SPoint3 &c)
  {
    return SPoint3((a.x() + b.x() + c.x()) / 3., (a.y() + b.y() + c.y()) / 3.,
                   (a.z() + b.z() + c.z()) / 3.);
  }

  double longestEdge(const SPoint3 &a, const SPoint3 &b, const SPoint3 &c)
  {
    return std::max(a.distance(b), std::max(b.distance(c), c.distance(a)));
  }

  class optimizer {
  public:
    optimizer(optimizableMesh &m, const surfaceMesh &input,
              const closestTriangleSearch &onInput,
              const meshOptimizationOptions &o, std::size_t &searches,
              std::size_t budget)
      : _m(m), _input(input), _onInput(onInput), _o(o),
        _around(m.points.size()), _searches(searches), _budget(budget)
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

    double kappa(int t) const
    {
      const std::array<int, 3> &c = _m.triangles[t];
      return triangleKappa(_m.points[c[0]], _m.points[c[1]], _m.points[c[2]]);
    }

    std::vector<int> trianglesBelowTarget() const
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

    // the first of t's edges tryFlip flips
    bool tryFlips(int t, bool forValence = false);
    // no valence flip makes a triangle worse than this (unless its pair
    // was): the target, or the mesh's worst when that is higher, so that the
    // flips never lower the worst kappa of a mesh
    double valenceFloor = 0.6;
    bool tryMove(int v);
    bool trySmooth(int v, double gain);
    bool spent() const { return _searches >= _budget; }
    void addNeighbours(int v, std::set<int> &to) const
    {
      to.insert(v);
      for(int t : _around[v])
        for(int w : _m.triangles[t]) to.insert(w);
    }

  private:
    optimizableMesh &_m;
    const surfaceMesh &_input;
    const closestTriangleSearch &_onInput;
    const meshOptimizationOptions _o;
    std::vector<std::vector<int> > _around; // triangles around each point
    // points whose surroundings changed since a move of them was refused
    std::vector<bool> _dirty;
    // searches of the input made and allowed: on CAD inputs with huge
    // triangles among tiny ones a search costs much more, and a face with
    // many triangles it cannot better must not hold the mesher
    std::size_t &_searches;
    const std::size_t _budget;
    void changedAround(int v)
    {
      for(int t : _around[v]) {
        _known[t] = false;
        for(int w : _m.triangles[t]) _dirty[w] = true;
      }
    }
    // the input's point closest to triangle t's centroid, kept until a
    // corner of t moves (a smoothing sweep asks for most of them twice)
    mutable std::vector<closestTriangleHit> _atCentroid;
    mutable std::vector<bool> _known;
    const closestTriangleHit &centroidHit(int t) const
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

    bool against(const SPoint3 &a, const SPoint3 &b, const SPoint3 &c) const
    {
      _searches += 4;
      return triangleAgainstInput(a, b, c, _input, _onInput) != _o.reversed;
    }
    double distanceToInput(const SPoint3 &p) const
    {
      _searches++;
      return _onInput.closest(p).distance;
    }
    // The triangle other than t on edge (a, b), -1 if none or several
    int neighbourAcross(int t, int a, int b) const;
    bool tryFlip(int t, int k, bool forValence = false);
    void replaceCorner(int t, int from, int to);
    int valenceOf(int v) const;
    int idealValenceOf(int v) const;
    // the valences and their ideals, kept from the first valence flip on
    // (the node moves between do not change them)
    mutable std::vector<int> _valence, _idealValence;
    double valenceCost(int v, int change) const
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
    std::pair<double, double> ringKappa(int v, const SPoint3 &at) const;
    SPoint3 worstTriangleApex(int v) const;
    SPoint3 maxMinPoint(int v) const;
    bool starKernelPoint(int v, SPoint3 &at) const;
    double ringFarthest(int v, const SPoint3 &at, double tolerance,
                        bool checkAgainst, bool &valid,
                        std::vector<closestTriangleHit> *hits = nullptr) const;
    SPoint3 ringCentroid(int v) const;
    SPoint3 ringApexMean(int v) const;
    struct ringQuality {
      double worst = 1., sum = 0.;
      int below = 0;
    };
    ringQuality ringAt(int v, const SPoint3 &at) const;
    static bool smoothedBetter(const ringQuality &before,
                               const ringQuality &after, double sumGain)
    {
      return after.worst >= before.worst && after.below <= before.below &&
             after.sum >= before.sum + sumGain;
    }
    std::vector<SPoint3> smoothingTargets(int v, const ringQuality &before,
                                          double sumGain) const;
    bool holdsInput(int v, const SPoint3 &to,
                    const std::vector<closestTriangleHit> &held) const;
    double ringLongestEdge(int v) const
    {
      double l = 0.;
      for(int t : _around[v]) {
        const std::array<int, 3> &c = _m.triangles[t];
        l = std::max(
          l, longestEdge(_m.points[c[0]], _m.points[c[1]], _m.points[c[2]]));
      }
      return l;
    }
    double distanceToRing(int v, const SPoint3 &at, const SPoint3 &p) const;
  };

  int optimizer::neighbourAcross(int t, int a, int b) const
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

  void optimizer::replaceCorner(int t, int from, int to)
  {
    for(int &v : _m.triangles[t])
      if(v == from) v = to;
    std::vector<int> &old = _around[from];
    old.erase(std::remove(old.begin(), old.end(), t), old.end());
    _around[to].push_back(t);
  }

  // How many points v shares an edge with
  int optimizer::valenceOf(int v) const
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
  int optimizer::idealValenceOf(int v) const
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
  bool optimizer::tryFlip(int t, int k, bool forValence)
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
    if(forValence && valenceCost(a, -1) + valenceCost(b, -1) +
                         valenceCost(p, 1) + valenceCost(q, 1) >=
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
    const double after = std::min(triangleKappa(x[a], x[q], x[p]),
                                  triangleKappa(x[q], x[b], x[p]));
    if(forValence) {
      // where a corner is fixed the node moves after cannot even out what
      // the flip made worse
      const bool free =
        _m.movable[a] && _m.movable[b] && _m.movable[p] && _m.movable[q];
      if(after < (free ? std::min(before, valenceFloor) : before))
        return false;
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

  bool optimizer::tryFlips(int t, bool forValence)
  {
    for(int k = 0; k < 3; k++)
      if(tryFlip(t, k, forValence)) return true;
    return false;
  }

  // The corners of triangle t with v at `at`
  void cornersWith(const std::array<int, 3> &t, int v, const SPoint3 &at,
                   const std::vector<SPoint3> &points, SPoint3 c[3])
  {
    for(int k = 0; k < 3; k++) c[k] = t[k] == v ? at : points[t[k]];
  }

  // The worst and the mean kappa of the triangles around v with v at `at`
  std::pair<double, double> optimizer::ringKappa(int v, const SPoint3 &at) const
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

  // Where v makes the worst triangle around it equilateral: over the
  // middle of the opposite edge, across it from nothing, in the plane of
  // the ring (the mean of its triangles' normals, as oriented)
  SPoint3 optimizer::worstTriangleApex(int v) const
  {
    const std::vector<SPoint3> &x = _m.points;
    SVector3 normal(0., 0., 0.);
    int worst = -1;
    double worstKappa = 2.;
    for(int t : _around[v]) {
      const std::array<int, 3> &c = _m.triangles[t];
      normal +=
        crossprod(SVector3(x[c[0]], x[c[1]]), SVector3(x[c[0]], x[c[2]]));
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
  // ring (Mesh/optimize/maxMinPlacement.h), from steps of a quarter of its mean edge
  SPoint3 optimizer::maxMinPoint(int v) const
  {
    const std::vector<SPoint3> &x = _m.points;
    SVector3 normal(0., 0., 0.);
    std::vector<std::array<SPoint3, 2> > opposite;
    double edges = 0.;
    for(int t : _around[v]) {
      const std::array<int, 3> &c = _m.triangles[t];
      normal +=
        crossprod(SVector3(x[c[0]], x[c[1]]), SVector3(x[c[0]], x[c[2]]));
      int k = 0;
      while(c[k] != v) k++;
      opposite.push_back({{x[c[(k + 1) % 3]], x[c[(k + 2) % 3]]}});
      edges += x[v].distance(x[c[(k + 1) % 3]]);
    }
    if(opposite.empty()) return x[v];
    return maxMinKappaPoint(x[v], opposite, normal,
                            0.25 * edges / opposite.size());
  }

  // The centroid of the kernel of v's ring projected on the plane of the
  // input under v (the region from which every opposite edge is seen on the
  // side the input's orientation asks), lifted back to 3D; false if empty
  bool optimizer::starKernelPoint(int v, SPoint3 &at) const
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

  // The largest distance of the centroids of the triangles around v (v at
  // `at`) to the input, less `tolerance` times their longest edge; `valid`:
  // none of them points against the input (tested only if `checkAgainst`)
  double optimizer::ringFarthest(int v, const SPoint3 &at, double tolerance,
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
      farthest = std::max(
        farthest, hit.distance - tolerance * longestEdge(c[0], c[1], c[2]));
    }
    return farthest;
  }

  // The mean over the triangles around v of the point that makes each
  // equilateral (over the middle of the edge opposite v, on v's side, in the
  // plane of the ring)
  SPoint3 optimizer::ringApexMean(int v) const
  {
    const std::vector<SPoint3> &x = _m.points;
    SVector3 normal(0., 0., 0.);
    for(int t : _around[v]) {
      const std::array<int, 3> &c = _m.triangles[t];
      normal +=
        crossprod(SVector3(x[c[0]], x[c[1]]), SVector3(x[c[0]], x[c[2]]));
    }
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

  // The distance of p to the triangles around v with v at `at`
  double optimizer::distanceToRing(int v, const SPoint3 &at,
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
  SPoint3 optimizer::ringCentroid(int v) const
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

  // The worst, the sum and the count below the target of the kappas of the
  // triangles around v with v at `at`
  optimizer::ringQuality optimizer::ringAt(int v, const SPoint3 &at) const
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

  // Where smoothing may move v, best first: the neighbours' centroid (which
  // evens the edges), the mean of the points that make each triangle around
  // equilateral (which evens the angles), and halfway to each, those where
  // the ring's kappa sum rises by sumGain, its worst does not fall and none
  // falls below the target
  std::vector<SPoint3> optimizer::smoothingTargets(int v,
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
  bool optimizer::holdsInput(int v, const SPoint3 &to,
                             const std::vector<closestTriangleHit> &held) const
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
  bool optimizer::trySmooth(int v, double gain)
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

  // v moved to its neighbours' centroid or halfway there, on the input, if
  // the triangles around it get better (the searches on the input only for
  // positions that would be better)
  bool optimizer::tryMove(int v)
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
    if(before.first < 0. && starKernelPoint(v, kernel))
      targets.push_back(kernel);
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

} // namespace

std::vector<int> removeDeadParts(optimizableMesh &m,
                                 const std::vector<bool> &deadPoint,
                                 const std::vector<bool> &deadTriangle)
{
  std::vector<int> newIndex(m.points.size(), -1);
  std::size_t n = 0;
  for(std::size_t i = 0; i < m.points.size(); i++) {
    if(deadPoint[i]) continue;
    newIndex[i] = (int)n;
    m.points[n] = m.points[i];
    m.movable[n] = m.movable[i];
    m.landing[n] = m.landing[i];
    m.inputNode[n] = m.inputNode[i];
    m.size[n] = m.size[i];
    m.origin[n] = m.origin[i];
    n++;
  }
  for(auto *v : {&m.landing, &m.inputNode, &m.origin}) v->resize(n);
  m.points.resize(n);
  m.movable.resize(n);
  m.size.resize(n);
  std::set<std::pair<int, int> > locked;
  for(const auto &e : m.lockedEdges)
    if(newIndex[e.first] >= 0 && newIndex[e.second] >= 0)
      locked.insert(std::make_pair(newIndex[e.first], newIndex[e.second]));
  m.lockedEdges = locked;
  std::size_t k = 0;
  const bool against = m.against.size() == m.triangles.size();
  for(std::size_t t = 0; t < m.triangles.size(); t++) {
    if(deadTriangle[t]) continue;
    for(int &v : m.triangles[t]) v = newIndex[v];
    m.triangles[k] = m.triangles[t];
    m.triangleOrigin[k] = m.triangleOrigin[t];
    if(against) m.against[k] = m.against[t];
    k++;
  }
  m.triangles.resize(k);
  m.triangleOrigin.resize(k);
  if(against) m.against.resize(k);
  return newIndex;
}

double worstKappa(const optimizableMesh &m)
{
  double worst = 1.;
  for(const std::array<int, 3> &t : m.triangles)
    worst = std::min(
      worst, triangleKappa(m.points[t[0]], m.points[t[1]], m.points[t[2]]));
  return worst;
}

namespace {

  // Flips and moves around the triangles below the target or against the
  // input, pass after pass
  void improvePoorTriangles(optimizableMesh &m, const surfaceMesh &input,
                            const closestTriangleSearch &onInput,
                            const meshOptimizationOptions &o,
                            meshOptimizationResult &r,
                            const std::vector<int> &smooth)
  {
    optimizer opt(m, input, onInput, o, r.searches,
                  o.searchesPerTriangle * m.triangles.size() + 1000);
    // first the nodes around the edges collapsed: their triangles are valid
    // but uneven
    std::set<int> around;
    for(int v : smooth) opt.addNeighbours(v, around);
    for(int v : around) r.moves += opt.tryMove(v);
    std::vector<int> below = opt.trianglesBelowTarget();
    for(int pass = 0; !below.empty() && pass < o.maxPasses; pass++) {
      r.passes++;
      std::size_t changes = 0;
      for(int t : below)
        if((m.against[t] || opt.kappa(t) < o.target) && opt.tryFlips(t))
          changes++;
      r.flips += changes;
      std::set<int> corners;
      for(int t : opt.trianglesBelowTarget())
        for(int v : m.triangles[t]) corners.insert(v);
      for(int v : corners)
        if(opt.tryMove(v)) {
          r.moves++;
          changes++;
        }
      below = opt.trianglesBelowTarget();
      if(!changes || opt.spent()) break;
    }
  }

  // Sweeps of trySmooth over every movable node, until one moves none
  void smoothMesh(optimizableMesh &m, const surfaceMesh &input,
                  const closestTriangleSearch &onInput,
                  const meshOptimizationOptions &o, meshOptimizationResult &r)
  {
    std::size_t searches = 0;
    optimizer opt(m, input, onInput, o, searches,
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

  // Triangles of m below the target, and pointing against the input
  void countPoorTriangles(const optimizableMesh &m,
                          const meshOptimizationOptions &o, std::size_t &below,
                          std::size_t &against)
  {
    below = against = 0;
    for(std::size_t t = 0; t < m.triangles.size(); t++) {
      const std::array<int, 3> &c = m.triangles[t];
      below += triangleKappa(m.points[c[0]], m.points[c[1]], m.points[c[2]]) <
               o.target;
      against += m.against[t];
    }
  }

} // namespace

meshOptimizationResult optimizeOnInput(optimizableMesh &m,
                                       const surfaceMesh &input,
                                       const closestTriangleSearch &onInput,
                                       const meshOptimizationOptions &o)
{
  meshOptimizationResult r;
  m.landing.resize(m.points.size(), -1);
  m.inputNode.resize(m.points.size(), -1);
  m.movable.resize(m.points.size(), false);
  if(m.origin.size() != m.points.size()) {
    m.origin.resize(m.points.size());
    for(std::size_t i = 0; i < m.points.size(); i++) m.origin[i] = (int)i;
  }
  if(m.triangleOrigin.size() != m.triangles.size()) {
    m.triangleOrigin.resize(m.triangles.size());
    for(std::size_t t = 0; t < m.triangles.size(); t++)
      m.triangleOrigin[t] = (int)t;
  }
  m.against.resize(m.triangles.size());
  for(std::size_t t = 0; t < m.triangles.size(); t++) {
    if(t < o.knownAlong.size() && o.knownAlong[t]) continue;
    const std::array<int, 3> &c = m.triangles[t];
    m.against[t] =
      triangleAgainstInput(m.points[c[0]], m.points[c[1]], m.points[c[2]],
                           input, onInput) != o.reversed;
  }
  r.minBefore = worstKappa(m);
  countPoorTriangles(m, o, r.belowBefore, r.againstBefore);
  for(int round = 0; round < std::max(1, o.maxInsertionRounds); round++) {
    std::size_t snapped = 0;
    const std::size_t inserted =
      o.insertAbove > 0. ? insertFarInputNodes(m, input, onInput, o.reversed,
                                               o.insertAbove, &snapped) :
                           0;
    const std::size_t splits =
      splitLongEdges(m, input, onInput, o.reversed, o.splitAbove);
    std::vector<int> collapsedInto;
    const std::size_t collapses =
      o.collapseBelow > 0. ?
        collapseShortEdges(m, input, onInput, o.reversed, o.collapseBelow,
                           4. * o.tolerance, &collapsedInto) :
        0;
    r.inserted += inserted;
    r.snapped += snapped;
    r.splits += splits;
    r.collapses += collapses;
    improvePoorTriangles(m, input, onInput, o, r, collapsedInto);
    if(!inserted && !splits && !collapses) break;
  }
  countPoorTriangles(m, o, r.belowAfter, r.againstAfter);
  if(r.againstAfter) {
    // tangles no flip nor single move undid: their cavities re-meshed
    std::vector<int> centers;
    r.cavities = remeshTangledCavities(m, input, onInput, o.reversed, &centers);
    if(r.cavities) {
      improvePoorTriangles(m, input, onInput, o, r, centers);
      countPoorTriangles(m, o, r.belowAfter, r.againstAfter);
    }
  }
  if(o.smoothPasses > 0) {
    smoothMesh(m, input, onInput, o, r);
    // the moves smoothing made free others around the worst triangles
    improvePoorTriangles(m, input, onInput, o, r, {});
    countPoorTriangles(m, o, r.belowAfter, r.againstAfter);
  }
  r.minAfter = worstKappa(m);
  return r;
}
} // namespace reparam

