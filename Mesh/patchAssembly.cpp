// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <vector>
#include "patchAssembly.h"

Eigen::SparseMatrix<double>
assembleWeightedLaplacian(const discretePatch &patch,
                          const triangleWeightFunction &weights)
{
  const int n = (int)patch.points.size();
  std::vector<Eigen::Triplet<double> > entries;
  entries.reserve(9 * patch.triangles.size());
  for(const auto &tri : patch.triangles) {
    triangleWeights w = weights(patch.points[tri[0]], patch.points[tri[1]],
                                patch.points[tri[2]]);
    for(int i = 0; i < 3; i++) {
      double diagonal = 0.;
      for(int j = 0; j < 3; j++) {
        if(i == j) continue;
        entries.emplace_back(tri[i], tri[j], -w[i][j]);
        diagonal += w[i][j];
      }
      entries.emplace_back(tri[i], tri[i], diagonal);
    }
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(entries.begin(), entries.end()); // sums duplicates
  A.makeCompressed();
  return A;
}
