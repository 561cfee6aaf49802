// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include "SVector3.h"
#include "closestTriangle.h"
#include "curveNodeSlide.h"
#include "triangleQuality.h"

namespace reparam {

namespace {

  // below this, the worst triangle of a ring is worth any loss to the others
  // (bench/README.md, Curve nodes slid along their curves)
  const double sliver = 0.3;

  SVector3 normalOf(const SPoint3 &x, const SPoint3 &a, const SPoint3 &b)
  {
    return crossprod(SVector3(x, a), SVector3(x, b));
  }

  // The worst kappa of the ring with the node at x (and its mean); -1 if a
  // triangle's normal turns by more than maxTurn from where the node was
  double worstAt(const curveNodeRing &ring, const SPoint3 &x,
                 const SPoint3 &was, double maxTurn, double &mean)
  {
    double worst = 1.;
    mean = 0.;
    const double cosMax = std::cos(maxTurn);
    for(const auto &o : ring.opposite) {
      const SVector3 n0 = normalOf(was, o[0], o[1]);
      const SVector3 n1 = normalOf(x, o[0], o[1]);
      const double l = n0.norm() * n1.norm();
      if(!(l > 0.) || dot(n0, n1) < cosMax * l) return -1.;
      const double k = triangleKappa(x, o[0], o[1]);
      worst = std::min(worst, k);
      mean += k;
    }
    if(!ring.opposite.empty()) mean /= ring.opposite.size();
    return worst;
  }

  // The farthest the polyline's nodes strictly between parameters t0 and t1
  // lie from the chord between their points
  double sagBetween(const std::vector<SPoint3> &polyline, double t0, double t1)
  {
    if(t1 < t0) std::swap(t0, t1);
    const SPoint3 a = pointOnPolyline(polyline, t0);
    const SPoint3 b = pointOnPolyline(polyline, t1);
    double farthest = 0.;
    for(int i = (int)std::floor(t0) + 1; i < t1 && i < (int)polyline.size();
        i++) {
      if(i <= t0) continue;
      farthest = std::max(farthest, polyline[i].distance(closestPointOnSegment(
                                      polyline[i], a, b)));
    }
    return farthest;
  }

  bool followsTheCurve(const curveNodeRing &ring, double t, double sag)
  {
    return chordsFollowPolyline(ring.polyline, ring.t, t, ring.before,
                                ring.after, sag);
  }

} // namespace

bool chordsFollowPolyline(const std::vector<SPoint3> &polyline, double was,
                          double t, double before, double after, double sag)
{
  for(double end : {before, after}) {
    const double length =
      pointOnPolyline(polyline, t).distance(pointOnPolyline(polyline, end));
    const double now = sagBetween(polyline, t, end);
    if(now > sag * length && now > sagBetween(polyline, was, end) * (1. + 1e-9))
      return false;
  }
  return true;
}

SPoint3 pointOnPolyline(const std::vector<SPoint3> &polyline, double t)
{
  if(polyline.empty()) return SPoint3();
  if(polyline.size() == 1) return polyline[0];
  const int last = (int)polyline.size() - 1;
  const int i = std::min(std::max((int)std::floor(t), 0), last - 1);
  const double s = std::min(std::max(t - i, 0.), 1.);
  return polyline[i] + (polyline[i + 1] - polyline[i]) * s;
}

namespace {

  // Parameters to try strictly between the neighbours': an eighth of the
  // way steps, and the polyline's nodes
  std::vector<double> candidatesOf(const curveNodeRing &ring)
  {
    std::vector<double> candidates;
    for(int k = 1; k < 8; k++)
      candidates.push_back(ring.before + (ring.after - ring.before) * k / 8.);
    for(int i = (int)std::floor(ring.before) + 1; i < ring.after; i++)
      if(i > ring.before) candidates.push_back(i);
    return candidates;
  }

} // namespace

curveNodeSlide slideCurveNodeForMean(const curveNodeRing &ring, double target,
                                     double gain, double maxTurn, double sag)
{
  curveNodeSlide best;
  best.t = ring.t;
  const SPoint3 was = pointOnPolyline(ring.polyline, ring.t);
  double meanBefore = 0.;
  best.worstBefore = best.worstAfter =
    worstAt(ring, was, was, M_PI, meanBefore);
  if(ring.opposite.empty() || !(ring.before < ring.after)) return best;
  std::vector<double> before;
  for(const auto &o : ring.opposite)
    before.push_back(triangleKappa(was, o[0], o[1]));
  double bestMean = meanBefore + gain;
  for(double t : candidatesOf(ring)) {
    if(t == ring.t) continue;
    const SPoint3 x = pointOnPolyline(ring.polyline, t);
    double mean = 0.;
    const double worst = worstAt(ring, x, was, maxTurn, mean);
    if(worst < best.worstBefore || mean < bestMean ||
       !followsTheCurve(ring, t, sag))
      continue;
    // a triangle below the target left no worse: the slides for the worst
    // triangles had their turn, and the mean must not undo them
    bool keepsPoor = true;
    for(std::size_t i = 0; i < before.size() && keepsPoor; i++) {
      const double k = triangleKappa(x, ring.opposite[i][0],
                                     ring.opposite[i][1]);
      keepsPoor = k >= target || k >= before[i];
    }
    if(!keepsPoor) continue;
    bestMean = mean;
    best.t = t;
    best.worstAfter = worst;
  }
  return best;
}

namespace {

  // The polyline's node strictly between parameters `before` and `after`
  // (other than t) farthest from the chords of a node at t to them, its
  // distance in `farthest` and the length of its chord in `chord`; -1 if
  // none
  int farthestFromChords(const std::vector<SPoint3> &polyline, double t,
                         double before, double after, double &farthest,
                         double &chord)
  {
    const SPoint3 a = pointOnPolyline(polyline, before);
    const SPoint3 x = pointOnPolyline(polyline, t);
    const SPoint3 b = pointOnPolyline(polyline, after);
    int found = -1;
    farthest = 0.;
    for(int i = (int)std::floor(before) + 1;
        i < after && i < (int)polyline.size(); i++) {
      if(i <= before || i == t) continue;
      const bool first = i < t;
      const SPoint3 &p = polyline[i];
      const double d =
        p.distance(closestPointOnSegment(p, first ? a : x, first ? x : b));
      if(d > farthest) {
        farthest = d;
        found = i;
        chord = first ? a.distance(x) : x.distance(b);
      }
    }
    return found;
  }

} // namespace

curveNodeSlide slideCurveNodeToFarthest(const curveNodeRing &ring,
                                        double share, double floor,
                                        double maxTurn)
{
  curveNodeSlide best;
  best.t = ring.t;
  const SPoint3 was = pointOnPolyline(ring.polyline, ring.t);
  double mean = 0.;
  best.worstBefore = best.worstAfter = worstAt(ring, was, was, M_PI, mean);
  if(ring.opposite.empty() || !(ring.before < ring.after)) return best;
  double farthest, chord = 0.;
  const int i = farthestFromChords(ring.polyline, ring.t, ring.before,
                                   ring.after, farthest, chord);
  if(i < 0 || !(farthest > share * chord)) return best;
  double after, chordAfter;
  farthestFromChords(ring.polyline, i, ring.before, ring.after, after,
                     chordAfter);
  if(!(after < farthest)) return best;
  const double worst = worstAt(ring, ring.polyline[i], was, maxTurn, mean);
  if(worst < std::min(best.worstBefore, floor)) return best;
  best.t = i;
  best.worstAfter = worst;
  return best;
}

curveNodeSlide slideCurveNode(const curveNodeRing &ring, double gain,
                              double maxTurn, double sag)
{
  curveNodeSlide best;
  best.t = ring.t;
  const SPoint3 was = pointOnPolyline(ring.polyline, ring.t);
  double meanBefore = 0., mean = 0.;
  best.worstBefore = best.worstAfter =
    worstAt(ring, was, was, M_PI, meanBefore);
  if(ring.opposite.empty() || !(ring.before < ring.after)) return best;
  double bestWorst = best.worstBefore + gain;
  for(double t : candidatesOf(ring)) {
    if(t == ring.t) continue;
    const double worst =
      worstAt(ring, pointOnPolyline(ring.polyline, t), was, maxTurn, mean);
    // the ring's kappa summed may fall by no more than the worst gains,
    // unless that is a sliver
    const double loss = (meanBefore - mean) * ring.opposite.size();
    if(worst < bestWorst ||
       (best.worstBefore >= sliver && loss > worst - best.worstBefore) ||
       !followsTheCurve(ring, t, sag))
      continue;
    bestWorst = worst;
    best.t = t;
    best.worstAfter = worst;
  }
  return best;
}
} // namespace reparam

