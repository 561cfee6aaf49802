// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "SVector3.h"
#include "diskMap.h"
#include "harmonicMap.h"

namespace reparam {

triangleWeights cotangentWeights(const SPoint3 &x0, const SPoint3 &x1,
                                 const SPoint3 &x2)
{
  const SPoint3 *x[3] = {&x0, &x1, &x2};
  triangleWeights w{};
  // twice the area, the same for the three angles
  const double area2 =
    crossprod(SVector3(x0, x1), SVector3(x0, x2)).norm();
  for(int k = 0; k < 3; k++) {
    int i = (k + 1) % 3, j = (k + 2) % 3;
    // cot(theta_k) = (a . b) / |a x b|, a and b the edges leaving k
    double c = dot(SVector3(*x[k], *x[i]), SVector3(*x[k], *x[j])) / area2;
    w[i][j] = w[j][i] = 0.5 * c;
  }
  return w;
}

patchMap harmonicMap(const discretePatch &patch)
{
  return diskMap(patch, cotangentWeights, sparseFactorization::cholesky);
}
} // namespace reparam

