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
  // a cap on the subdivision bounds the memory: the few huge triangles
  // among tiny ones (CAD STL) are measured at every query instead
  const int maxSubdivision = 64;
  std::vector<int> subdivision(_triangles.size(), 1);
  double largest = 0.;
  for(std::size_t t = 0; t < _triangles.size(); t++) {
    if(meanRadius > 0. && radius[t] > maxSubdivision * meanRadius) {
      subdivision[t] = 0;
      _hugeTriangles.push_back((int)t);
      continue;
    }
    if(meanRadius > 0. && radius[t] > meanRadius)
      subdivision[t] = (int)std::ceil(radius[t] / meanRadius);
    largest = std::max(largest, radius[t] / subdivision[t]);
  }
  // class k: sample radius in (largest / 4^(k+1), largest / 4^k]: few
  // classes (each costs a search per query), far enough apart that the
  // dense tiny triangles do not share the radius of the large ones
  const int numClasses = 12;
  auto classOf = [&](std::size_t t) {
    const double r = radius[t] / subdivision[t];
    if(!(r > 0.) || !(largest > 0.)) return numClasses - 1;
    return std::min(numClasses - 1,
                    (int)std::floor(std::log2(largest / r) / 2.));
  };
  std::vector<std::size_t> count(numClasses, 0);
  for(std::size_t t = 0; t < _triangles.size(); t++)
    if(subdivision[t])
      count[classOf(t)] += (std::size_t)subdivision[t] * subdivision[t];
  std::vector<sampleClass *> byIndex(numClasses, nullptr);
  for(int k = 0; k < numClasses; k++) {
    if(!count[k]) continue;
    _classes.emplace_back(new sampleClass);
    byIndex[k] = _classes.back().get();
    byIndex[k]->radius = largest / std::ldexp(1., 2 * k);
    byIndex[k]->points = annAllocPts((int)count[k], 3);
    byIndex[k]->triangle.reserve(count[k]);
  }
  for(std::size_t t = 0; t < _triangles.size(); t++) {
    const int m = subdivision[t];
    if(!m) continue;
    sampleClass &c = *byIndex[classOf(t)];
    const SPoint3 &a = _points[_triangles[t][0]],
                  &b = _points[_triangles[t][1]],
                  &p = _points[_triangles[t][2]];
    auto addSample = [&](double v, double w) {
      double *s = c.points[c.triangle.size()];
      for(int k = 0; k < 3; k++)
        s[k] = a[k] + v * (b[k] - a[k]) + w * (p[k] - a[k]);
      c.triangle.push_back((int)t);
    };
    for(int i = 0; i < m; i++)
      for(int j = 0; i + j < m; j++) {
        // sub-triangle with the same orientation as the triangle...
        addSample((i + 1. / 3.) / m, (j + 1. / 3.) / m);
        // ... and the reversed one next to it
        if(i + j < m - 1) addSample((i + 2. / 3.) / m, (j + 2. / 3.) / m);
      }
  }
  for(auto &c : _classes)
    c->tree.reset(new ANNkd_tree(c->points, (int)c->triangle.size(), 3));
}

closestTriangleSearch::~closestTriangleSearch()
{
  for(auto &c : _classes) {
    c->tree.reset();
    annDeallocPts(c->points);
  }
}

std::size_t closestTriangleSearch::numSamples() const
{
  std::size_t n = 0;
  for(const auto &c : _classes) n += c->triangle.size();
  return n;
}

double closestTriangleSearch::distanceTo(int t, const SPoint3 &p,
                                         SPoint3 &closest) const
{
  closest = closestPointOnTriangle(p, _points[_triangles[t][0]],
                                   _points[_triangles[t][1]],
                                   _points[_triangles[t][2]]);
  return p.distance(closest);
}

void closestTriangleSearch::closer(const SPoint3 &p, std::vector<int> &candidates,
                                   closestTriangleHit &hit) const
{
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()),
                   candidates.end());
  for(int t : candidates) {
    if(t == hit.triangle) continue;
    SPoint3 point;
    double d = distanceTo(t, p, point);
    if(hit.triangle < 0 || d < hit.distance) {
      hit.triangle = t;
      hit.distance = d;
      hit.point = point;
    }
  }
}

closestTriangleHit closestTriangleSearch::closest(const SPoint3 &p) const
{
  closestTriangleHit hit;
  std::vector<int> candidates = _hugeTriangles;
  double q[3] = {p.x(), p.y(), p.z()};
  // an upper bound: the triangles of the nearest samples of each class
  for(const auto &c : _classes) {
    const int k = std::min<int>(4, (int)c->triangle.size());
    ANNidx nearest[4];
    ANNdist squared[4];
    c->tree->annkSearch(q, k, nearest, squared, 0.);
    for(int i = 0; i < k; i++) candidates.push_back(c->triangle[nearest[i]]);
  }
  closer(p, candidates, hit);
  // every triangle closer than the bound has a sample of its class within
  // the bound plus the class radius
  for(const auto &c : _classes) {
    const double r = (hit.distance + c->radius) * (1. + 1e-12);
    int count = c->tree->annkFRSearch(q, r * r, 0);
    if(!count) continue;
    std::vector<ANNidx> inside(count);
    c->tree->annkFRSearch(q, r * r, count, inside.data(), nullptr, 0.);
    candidates.clear();
    for(ANNidx s : inside) candidates.push_back(c->triangle[s]);
    closer(p, candidates, hit);
  }
  return hit;
}
