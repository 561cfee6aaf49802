// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "barycentricMap.h"
#include "diskMap.h"

namespace reparam {

triangleWeights barycentricWeights(const SPoint3 &, const SPoint3 &,
                                   const SPoint3 &)
{
  triangleWeights w;
  for(auto &row : w) row.fill(0.5);
  return w;
}

patchMap barycentricMap(const discretePatch &patch)
{
  return diskMap(patch, barycentricWeights, sparseFactorization::cholesky);
}
} // namespace reparam

