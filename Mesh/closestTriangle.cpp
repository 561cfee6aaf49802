// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include <ANN/ANN.h>
#include "SVector3.h"
#include "closestTriangle.h"

namespace {

  SPoint3 closestPointOnSegment(const SPoint3 &p, const SPoint3 &a,
                                const SPoint3 &b)
  {
    SVector3 ab(a, b);
    double l2 = dot(ab, ab);
    if(l2 == 0.) return a;
    double t = std::clamp(dot(SVector3(a, p), ab) / l2, 0., 1.);
    return SPoint3(a.x() + t * ab.x(), a.y() + t * ab.y(), a.z() + t * ab.z());
  }

} // namespace

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

closestTriangleSearch::closestTriangleSearch(
  const std::vector<SPoint3> &points,
  const std::vector<std::array<int, 3> > &triangles)
  : _points(points), _triangles(triangles)
{
  if(_triangles.empty()) return;
  // Radius of a triangle around its centroid: the samples of a triangle
  // subdivided m times are the centroids of its m^2 sub-triangles, each a
  // copy of the triangle scaled by 1/m, so their radius is radius / m
  std::vector<double> radius(_triangles.size());
  double meanRadius = 0.;
  for(std::size_t t = 0; t < _triangles.size(); t++) {
    const SPoint3 &a = _points[_triangles[t][0]],
                  &b = _points[_triangles[t][1]],
                  &c = _points[_triangles[t][2]];
    SPoint3 g = (a + b + c) * (1. / 3.);
    radius[t] = std::max({g.distance(a), g.distance(b), g.distance(c)});
    meanRadius += radius[t];
  }
  meanRadius /= _triangles.size();
  // a cap on the subdivision bounds the memory for a few huge triangles
  // among tiny ones (CAD STL); the search stays exact, only slower
  const int maxSubdivision = 64;
  std::vector<int> subdivision(_triangles.size(), 1);
  std::size_t numSamples = 0;
  for(std::size_t t = 0; t < _triangles.size(); t++) {
    if(meanRadius > 0. && radius[t] > meanRadius)
      subdivision[t] =
        std::min(maxSubdivision, (int)std::ceil(radius[t] / meanRadius));
    numSamples += (std::size_t)subdivision[t] * subdivision[t];
    _sampleRadius = std::max(_sampleRadius, radius[t] / subdivision[t]);
  }

  _samplePoints = annAllocPts((int)numSamples, 3);
  _sampleTriangle.reserve(numSamples);
  auto addSample = [&](int t, double v, double w) {
    const SPoint3 &a = _points[_triangles[t][0]],
                  &b = _points[_triangles[t][1]],
                  &c = _points[_triangles[t][2]];
    double *s = _samplePoints[_sampleTriangle.size()];
    for(int k = 0; k < 3; k++)
      s[k] = a[k] + v * (b[k] - a[k]) + w * (c[k] - a[k]);
    _sampleTriangle.push_back(t);
  };
  for(std::size_t t = 0; t < _triangles.size(); t++) {
    const int m = subdivision[t];
    for(int i = 0; i < m; i++)
      for(int j = 0; i + j < m; j++) {
        // sub-triangle with the same orientation as the triangle...
        addSample((int)t, (i + 1. / 3.) / m, (j + 1. / 3.) / m);
        // ... and the reversed one next to it
        if(i + j < m - 1)
          addSample((int)t, (i + 2. / 3.) / m, (j + 2. / 3.) / m);
      }
  }
  _tree.reset(new ANNkd_tree(_samplePoints, (int)numSamples, 3));
}

closestTriangleSearch::~closestTriangleSearch()
{
  _tree.reset();
  if(_samplePoints) annDeallocPts(_samplePoints);
}

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
  closestTriangleHit hit;
  if(!_tree) return hit;
  double q[3] = {p.x(), p.y(), p.z()};
  // the few nearest samples hold every candidate but in rare cases
  const int k = std::min<int>(16, (int)_sampleTriangle.size());
  ANNidx nearest[16];
  ANNdist squared[16];
  _tree->annkSearch(q, k, nearest, squared, 0.);
  hit.triangle = _sampleTriangle[nearest[0]];
  hit.distance = distanceTo(hit.triangle, p, hit.point);

  // every triangle closer than hit.distance has a sample within this radius
  double r = (hit.distance + _sampleRadius) * (1. + 1e-12);
  std::vector<int> triangles;
  if(k < (int)_sampleTriangle.size() && squared[k - 1] <= r * r) {
    int count = _tree->annkFRSearch(q, r * r, 0);
    std::vector<ANNidx> inside(count);
    _tree->annkFRSearch(q, r * r, count, inside.data(), nullptr, 0.);
    for(ANNidx s : inside) triangles.push_back(_sampleTriangle[s]);
  }
  else {
    for(int i = 1; i < k && squared[i] <= r * r; i++)
      triangles.push_back(_sampleTriangle[nearest[i]]);
  }
  std::sort(triangles.begin(), triangles.end());
  triangles.erase(std::unique(triangles.begin(), triangles.end()),
                  triangles.end());
  for(int t : triangles) {
    if(t == hit.triangle) continue;
    SPoint3 point;
    double d = distanceTo(t, p, point);
    if(d < hit.distance) {
      hit.triangle = t;
      hit.distance = d;
      hit.point = point;
    }
  }
  return hit;
}
