// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <vector>
#include "conformalAssembly.h"
#include "harmonicMap.h"
#include "patchAssembly.h"

namespace reparam {

Eigen::SparseMatrix<std::complex<double> >
assembleConformalEnergy(const discretePatch &patch)
{
  Eigen::SparseMatrix<std::complex<double> > H =
    assembleWeightedLaplacian(patch, cotangentWeights)
      .cast<std::complex<double> >();
  // Area of the image: sum over boundary edges a -> b (the patch on their
  // left) of (u_a v_b - u_b v_a) / 2 = Im(conj(z_a) z_b) / 2, entering
  // E_LSCM with a minus sign. Boundary edges are edges of the pattern: no
  // insertion.
  const std::complex<double> half(0., 0.5);
  for(const auto &loop : patch.boundaryLoops) {
    for(std::size_t i = 0; i < loop.size(); i++) {
      int a = loop[i], b = loop[(i + 1) % loop.size()];
      H.coeffRef(a, b) += half;
      H.coeffRef(b, a) -= half;
    }
  }
  return H;
}

double dirichletEnergy(const discretePatch &patch,
                       const std::vector<double> &uv)
{
  double energy = 0.;
  for(const auto &t : patch.triangles) {
    triangleWeights w = cotangentWeights(patch.points[t[0]], patch.points[t[1]],
                                         patch.points[t[2]]);
    // E_D = 1/2 sum over edges of w_ij |u_i - u_j|^2
    for(int i = 0; i < 3; i++) {
      int j = (i + 1) % 3;
      double du = uv[2 * t[i]] - uv[2 * t[j]];
      double dv = uv[2 * t[i] + 1] - uv[2 * t[j] + 1];
      energy += 0.5 * w[i][j] * (du * du + dv * dv);
    }
  }
  return energy;
}

double imageArea(const discretePatch &patch, const std::vector<double> &uv)
{
  double area2 = 0.;
  for(const auto &t : patch.triangles)
    area2 += signedArea2(uv[2 * t[0]], uv[2 * t[0] + 1], uv[2 * t[1]],
                         uv[2 * t[1] + 1], uv[2 * t[2]], uv[2 * t[2] + 1]);
  return 0.5 * area2;
}
} // namespace reparam

