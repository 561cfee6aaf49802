// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include <limits>
#include "SVector3.h"
#include "closestTriangle.h"

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

SPoint3 closestPointOnTriangle(const SPoint3 &p, const SPoint3 &a,
                               const SPoint3 &b, const SPoint3 &c)
{
  SVector3 ab(a, b), ac(a, c), ap(a, p);
  SVector3 n = crossprod(ab, ac);
  double n2 = dot(n, n);
  double scale = std::max({dot(ab, ab), dot(ac, ac), SVector3(b, c).normSq()});
  // Barycentric coordinates of the projection onto the plane (Cramer on
  // the normal equations); a triangle flat to round-off is its edges
  if(n2 > 1e-24 * scale * scale) {
    double v = dot(crossprod(ap, ac), n) / n2;
    double w = dot(crossprod(ab, ap), n) / n2;
    if(v >= 0. && w >= 0. && v + w <= 1.)
      return SPoint3(a.x() + v * ab.x() + w * ac.x(),
                     a.y() + v * ab.y() + w * ac.y(),
                     a.z() + v * ab.z() + w * ac.z());
  }
  // outside the face: the closest point is on an edge
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
  : _points(points), _triangles(triangles)
{
  if(_triangles.empty()) return;
  _order.resize(_triangles.size());
  for(std::size_t t = 0; t < _order.size(); t++) _order[t] = (int)t;
  std::vector<SPoint3> centroids(_triangles.size());
  for(std::size_t t = 0; t < _triangles.size(); t++)
    centroids[t] = (_points[_triangles[t][0]] + _points[_triangles[t][1]] +
                    _points[_triangles[t][2]]) *
                   (1. / 3.);
  _nodes.reserve(2 * _triangles.size() / leafSize + 2);
  build(0, (int)_order.size(), centroids);
}

closestTriangleSearch::~closestTriangleSearch() {}

// The node over _order[first, first + count): its box, then halves split at
// the median centroid along the longest side of the centroids' box
int closestTriangleSearch::build(int first, int count,
                                 const std::vector<SPoint3> &centroids)
{
  const int index = (int)_nodes.size();
  _nodes.push_back(boxNode());
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  double clo[3] = {1e300, 1e300, 1e300}, chi[3] = {-1e300, -1e300, -1e300};
  for(int i = first; i < first + count; i++) {
    const int t = _order[i];
    for(int v : _triangles[t])
      for(int k = 0; k < 3; k++) {
        lo[k] = std::min(lo[k], _points[v][k]);
        hi[k] = std::max(hi[k], _points[v][k]);
      }
    for(int k = 0; k < 3; k++) {
      clo[k] = std::min(clo[k], centroids[t][k]);
      chi[k] = std::max(chi[k], centroids[t][k]);
    }
  }
  for(int k = 0; k < 3; k++) {
    _nodes[index].lo[k] = lo[k];
    _nodes[index].hi[k] = hi[k];
  }
  if(count <= leafSize) {
    _nodes[index].first = first;
    _nodes[index].count = count;
    return index;
  }
  int axis = 0;
  for(int k = 1; k < 3; k++)
    if(chi[k] - clo[k] > chi[axis] - clo[axis]) axis = k;
  const int half = count / 2;
  std::nth_element(_order.begin() + first, _order.begin() + first + half,
                   _order.begin() + first + count, [&](int a, int b) {
                     return centroids[a][axis] < centroids[b][axis];
                   });
  const int left = build(first, half, centroids);
  const int right = build(first + half, count - half, centroids);
  _nodes[index].left = left;
  _nodes[index].right = right;
  return index;
}

std::size_t closestTriangleSearch::numBoxes() const { return _nodes.size(); }

double closestTriangleSearch::distanceTo(int t, const SPoint3 &p,
                                         SPoint3 &closest) const
{
  closest = closestPointOnTriangle(p, _points[_triangles[t][0]],
                                   _points[_triangles[t][1]],
                                   _points[_triangles[t][2]]);
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
  if(_nodes.empty()) return hit;
  double best2 = 1e300;
  if(near >= 0 && near < (int)_triangles.size()) {
    hit.triangle = near;
    hit.distance = distanceTo(near, p, hit.point);
    best2 = hit.distance * hit.distance;
  }
  // depth first, the nearer child first, boxes farther than the best
  // distance skipped; the tree is balanced (median splits), so that the
  // stack holds at most two boxes per level (a fixed array: one allocation
  // per search was a tenth of its time)
  std::pair<double, int> stack[2 * maxDepth + 2];
  int size = 0;
  stack[size++] = std::make_pair(0., 0);
  while(size) {
    const std::pair<double, int> top = stack[--size];
    if(top.first >= best2) continue;
    const boxNode &n = _nodes[top.second];
    if(n.count) {
      for(int i = n.first; i < n.first + n.count; i++) {
        SPoint3 point;
        const double d = distanceTo(_order[i], p, point);
        if(d * d < best2) {
          best2 = d * d;
          hit.triangle = _order[i];
          hit.distance = d;
          hit.point = point;
        }
      }
      continue;
    }
    const double dl = boxDistance2(_nodes[n.left].lo, _nodes[n.left].hi, p);
    const double dr = boxDistance2(_nodes[n.right].lo, _nodes[n.right].hi, p);
    if(dl < dr) {
      stack[size++] = std::make_pair(dr, n.right);
      stack[size++] = std::make_pair(dl, n.left);
    }
    else {
      stack[size++] = std::make_pair(dl, n.left);
      stack[size++] = std::make_pair(dr, n.right);
    }
  }
  return hit;
}
