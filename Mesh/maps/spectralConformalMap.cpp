// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <cmath>
#include "conformalAssembly.h"
#include "generalizedEigenSolve.h"
#include "spectralConformalMap.h"
#include "stageTimer.h"

namespace reparam {

patchMap spectralConformalMap(const discretePatch &patch, spectralMapInfo *info)
{
  patchMap map;
  const std::size_t n = patch.points.size();
  double t0 = wallSeconds();
  Eigen::SparseMatrix<std::complex<double> > H = assembleConformalEnergy(patch);
  Eigen::VectorXd B = Eigen::VectorXd::Zero(n);
  std::size_t numBoundary = 0;
  for(const auto &loop : patch.boundaryLoops) {
    for(int i : loop) B[i] = 1.;
    numBoundary += loop.size();
  }
  // The translations z = c: zero energy, to be excluded
  Eigen::MatrixXcd translations = Eigen::MatrixXcd::Ones(n, 1);
  // lambda is the conformal energy of a map whose boundary has a unit
  // moment: 0 for a developable patch and tiny for smooth ones (1e-9 on a
  // bumpy 100k-triangle square, 1e-4 on a 60-degree spherical cap of 40
  // boundary nodes). Convergence goes with (lambda - shift) over the gap to
  // the next pair, so the shift must be small: with -1e-4 / (boundary
  // nodes), 21 back substitutions on the 100k-triangle patch, against 361
  // with -1 / (boundary nodes). It only has to make L - shift B definite
  // along the translations, which are projected out anyway.
  const double shift = -1e-4 / (double)numBoundary;
  double t1 = wallSeconds();
  eigenpairResult eig = smallestGeneralizedEigenpair(H, B, translations, shift);
  map.assembleTime = t1 - t0;
  map.solveTime = wallSeconds() - t1;
  if(info) {
    info->lambda = eig.lambda;
    info->iterations = eig.iterations;
    info->solves = eig.solves;
  }
  map.error = eig.error;
  if(!map.error.ok()) return map;
  // x^T B x = 1 is a unit boundary moment: rescale to a unit RMS radius
  const double scale = std::sqrt((double)numBoundary);
  map.uv.resize(2 * n);
  for(std::size_t i = 0; i < n; i++) {
    map.uv[2 * i] = scale * eig.x[i].real();
    map.uv[2 * i + 1] = scale * eig.x[i].imag();
  }
  return map;
}
} // namespace reparam

