// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "SVector3.h"
#include "diskMap.h"
#include "meanValueMap.h"

namespace reparam {

namespace {

  // tan(alpha / 2) of the angle between a and b, as |a x b| / (|a||b| + a.b):
  // no acos, so accurate for the tiny and the nearly flat angles of slivers
  double tanHalfAngle(const SVector3 &a, const SVector3 &b)
  {
    return crossprod(a, b).norm() / (a.norm() * b.norm() + dot(a, b));
  }

} // namespace

triangleWeights meanValueWeights(const SPoint3 &x0, const SPoint3 &x1,
                                 const SPoint3 &x2)
{
  const SPoint3 *x[3] = {&x0, &x1, &x2};
  triangleWeights w{};
  for(int i = 0; i < 3; i++) {
    int j = (i + 1) % 3, k = (i + 2) % 3;
    SVector3 ej(*x[i], *x[j]), ek(*x[i], *x[k]);
    double t = tanHalfAngle(ej, ek);
    // Eq. (14): the angle at i weighs both edges leaving i
    w[i][j] = t / ej.norm();
    w[i][k] = t / ek.norm();
  }
  return w;
}

patchMap meanValueMap(const discretePatch &patch)
{
  return diskMap(patch, meanValueWeights, sparseFactorization::lu);
}
} // namespace reparam

