// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <Eigen/Eigenvalues>
#include "conformalAssembly.h"
#include "conformalMap.h"
#include "dirichletSolve.h"
#include "stageTimer.h"

namespace reparam {

std::array<int, 2> farthestBoundaryPair(const discretePatch &patch)
{
  const std::vector<int> &loop = patch.boundaryLoops[patch.outerLoop];
  const std::size_t m = loop.size();
  auto d2 = [&](int a, int b) {
    return patch.points[a].distance(patch.points[b]) *
           patch.points[a].distance(patch.points[b]);
  };
  std::array<int, 2> best{{loop[0], loop[m / 2]}};
  double bestD2 = -1.;
  if(m <= 2048) {
    for(std::size_t i = 0; i < m; i++)
      for(std::size_t j = i + 1; j < m; j++) {
        double d = d2(loop[i], loop[j]);
        if(d > bestD2) {
          bestD2 = d;
          best = {{loop[i], loop[j]}};
        }
      }
    return best;
  }
  for(std::size_t start = 0; start < m; start += m / 4) {
    int a = loop[start], b = a;
    for(int sweep = 0; sweep < 3; sweep++) {
      double far = -1.;
      int next = a;
      for(int x : loop) {
        double d = d2(a, x);
        if(d > far) {
          far = d;
          next = x;
        }
      }
      b = a;
      a = next;
      if(far > bestD2) {
        bestD2 = far;
        best = {{b, a}};
      }
    }
  }
  return best;
}

std::array<int, 2> principalAxisPins(const discretePatch &patch)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for(const SPoint3 &p : patch.points)
    mean += Eigen::Vector3d(p.x(), p.y(), p.z());
  mean /= (double)patch.points.size();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for(const SPoint3 &p : patch.points) {
    Eigen::Vector3d d = Eigen::Vector3d(p.x(), p.y(), p.z()) - mean;
    covariance += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(covariance);
  // eigenvalues in increasing order: the last vector is the longest axis
  const Eigen::Vector3d axis = eig.eigenvectors().col(2);
  const std::vector<int> &loop = patch.boundaryLoops[patch.outerLoop];
  std::array<int, 2> pins{{loop[0], loop[0]}};
  double lo = 1e300, hi = -1e300;
  for(int i : loop) {
    const SPoint3 &p = patch.points[i];
    double s = axis.dot(Eigen::Vector3d(p.x(), p.y(), p.z()) - mean);
    if(s < lo) {
      lo = s;
      pins[0] = i;
    }
    if(s > hi) {
      hi = s;
      pins[1] = i;
    }
  }
  return pins;
}

patchMap conformalMap(const discretePatch &patch, std::array<int, 2> pins)
{
  patchMap map;
  const std::size_t n = patch.points.size();
  double t0 = wallSeconds();
  Eigen::SparseMatrix<std::complex<double> > H = assembleConformalEnergy(patch);
  Eigen::MatrixXcd z = Eigen::MatrixXcd::Zero(n, 1);
  std::vector<char> isFixed(n, 0);
  z(pins[0], 0) = -1.;
  z(pins[1], 0) = 1.;
  isFixed[pins[0]] = isFixed[pins[1]] = 1;
  double t1 = wallSeconds();
  if(pins[0] == pins[1])
    map.error = reparamFailure(reparamStatus::solverFailed,
                               "the two pinned nodes are the same");
  else
    map.error = dirichletSolve(H, isFixed, z);
  map.assembleTime = t1 - t0;
  map.solveTime = wallSeconds() - t1;
  if(map.error.ok()) {
    map.uv.resize(2 * n);
    for(std::size_t i = 0; i < n; i++) {
      map.uv[2 * i] = z(i, 0).real();
      map.uv[2 * i + 1] = z(i, 0).imag();
    }
  }
  return map;
}

patchMap conformalMap(const discretePatch &patch)
{
  double t0 = wallSeconds();
  std::array<int, 2> pins = farthestBoundaryPair(patch);
  double t1 = wallSeconds();
  patchMap map = conformalMap(patch, pins);
  map.assembleTime += t1 - t0;
  return map;
}
} // namespace reparam

