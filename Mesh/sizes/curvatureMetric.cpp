// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include <Eigen/Eigenvalues>
#include "closestTriangle.h"
#include "curvature.h"
#include "curvatureMetric.h"
#include "surfaceMesh.h"

namespace reparam {

std::vector<principalCurvatures> curvaturesOf(const surfaceMesh &m)
{
  std::vector<int> triangles;
  for(const std::array<int, 3> &t : m.triangles)
    triangles.insert(triangles.end(), t.begin(), t.end());
  std::vector<std::pair<SVector3, SVector3> > nodal;
  std::vector<double> normals(3 * m.points.size(), 0.);
  std::vector<principalCurvatures> c(m.points.size());
  if(triangles.empty()) return c;
  CurvatureRusinkiewicz(triangles, m.points, nodal, normals);
  for(std::size_t i = 0; i < c.size() && i < nodal.size(); i++) {
    // Gmsh gives each direction scaled by |k|: a zero curvature (a
    // cylinder's axis) comes without its direction, which is then the
    // tangent across the other one
    const SVector3 *d[2] = {&nodal[i].first, &nodal[i].second};
    for(int k = 0; k < 2; k++) {
      const double norm = d[k]->norm();
      const bool known = norm > 0. && std::isfinite(norm);
      c[i].curvature[k] = known ? norm : 0.;
      c[i].direction[k] = known ? *d[k] * (1. / norm) : SVector3(0., 0., 0.);
    }
    const SVector3 n(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
    for(int k = 0; k < 2; k++)
      if(c[i].direction[k].norm() == 0. && c[i].direction[1 - k].norm() > 0.) {
        c[i].direction[k] = crossprod(n, c[i].direction[1 - k]);
        if(c[i].direction[k].norm() > 0.) c[i].direction[k].normalize();
      }
  }
  return c;
}

double curvatureSizes::along(double curvature) const
{
  const double k = std::fabs(curvature);
  double h = k > 0. ? 2. * M_PI / (elementsPerCircle * k) : hMax;
  if(!std::isfinite(h)) h = hMax;
  return std::max(hMin, std::min(hMax, h));
}

SMetric3 curvatureMetric(const principalCurvatures &c,
                         const curvatureSizes &sizes)
{
  SVector3 t1 = c.direction[0], t2 = c.direction[1];
  double h1 = sizes.along(c.curvature[0]), h2 = sizes.along(c.curvature[1]);
  // no direction (a flat or degenerate spot): isotropic at the smaller size
  if(t1.norm() == 0. || t2.norm() == 0. || crossprod(t1, t2).norm() < 1e-6) {
    const double h = std::min(h1, h2);
    return SMetric3(1. / (h * h));
  }
  SVector3 n = crossprod(t1, t2);
  n.normalize();
  // the directions made exactly orthogonal
  t2 = crossprod(n, t1);
  t2.normalize();
  t1.normalize();
  return SMetric3(1. / (h1 * h1), 1. / (h2 * h2),
                  1. / (sizes.hMax * sizes.hMax), t1, t2, n);
}

void gradeMetrics(const surfaceMesh &m, std::vector<SMetric3> &metrics,
                  double growth)
{
  const std::size_t n = std::min(m.points.size(), metrics.size());
  std::vector<std::vector<int> > neighbours(n);
  for(const std::array<int, 3> &t : m.triangles)
    for(int k = 0; k < 3; k++) {
      const int a = t[k], b = t[(k + 1) % 3];
      if(a >= (int)n || b >= (int)n) continue;
      neighbours[a].push_back(b);
      neighbours[b].push_back(a);
    }
  const double logGrowth = std::log(growth);
  std::vector<int> queue;
  std::vector<bool> queued(n, true);
  std::vector<int> updates(n, 0);
  for(std::size_t i = 0; i < n; i++) queue.push_back((int)i);
  for(std::size_t head = 0; head < queue.size(); head++) {
    const int p = queue[head];
    queued[p] = false;
    const SMetric3 &mp = metrics[p];
    for(int q : neighbours[p]) {
      const SVector3 e(m.points[p], m.points[q]);
      double length = 0.;
      for(int i = 0; i < 3; i++)
        for(int j = 0; j < 3; j++) length += e[i] * mp(i, j) * e[j];
      const double eta =
        1. / (1. + std::sqrt(std::max(0., length)) * logGrowth);
      SMetric3 propagated = mp;
      propagated *= eta * eta;
      const SMetric3 graded = intersectAlong(metrics[q], propagated);
      double change = 0., norm = 0.;
      for(int i = 0; i < 3; i++)
        for(int j = 0; j < 3; j++) {
          change += std::fabs(graded(i, j) - metrics[q](i, j));
          norm += std::fabs(metrics[q](i, j));
        }
      if(change <= 0.01 * norm || updates[q] >= 20) continue;
      metrics[q] = graded;
      updates[q]++;
      if(!queued[q]) {
        queued[q] = true;
        queue.push_back(q);
      }
    }
  }
}

curvatureMetricField::curvatureMetricField(const surfaceMesh &input,
                                           const curvatureSizes &sizes)
  : _points(input.points), _triangles(input.triangles)
{
  for(const principalCurvatures &c : curvaturesOf(input))
    _metrics.push_back(curvatureMetric(c, sizes));
  if(sizes.gradation > 1.) gradeMetrics(input, _metrics, sizes.gradation);
  _search.reset(new closestTriangleSearch(_points, _triangles));
}

curvatureMetricField::~curvatureMetricField() = default;

SMetric3 curvatureMetricField::at(const SPoint3 &x) const
{
  const closestTriangleHit hit = _search->closest(x);
  if(hit.triangle < 0) return SMetric3(1e-44);
  const std::array<int, 3> &t = _triangles[hit.triangle];
  // barycentric weights of the closest point (by sub-triangle areas)
  const SPoint3 &a = _points[t[0]], &b = _points[t[1]], &c = _points[t[2]];
  const SVector3 n = crossprod(SVector3(a, b), SVector3(a, c));
  const double area = n.norm();
  double w[3] = {1. / 3., 1. / 3., 1. / 3.};
  if(area > 0.) {
    const SPoint3 &p = hit.point;
    w[0] = dot(crossprod(SVector3(p, b), SVector3(p, c)), n) / (area * area);
    w[1] = dot(crossprod(SVector3(p, c), SVector3(p, a)), n) / (area * area);
    w[2] = 1. - w[0] - w[1];
    for(double &v : w) v = std::max(0., v);
    const double sum = w[0] + w[1] + w[2];
    for(double &v : w) v = sum > 0. ? v / sum : 1. / 3.;
  }
  SMetric3 m(0.);
  for(int k = 0; k < 3; k++) {
    SMetric3 part = _metrics[t[k]];
    part *= w[k];
    m += part;
  }
  return m;
}

namespace {

  Eigen::Matrix3d matrixOf(const SMetric3 &m)
  {
    Eigen::Matrix3d a;
    for(int i = 0; i < 3; i++)
      for(int j = 0; j < 3; j++) a(i, j) = m(i, j);
    return a;
  }

} // namespace

SMetric3 intersectAlong(const SMetric3 &c, const SMetric3 &m)
{
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(matrixOf(c));
  const Eigen::Matrix3d &v = eig.eigenvectors();
  const Eigen::Matrix3d mm = matrixOf(m);
  SVector3 axis[3];
  double value[3];
  for(int k = 0; k < 3; k++) {
    const Eigen::Vector3d e = v.col(k);
    axis[k] = SVector3(e(0), e(1), e(2));
    value[k] = std::max(eig.eigenvalues()(k), e.dot(mm * e));
  }
  return SMetric3(value[0], value[1], value[2], axis[0], axis[1], axis[2]);
}

double curvatureMetricField::smallestSizeAt(const SPoint3 &x) const
{
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(
    matrixOf(at(x)), Eigen::EigenvaluesOnly);
  const double largest = eig.eigenvalues().maxCoeff();
  return largest > 0. ? 1. / std::sqrt(largest) : 1e22;
}
} // namespace reparam

