// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include <limits>
#include "SVector3.h"
#include "closestTriangle.h"

namespace reparam {

SPoint3 closestPointOnSegment(const SPoint3 &p, const SPoint3 &a,
                              const SPoint3 &b)
{
  SVector3 ab(a, b);
  double l2 = dot(ab, ab);
  if(l2 == 0.) return a;
  double t = std::clamp(dot(SVector3(a, p), ab) / l2, 0., 1.);
  return SPoint3(a.x() + t * ab.x(), a.y() + t * ab.y(), a.z() + t * ab.z());
}

double distanceToPolyline(const SPoint3 &p,
                          const std::vector<SPoint3> &polyline)
{
  if(polyline.empty()) return std::numeric_limits<double>::infinity();
  double nearest = p.distance(polyline[0]);
  for(std::size_t i = 0; i + 1 < polyline.size(); i++)
    nearest = std::min(nearest, p.distance(closestPointOnSegment(
                                  p, polyline[i], polyline[i + 1])));
  return nearest;
}

namespace {

  SPoint3 along(const SPoint3 &a, const SVector3 &v, double t)
  {
    return SPoint3(a.x() + t * v.x(), a.y() + t * v.y(), a.z() + t * v.z());
  }

  // Closest point of a triangle flat to round-off: its edges
  SPoint3 closestPointOnEdges(const SPoint3 &p, const SPoint3 &a,
                              const SPoint3 &b, const SPoint3 &c)
  {
    SPoint3 best = closestPointOnSegment(p, a, b);
    double bestDistance = p.distance(best);
    for(const SPoint3 &q :
        {closestPointOnSegment(p, b, c), closestPointOnSegment(p, c, a)}) {
      double d = p.distance(q);
      if(d < bestDistance) {
        bestDistance = d;
        best = q;
      }
    }
    return best;
  }

} // namespace

SPoint3 closestPointOnTriangle(const SPoint3 &p, const SPoint3 &a,
                               const SPoint3 &b, const SPoint3 &c)
{
  const SVector3 ab(a, b), ac(a, c), ap(a, p);
  const SVector3 n = crossprod(ab, ac);
  const double n2 = dot(n, n);
  const double scale =
    std::max({dot(ab, ab), dot(ac, ac), SVector3(b, c).normSq()});
  if(!(n2 > 1e-24 * scale * scale)) return closestPointOnEdges(p, a, b, c);
  // the region of p among the corners, edges and face, from the dot
  // products of the edges with p's offsets from the corners: one
  // projection only (this search is most of the optimizer's and the
  // report's time)
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if(d1 <= 0. && d2 <= 0.) return a;
  const SVector3 bp(b, p);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if(d3 >= 0. && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if(vc <= 0. && d1 >= 0. && d3 <= 0.) return along(a, ab, d1 / (d1 - d3));
  const SVector3 cp(c, p);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if(d6 >= 0. && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if(vb <= 0. && d2 >= 0. && d6 <= 0.) return along(a, ac, d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if(va <= 0. && d4 - d3 >= 0. && d5 - d6 >= 0.)
    return along(b, SVector3(b, c), (d4 - d3) / ((d4 - d3) + (d5 - d6)));
  // inside the face: the projection, by its barycentric coordinates
  const double sum = va + vb + vc, v = vb / sum, w = vc / sum;
  return SPoint3(a.x() + v * ab.x() + w * ac.x(),
                 a.y() + v * ab.y() + w * ac.y(),
                 a.z() + v * ab.z() + w * ac.z());
}

namespace {

  // The squared distance from p to the box [lo, hi] (0 inside)
  double boxDistance2(const double *lo, const double *hi, const SPoint3 &p)
  {
    double d2 = 0.;
    for(int k = 0; k < 3; k++) {
      const double below = lo[k] - p[k], above = p[k] - hi[k];
      const double d = std::max({below, above, 0.});
      d2 += d * d;
    }
    return d2;
  }

  // Triangles per leaf: a few distances are cheaper than a level of boxes
  const int leafSize = 4;
  // the tree's depth: halving from fewer than 2^62 triangles
  const int maxDepth = 64;

} // namespace

closestTriangleSearch::closestTriangleSearch(
  const std::vector<SPoint3> &points,
  const std::vector<std::array<int, 3> > &triangles)
{
  if(triangles.empty()) return;
  auto corner = [&](int t, int c) -> const SPoint3 & {
    return points[triangles[t][c]];
  };
  _tree.build(
    (int)triangles.size(), leafSize,
    [&](int t, double *lo, double *hi) {
      for(int k = 0; k < 3; k++) {
        lo[k] = std::min({corner(t, 0)[k], corner(t, 1)[k], corner(t, 2)[k]});
        hi[k] = std::max({corner(t, 0)[k], corner(t, 1)[k], corner(t, 2)[k]});
      }
    },
    [&](int t, int k) {
      return (corner(t, 0)[k] + corner(t, 1)[k] + corner(t, 2)[k]) / 3.;
    });
  const std::vector<int> &order = _tree.order;
  _corners.resize(3 * order.size());
  _position.resize(order.size());
  for(std::size_t i = 0; i < order.size(); i++) {
    _position[order[i]] = (int)i;
    for(int c = 0; c < 3; c++) _corners[3 * i + c] = corner(order[i], c);
  }
}

closestTriangleSearch::~closestTriangleSearch() {}

std::size_t closestTriangleSearch::numBoxes() const
{
  return _tree.nodes.size();
}

double closestTriangleSearch::distanceTo(int t, const SPoint3 &p,
                                         SPoint3 &closest) const
{
  const SPoint3 *c = &_corners[3 * _position[t]];
  closest = closestPointOnTriangle(p, c[0], c[1], c[2]);
  return p.distance(closest);
}

closestTriangleHit closestTriangleSearch::closest(const SPoint3 &p) const
{
  return closest(p, -1);
}

closestTriangleHit closestTriangleSearch::closest(const SPoint3 &p,
                                                  int near) const
{
  closestTriangleHit hit;
  if(_tree.nodes.empty()) return hit;
  double best2 = 1e300;
  if(near >= 0 && near < (int)_position.size()) {
    hit.triangle = near;
    hit.distance = distanceTo(near, p, hit.point);
    best2 = hit.distance * hit.distance;
  }
  // depth first, the nearer child first, boxes farther than the best
  // distance skipped; the tree is balanced (median splits), so that the
  // stack holds at most two boxes per level (fixed arrays, left
  // uninitialized: one allocation per search was a tenth of its time, and
  // zeroing an array of pairs a few percent)
  double stackDistance[2 * maxDepth + 2];
  int stackNode[2 * maxDepth + 2];
  int size = 0;
  auto push = [&](double d2, int node) {
    stackDistance[size] = d2;
    stackNode[size++] = node;
  };
  push(0., 0);
  while(size) {
    size--;
    if(stackDistance[size] >= best2) continue;
    const boxTree<3>::node &n = _tree.nodes[stackNode[size]];
    if(n.count) {
      for(int i = n.first; i < n.first + n.count; i++) {
        const SPoint3 *c = &_corners[3 * i];
        double lo[3], hi[3];
        for(int k = 0; k < 3; k++) {
          lo[k] = std::min({c[0][k], c[1][k], c[2][k]});
          hi[k] = std::max({c[0][k], c[1][k], c[2][k]});
        }
        if(boxDistance2(lo, hi, p) >= best2) continue;
        const SPoint3 point = closestPointOnTriangle(p, c[0], c[1], c[2]);
        const double d = p.distance(point);
        if(d * d < best2) {
          best2 = d * d;
          hit.triangle = _tree.order[i];
          hit.distance = d;
          hit.point = point;
        }
      }
      continue;
    }
    const boxTree<3>::node &l = _tree.nodes[n.left], &r = _tree.nodes[n.right];
    const double dl = boxDistance2(l.lo, l.hi, p);
    const double dr = boxDistance2(r.lo, r.hi, p);
    if(dl < dr) {
      push(dr, n.right);
      push(dl, n.left);
    }
    else {
      push(dl, n.left);
      push(dr, n.right);
    }
  }
  return hit;
}
} // namespace reparam

