// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include <Eigen/Dense>
#include "bijectivityCheck.h"
#include "mapKind.h"
#include "planeProjection.h"
#include "stageTimer.h"

namespace reparam {

namespace {

  struct leastSquaresPlane {
    Eigen::Vector3d origin, normal, u, v;
  };

  leastSquaresPlane planeOf(const std::vector<SPoint3> &points)
  {
    leastSquaresPlane plane;
    plane.origin = Eigen::Vector3d::Zero();
    for(const SPoint3 &p : points)
      plane.origin += Eigen::Vector3d(p.x(), p.y(), p.z());
    plane.origin /= (double)points.size();
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for(const SPoint3 &p : points) {
      const Eigen::Vector3d d =
        Eigen::Vector3d(p.x(), p.y(), p.z()) - plane.origin;
      covariance += d * d.transpose();
    }
    // eigenvalues in increasing order: the first vector is the normal
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(covariance);
    plane.normal = eig.eigenvectors().col(0);
    plane.u = eig.eigenvectors().col(2);
    plane.v = plane.normal.cross(plane.u);
    return plane;
  }

  Eigen::Vector3d vectorOf(const SPoint3 &p)
  {
    return Eigen::Vector3d(p.x(), p.y(), p.z());
  }

  double diagonalOf(const std::vector<SPoint3> &points)
  {
    if(points.empty()) return 0.;
    Eigen::Vector3d lo = vectorOf(points[0]), hi = lo;
    for(const SPoint3 &p : points) {
      lo = lo.cwiseMin(vectorOf(p));
      hi = hi.cwiseMax(vectorOf(p));
    }
    return (hi - lo).norm();
  }

  // Twice the triangle's 3D area over its longest edge
  double heightOf(const discretePatch &patch, int t)
  {
    const auto &c = patch.triangles[t];
    const Eigen::Vector3d a = vectorOf(patch.points[c[0]]),
                          b = vectorOf(patch.points[c[1]]),
                          d = vectorOf(patch.points[c[2]]);
    const double longest =
      std::max((b - a).norm(), std::max((d - b).norm(), (a - d).norm()));
    return longest > 0. ? (b - a).cross(d - a).norm() / longest : 0.;
  }

} // namespace

bool patchIsPlanar(const surfaceMesh &patch, double tolerance)
{
  if(!(tolerance > 0.) || patch.points.empty()) return false;
  const double bound = tolerance * diagonalOf(patch.points);
  const leastSquaresPlane plane = planeOf(patch.points);
  for(const SPoint3 &p : patch.points)
    if(std::fabs(plane.normal.dot(vectorOf(p) - plane.origin)) > bound)
      return false;
  return true;
}

patchMap planeProjectionMap(const discretePatch &patch, double *scale)
{
  patchMap map;
  const double t0 = wallSeconds();
  const std::size_t n = patch.points.size();
  leastSquaresPlane plane = planeOf(patch.points);
  map.uv.resize(2 * n);
  for(std::size_t i = 0; i < n; i++) {
    const Eigen::Vector3d d = vectorOf(patch.points[i]) - plane.origin;
    map.uv[2 * i] = plane.u.dot(d);
    map.uv[2 * i + 1] = plane.v.dot(d);
  }
  double signedArea = 0.;
  for(const auto &t : patch.triangles) {
    const double *a = &map.uv[2 * t[0]], *b = &map.uv[2 * t[1]],
                 *c = &map.uv[2 * t[2]];
    signedArea += (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  }
  // mirrored: the plane seen from the other side
  if(signedArea < 0.)
    for(std::size_t i = 0; i < n; i++) map.uv[2 * i + 1] *= -1.;
  double cu = 0., cv = 0., rms = 0.;
  std::size_t boundary = 0;
  for(const auto &loop : patch.boundaryLoops)
    for(int i : loop) {
      cu += map.uv[2 * i];
      cv += map.uv[2 * i + 1];
      boundary++;
    }
  if(boundary) {
    cu /= boundary;
    cv /= boundary;
    for(const auto &loop : patch.boundaryLoops)
      for(int i : loop)
        rms +=
          std::pow(map.uv[2 * i] - cu, 2) + std::pow(map.uv[2 * i + 1] - cv, 2);
    rms = std::sqrt(rms / boundary);
  }
  const double s = rms > 0. ? 1. / rms : 1.;
  for(std::size_t i = 0; i < n; i++) {
    map.uv[2 * i] = (map.uv[2 * i] - cu) * s;
    map.uv[2 * i + 1] = (map.uv[2 * i + 1] - cv) * s;
  }
  if(scale) *scale = s;
  map.solveTime = wallSeconds() - t0;
  return map;
}

checkedMap planeProjection(const discretePatch &patch, double tolerance)
{
  checkedMap result;
  mapAttempt attempt;
  attempt.map = (int)compoundParametrization::plane;
  double scale = 1.;
  result.map = planeProjectionMap(patch, &scale);
  attempt.mapTime = result.map.solveTime;
  const double t0 = wallSeconds();
  const double within = tolerance * diagonalOf(patch.points);
  const bijectivityReport report = checkBijectivity(patch, result.map.uv);
  attempt.degenerate = report.degenerateTriangles.size();
  for(int t : report.flippedTriangles)
    if(heightOf(patch, t) > within)
      attempt.flipped++;
    else
      attempt.degenerate++;
  attempt.folds = report.numFolds ?
                    countBoundaryFolds(patch, result.map.uv, within * scale) :
                    0;
  attempt.flippedAfter = attempt.flipped;
  attempt.foldsAfter = attempt.folds;
  attempt.degenerateAfter = attempt.degenerate;
  attempt.checkTime = wallSeconds() - t0;
  result.attempts.push_back(attempt);
  result.chosen = 0;
  result.bijective = attempt.bijective();
  return result;
}

} // namespace reparam
