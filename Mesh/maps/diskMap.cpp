// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "diskMap.h"
#include "patchBoundary.h"
#include "stageTimer.h"

namespace reparam {

patchMap diskMap(const discretePatch &patch,
                 const triangleWeightFunction &weights,
                 sparseFactorization factorization)
{
  patchMap map;
  const std::size_t n = patch.points.size();
  double t0 = wallSeconds();
  Eigen::SparseMatrix<double> A = assembleWeightedLaplacian(patch, weights);
  map.uv.assign(2 * n, 0.);
  std::vector<char> isFixed(n, 0);
  mapLoopToUnitCircle(patch, patch.outerLoop, map.uv, isFixed);
  double t1 = wallSeconds();
  map.error = dirichletSolve(A, isFixed, map.uv, factorization);
  map.assembleTime = t1 - t0;
  map.solveTime = wallSeconds() - t1;
  return map;
}
} // namespace reparam

