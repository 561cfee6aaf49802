// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <array>
#include "SVector3.h"
#include "closestTriangle.h"
#include "curveNodeSlide.h"
#include "quadNodeSmoothing.h"
#include "quadQuality.h"
#include "surfaceMesh.h"
#include "triangleQuality.h"

namespace reparam {

namespace {

  // m's triangles and quadrangles as one list (corners[3] = -1: a triangle)
  struct elementList {
    std::vector<std::array<int, 4> > corners;
    std::vector<std::vector<int> > around; // per point, its elements

    explicit elementList(const surfaceMesh &m) : around(m.points.size())
    {
      for(const std::array<int, 3> &t : m.triangles)
        corners.push_back({{t[0], t[1], t[2], -1}});
      for(const std::array<int, 4> &q : m.quadrangles) corners.push_back(q);
      for(std::size_t e = 0; e < corners.size(); e++)
        for(int v : corners[e])
          if(v >= 0) around[v].push_back((int)e);
    }
  };

  double qualityOf(const std::array<int, 4> &c, const std::vector<SPoint3> &p)
  {
    if(c[3] < 0) return triangleKappa(p[c[0]], p[c[1]], p[c[2]]);
    return quadEta(p[c[0]], p[c[1]], p[c[2]], p[c[3]]);
  }

  SVector3 normalOf(const std::array<int, 4> &c, const std::vector<SPoint3> &p)
  {
    if(c[3] < 0)
      return crossprod(SVector3(p[c[0]], p[c[1]]), SVector3(p[c[0]], p[c[2]]));
    return crossprod(SVector3(p[c[0]], p[c[2]]), SVector3(p[c[1]], p[c[3]]));
  }

  // How far the corners of an element are from the right angle (the
  // equilateral triangle's 60 degrees), squared and summed: a smooth
  // measure to lower, where eta, by the worst corner only, has flat
  // stretches and kinks (a row of zig-zag nodes moved one by one on the sum
  // of eta flips to the mirror zig-zag)
  double cornerDeviation(const std::array<int, 4> &c,
                         const std::vector<SPoint3> &p)
  {
    const int n = c[3] < 0 ? 3 : 4;
    const double ideal = n == 3 ? M_PI / 3. : M_PI / 2.;
    double sum = 0.;
    for(int k = 0; k < n; k++) {
      const SVector3 next(p[c[k]], p[c[(k + 1) % n]]);
      const SVector3 previous(p[c[k]], p[c[(k + n - 1) % n]]);
      const double alpha =
        std::atan2(crossprod(next, previous).norm(), dot(next, previous));
      sum += (alpha - ideal) * (alpha - ideal);
    }
    return sum;
  }

  // The element's edges' squared log-ratio to the size asked at their
  // ends, summed and weighted (0 without sizes)
  double offSize(const std::array<int, 4> &c, const std::vector<SPoint3> &p,
                 const quadSmoothingOptions &o)
  {
    if(o.size.size() != p.size() || !(o.lengthWeight > 0.)) return 0.;
    const int n = c[3] < 0 ? 3 : 4;
    double sum = 0.;
    for(int k = 0; k < n; k++) {
      const int a = c[k], b = c[(k + 1) % n];
      const double h = 0.5 * (o.size[a] + o.size[b]);
      if(!(h > 0.)) continue;
      const double r = std::log(p[a].distance(p[b]) / h);
      sum += r * r;
    }
    return o.lengthWeight * sum;
  }

  double distanceToElement(const SPoint3 &x, const std::array<int, 4> &c,
                           const std::vector<SPoint3> &p)
  {
    double d = x.distance(closestPointOnTriangle(x, p[c[0]], p[c[1]], p[c[2]]));
    if(c[3] >= 0)
      d = std::min(
        d, x.distance(closestPointOnTriangle(x, p[c[0]], p[c[2]], p[c[3]])));
    return d;
  }

  double longestEdge(const std::array<int, 4> &c, const std::vector<SPoint3> &p)
  {
    const int n = c[3] < 0 ? 3 : 4;
    double l = 0.;
    for(int k = 0; k < n; k++)
      l = std::max(l, p[c[k]].distance(p[c[(k + 1) % n]]));
    return l;
  }

  // eta's and kappa's minimum apart: a quadrangle may not fall to a
  // triangle's kappa
  struct ringScore {
    double sum = 0., min = 1., kappaMin = 1.;
  };

  // One node's compass search on the input
  class nodeMover {
  public:
    nodeMover(surfaceMesh &m, const elementList &list,
              const closestTriangleSearch &onInput,
              const quadSmoothingOptions &o)
      : _m(m), _list(list), _onInput(onInput), _o(o)
    {
    }

    std::size_t searches() const { return _searches; }
    // what a move raises: eta summed over the ring, or (false) minus the
    // corners' deviation from the right angle
    void raiseEta(bool byEta) { _byEta = byEta; }

    // Moves point v where its ring is best; the input triangle it landed on
    // (-1: not moved)
    int move(int v, int hint)
    {
      if(_list.around[v].empty()) return -1;
      startRing(v);
      SVector3 e1, e2;
      double edge;
      if(!tangentFrame(v, e1, e2, edge)) return -1;
      const ringScore start = score(v, _origin);
      ringScore best = start;
      SPoint3 at = _origin;
      int landing = -1;
      const SVector3 steps[4] = {e1, e1 * -1., e2, e2 * -1.};
      for(double step = _o.firstStep * edge; step >= _o.lastStep * edge;) {
        bool improved = false;
        for(const SVector3 &d : steps) {
          const SPoint3 trial(at.x() + step * d.x(), at.y() + step * d.y(),
                              at.z() + step * d.z());
          const closestTriangleHit hit = _onInput.closest(trial, hint);
          _searches++;
          if(hit.triangle < 0) continue;
          const ringScore s = score(v, hit.point);
          if(!better(s, start, best)) continue;
          best = s;
          at = hit.point;
          landing = hint = hit.triangle;
          improved = true;
          break;
        }
        if(!improved) step /= 2.;
      }
      if(landing < 0 || best.sum < start.sum + _o.gain) {
        _m.points[v] = _origin;
        return -1;
      }
      _m.points[v] = at;
      return landing;
    }

    // Slides point v along its polyline where its ring is best; whether it
    // moved (s.t updated)
    bool slide(int v, std::vector<polylineSlide> &slides)
    {
      polylineSlide &s = slides[v];
      if(s.previous >= 0) s.before = slides[s.previous].t;
      if(s.next >= 0) s.after = slides[s.next].t;
      if(_list.around[v].empty() || !(s.after > s.before)) return false;
      startRing(v);
      const ringScore start = score(v, _origin);
      ringScore best = start;
      double at = s.t;
      // not nearer to a neighbour than a tenth of the way
      const double span = s.after - s.before, margin = 0.1 * span;
      for(double step = _o.firstStep * span; step >= _o.lastStep * span;) {
        bool improved = false;
        for(double sign : {1., -1.}) {
          const double t = at + sign * step;
          if(t < s.before + margin || t > s.after - margin ||
             !chordsFollowPolyline(*s.polyline, s.t, t, s.before, s.after,
                                   0.05))
            continue;
          const ringScore r = score(v, pointOnPolyline(*s.polyline, t));
          if(!better(r, start, best)) continue;
          best = r;
          at = t;
          improved = true;
          break;
        }
        if(!improved) step /= 2.;
      }
      if(at == s.t || best.sum < start.sum + _o.gain) {
        _m.points[v] = _origin;
        return false;
      }
      _m.points[v] = pointOnPolyline(*s.polyline, at);
      s.t = at;
      return true;
    }

  private:
    // v's old place and its elements' normals, which moves are measured
    // against
    void startRing(int v)
    {
      _origin = _m.points[v];
      _normals.clear();
      for(int e : _list.around[v])
        _normals.push_back(normalOf(_list.corners[e], _m.points));
    }

    // The plane of v's ring (its elements' mean normal) and its mean edge
    bool tangentFrame(int v, SVector3 &e1, SVector3 &e2, double &edge) const
    {
      SVector3 mean(0., 0., 0.);
      for(const SVector3 &n : _normals) mean += n.unit();
      edge = 0.;
      int edges = 0;
      for(int e : _list.around[v])
        for(int u : _list.corners[e])
          if(u >= 0 && u != v) {
            edge += _origin.distance(_m.points[u]);
            edges++;
          }
      if(mean.norm() == 0. || !edges) return false;
      mean.normalize();
      e1 = crossprod(mean, SVector3(1., 0., 0.));
      if(e1.norm() < 0.5) e1 = crossprod(mean, SVector3(0., 1., 0.));
      e1.normalize();
      e2 = crossprod(mean, e1);
      edge /= edges;
      return true;
    }

    // s beats the best so far, and no element falls below the ring's worst
    // at the start (quadrangles and triangles apart)
    static bool better(const ringScore &s, const ringScore &start,
                       const ringScore &best)
    {
      return s.min >= start.min - 1e-12 &&
             s.kappaMin >= start.kappaMin - 1e-12 && s.sum > best.sum + 1e-9;
    }

    // The ring's quality with v at x; min -1 where an element turns over
    // or the ring leaves v's old place behind
    ringScore score(int v, const SPoint3 &x)
    {
      _m.points[v] = x;
      ringScore s;
      const std::vector<int> &ring = _list.around[v];
      const double cosTurn = std::cos(_o.maxTurn);
      double away = 1e300, longest = 0.;
      for(std::size_t k = 0; k < ring.size(); k++) {
        const std::array<int, 4> &c = _list.corners[ring[k]];
        const SVector3 n = normalOf(c, _m.points);
        const double q = qualityOf(c, _m.points);
        if(dot(n, _normals[k]) <= cosTurn * n.norm() * _normals[k].norm()) {
          s.min = -1.;
          return s;
        }
        s.sum += _byEta ?
                   q :
                   -cornerDeviation(c, _m.points) - offSize(c, _m.points, _o);
        if(c[3] < 0)
          s.kappaMin = std::min(s.kappaMin, q);
        else
          s.min = std::min(s.min, q);
        away = std::min(away, distanceToElement(_origin, c, _m.points));
        longest = std::max(longest, longestEdge(c, _m.points));
      }
      if(away > _o.tolerance * longest) s.min = -1.;
      return s;
    }

    surfaceMesh &_m;
    const elementList &_list;
    const closestTriangleSearch &_onInput;
    const quadSmoothingOptions &_o;
    SPoint3 _origin;
    std::vector<SVector3> _normals;
    std::size_t _searches = 0;
    bool _byEta = false;
  };

  // The active points, those with the worst element around first: where
  // the nodes of a cut zig-zag, their neighbours would otherwise follow the
  // zig-zag first (in the order of the points), and a move straightening it
  // then lowers their elements
  std::vector<int> worstFirst(const surfaceMesh &m, const elementList &list,
                              const std::vector<bool> &active)
  {
    std::vector<std::pair<double, int> > order;
    for(std::size_t v = 0; v < active.size(); v++) {
      if(!active[v]) continue;
      double worst = 1.;
      for(int e : list.around[v])
        worst = std::min(worst, qualityOf(list.corners[e], m.points));
      order.push_back(std::make_pair(worst, (int)v));
    }
    std::sort(order.begin(), order.end());
    std::vector<int> points;
    for(const auto &o : order) points.push_back(o.second);
    return points;
  }

} // namespace

std::vector<double> meanQuadEdgeAtPoints(const surfaceMesh &m)
{
  std::vector<double> sum(m.points.size(), 0.);
  std::vector<int> count(m.points.size(), 0);
  for(const std::array<int, 4> &q : m.quadrangles)
    for(int k = 0; k < 4; k++) {
      const int a = q[k], b = q[(k + 1) % 4];
      const double l = m.points[a].distance(m.points[b]);
      sum[a] += l;
      sum[b] += l;
      count[a]++;
      count[b]++;
    }
  for(std::size_t i = 0; i < sum.size(); i++)
    if(count[i]) sum[i] /= count[i];
  return sum;
}

quadSmoothingResult smoothQuadsOnInput(surfaceMesh &m,
                                       const std::vector<bool> &movable,
                                       const closestTriangleSearch &onInput,
                                       std::vector<int> &landing,
                                       const quadSmoothingOptions &o,
                                       std::vector<polylineSlide> *slides)
{
  if(slides && slides->size() != m.points.size()) slides = nullptr;
  auto canMove = [&](int v) {
    return ((std::size_t)v < movable.size() && movable[v]) ||
           (slides && (*slides)[v].polyline);
  };
  quadSmoothingResult r;
  etaOfQuadrangles(m, r.etaMinBefore, r.etaMeanBefore);
  landing.assign(m.points.size(), -1);
  const elementList list(m);
  nodeMover mover(m, list, onInput, o);
  std::vector<bool> active(m.points.size(), false);
  for(std::size_t v = 0; v < m.points.size(); v++) active[v] = canMove((int)v);
  for(; r.sweeps < o.sweeps; r.sweeps++) {
    std::vector<bool> next(m.points.size(), false);
    std::size_t moved = 0;
    mover.raiseEta(r.sweeps >= o.sweeps / 2);
    for(int v : worstFirst(m, list, active)) {
      if(slides && (*slides)[v].polyline) {
        if(!mover.slide(v, *slides)) continue;
        r.slides++;
      }
      else {
        const int hit = mover.move(v, landing[v]);
        if(hit < 0) continue;
        landing[v] = hit;
      }
      moved++;
      for(int e : list.around[v])
        for(int u : list.corners[e])
          if(u >= 0 && canMove(u)) next[u] = true;
    }
    r.moves += moved;
    active.swap(next);
    if(!moved) break;
  }
  r.searches = mover.searches();
  etaOfQuadrangles(m, r.etaMinAfter, r.etaMeanAfter);
  return r;
}
} // namespace reparam

