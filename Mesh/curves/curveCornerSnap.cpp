// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include "curveCornerSnap.h"
#include "curveNodeSlide.h"
#include "SVector3.h"

namespace reparam {

namespace {

  // Arc length along the polyline at its nodes, and the parameter at a
  // given arc length
  struct arcLength {
    std::vector<double> at;
    explicit arcLength(const std::vector<SPoint3> &polyline)
      : at(polyline.size(), 0.)
    {
      for(std::size_t i = 1; i < polyline.size(); i++)
        at[i] = at[i - 1] + polyline[i - 1].distance(polyline[i]);
    }
    double of(double t) const
    {
      const int last = (int)at.size() - 1;
      int i = std::min(std::max((int)std::floor(t), 0), last - 1);
      return at[i] + (at[i + 1] - at[i]) * (t - i);
    }
    double parameter(double length) const
    {
      auto it = std::upper_bound(at.begin(), at.end(), length);
      int i =
        std::min(std::max((int)(it - at.begin()) - 1, 0), (int)at.size() - 2);
      const double l = at[i + 1] - at[i];
      return i +
             (l > 0. ? std::min(std::max((length - at[i]) / l, 0.), 1.) : 0.);
    }
  };

  // The angle the polyline turns by at its node i, seen at the scale w:
  // between the chords from w before it and to w after it (in arc length).
  // Input edges along a curve zig-zag (a crease of a scan, a cut between
  // patches): seen node by node they turn by 30 degrees or more all along,
  // seen at the mesh's scale they do not.
  double turningAngle(const std::vector<SPoint3> &polyline,
                      const arcLength &arc, int i, double w)
  {
    const SPoint3 before =
      pointOnPolyline(polyline, arc.parameter(arc.at[i] - w));
    const SPoint3 after =
      pointOnPolyline(polyline, arc.parameter(arc.at[i] + w));
    SVector3 in(before, polyline[i]), out(polyline[i], after);
    const double l = in.norm() * out.norm();
    if(l <= 0.) return 0.;
    return std::acos(std::min(1., std::max(-1., dot(in, out) / l)));
  }

  // The input nodes strictly between parameters t0 and t1 where the
  // polyline turns at the scale of half the segment by cornerAngle or more,
  // with their turns (negated)
  void cornersWithin(const std::vector<SPoint3> &polyline, const arcLength &arc,
                     double t0, double t1,
                     std::vector<std::pair<double, int> > &corners)
  {
    // Below this a turn is the polyline following a smooth curve: moving
    // nodes onto it would only make the segments uneven (a hole's polygon
    // of 12 sides turns by 30 degrees per node: bench/README.md#curve-corners).
    // 40 degrees: the feature angle of the STL recipe.
    const double cornerAngle = 40. * M_PI / 180.;
    const double w = 0.5 * (arc.of(t1) - arc.of(t0));
    for(int i = std::max(1, (int)std::floor(t0) + 1);
        i < t1 && i + 1 < (int)polyline.size(); i++) {
      if(i <= t0) continue;
      const double a = turningAngle(polyline, arc, i, w);
      if(a >= cornerAngle) corners.push_back({-a, i});
    }
  }

  // The corners the nodes go to: the sharpest of each segment (every one
  // with everyCorner), sharpest first; one closer than half a segment to
  // the curve's ends or to a sharper corner is left out (a node already
  // sits about there)
  std::vector<int> chooseCorners(const std::vector<SPoint3> &polyline,
                                 const arcLength &arc,
                                 const std::vector<double> &params,
                                 const std::function<bool(int)> &allowed,
                                 bool everyCorner)
  {
    std::vector<std::pair<double, int> > candidates; // (-turn, node)
    for(std::size_t s = 0; s + 1 < params.size(); s++) {
      std::vector<std::pair<double, int> > corners;
      cornersWithin(polyline, arc, params[s], params[s + 1], corners);
      if(!everyCorner && corners.size() > 1) {
        // the sharpest, the last of equal ones
        std::pair<double, int> sharpest = corners.front();
        for(const auto &c : corners)
          if(c.first <= sharpest.first) sharpest = c;
        corners = {sharpest};
      }
      for(const auto &c : corners)
        if(!allowed || allowed(c.second)) candidates.push_back(c);
    }
    std::sort(candidates.begin(), candidates.end());
    const double segment =
      (arc.of(params.back()) - arc.of(params.front())) / (params.size() - 1);
    std::vector<double> taken = {arc.of(params.front()), arc.of(params.back())};
    std::vector<int> corners;
    for(const auto &c : candidates) {
      const double at = arc.at[c.second];
      bool near = false;
      for(double t : taken) near = near || std::fabs(at - t) < 0.5 * segment;
      if(near) continue;
      taken.push_back(at);
      corners.push_back(c.second);
    }
    std::sort(corners.begin(), corners.end());
    return corners;
  }

  // How many of the old segments lie between arc lengths a and b (by the
  // fraction of each inside): the piece gets as many, rounded, so that the
  // size along the curve stays what Gmsh chose
  double segmentsBetween(const arcLength &arc,
                         const std::vector<double> &params, double a, double b)
  {
    double n = 0.;
    for(std::size_t s = 0; s + 1 < params.size(); s++) {
      const double s0 = arc.of(params[s]), s1 = arc.of(params[s + 1]);
      const double overlap = std::min(b, s1) - std::max(a, s0);
      if(overlap > 0. && s1 > s0) n += overlap / (s1 - s0);
    }
    return n;
  }

  // Whole numbers of segments for pieces with these shares of `total`: at
  // least one each, the rest by the largest remainders, so that the curve
  // keeps its count (or, where the pieces are more than the segments, its
  // parity)
  std::vector<int> apportionSegments(const std::vector<double> &share,
                                     int total)
  {
    std::vector<int> n(share.size());
    std::vector<std::pair<double, std::size_t> > remainders;
    int sum = 0;
    for(std::size_t k = 0; k < share.size(); k++) {
      n[k] = std::max(1, (int)std::floor(share[k]));
      sum += n[k];
      remainders.push_back(std::make_pair(n[k] - share[k], k));
    }
    std::sort(remainders.begin(), remainders.end());
    for(std::size_t i = 0; sum < total && i < remainders.size(); i++, sum++)
      n[remainders[i].second]++;
    if((sum - total) % 2) n[remainders.front().second]++;
    return n;
  }

} // namespace

std::vector<double> snapCurveNodesToCorners(
  const std::vector<SPoint3> &polyline, const std::vector<double> &params,
  const std::function<bool(int)> &allowed, std::vector<int> *taken,
  bool keepParity, bool everyCorner)
{
  if(taken) taken->clear();
  if(polyline.size() < 3 || params.size() < 3) return params;
  const arcLength arc(polyline);
  const std::vector<int> corners =
    chooseCorners(polyline, arc, params, allowed, everyCorner);
  if(taken) *taken = corners;
  if(corners.empty()) return params;
  // the curve cut at its corners, each piece meshed evenly with its share
  // of the segments (at least one)
  std::vector<double> ends = {params.front()};
  for(int c : corners) ends.push_back(c);
  ends.push_back(params.back());
  std::vector<double> share;
  for(std::size_t k = 0; k + 1 < ends.size(); k++)
    share.push_back(
      segmentsBetween(arc, params, arc.of(ends[k]), arc.of(ends[k + 1])));
  std::vector<int> counts;
  if(keepParity)
    counts = apportionSegments(share, (int)params.size() - 1);
  else
    for(double n : share) counts.push_back(std::max(1, (int)std::lround(n)));
  std::vector<double> snapped = {params.front()};
  for(std::size_t k = 0; k + 1 < ends.size(); k++) {
    const double a = arc.of(ends[k]), b = arc.of(ends[k + 1]);
    const int n = counts[k];
    for(int i = 1; i < n; i++)
      snapped.push_back(arc.parameter(a + (b - a) * i / n));
    snapped.push_back(ends[k + 1]);
  }
  return snapped;
}
} // namespace reparam

