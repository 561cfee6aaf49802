// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <vector>
#include "conformalAssembly.h"
#include "harmonicMap.h"
#include "patchAssembly.h"

Eigen::SparseMatrix<double> assembleConformalEnergy(const discretePatch &patch)
{
  // The stiffness matrix of one coordinate, expanded to both: column j of A
  // gives columns 2j (rows 2i) and 2j + 1 (rows 2i + 1), rows staying sorted
  Eigen::SparseMatrix<double> A =
    assembleWeightedLaplacian(patch, cotangentWeights);
  const int n = (int)A.rows();
  Eigen::SparseMatrix<double> D(2 * n, 2 * n);
  D.resizeNonZeros(2 * A.nonZeros());
  int *outer = D.outerIndexPtr(), *inner = D.innerIndexPtr();
  double *value = D.valuePtr();
  int k = 0;
  outer[0] = 0;
  for(int j = 0; j < n; j++) {
    for(int c = 0; c < 2; c++) {
      for(Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) {
        inner[k] = 2 * (int)it.row() + c;
        value[k++] = it.value();
      }
      outer[2 * j + c + 1] = k;
    }
  }

  // Area of the image: sum over boundary edges a -> b (the patch on their
  // left) of (u_a v_b - u_b v_a) / 2, entering E_LSCM with a minus sign
  std::vector<Eigen::Triplet<double> > area;
  for(const auto &loop : patch.boundaryLoops) {
    for(std::size_t i = 0; i < loop.size(); i++) {
      int a = loop[i], b = loop[(i + 1) % loop.size()];
      area.emplace_back(2 * a, 2 * b + 1, -0.5);
      area.emplace_back(2 * b + 1, 2 * a, -0.5);
      area.emplace_back(2 * b, 2 * a + 1, 0.5);
      area.emplace_back(2 * a + 1, 2 * b, 0.5);
    }
  }
  Eigen::SparseMatrix<double> C(2 * n, 2 * n);
  C.setFromTriplets(area.begin(), area.end());
  return D + C;
}

double dirichletEnergy(const discretePatch &patch, const std::vector<double> &uv)
{
  double energy = 0.;
  for(const auto &t : patch.triangles) {
    triangleWeights w = cotangentWeights(patch.points[t[0]],
                                         patch.points[t[1]],
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
