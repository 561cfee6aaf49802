// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <vector>
#include "patchAssembly.h"

namespace reparam {

namespace {

  // Where each entry of the node-to-node pattern (one per edge, both ways,
  // plus the diagonal) lives in the compressed column storage of A
  struct laplacianLayout {
    std::vector<int> diagonal; // of node j, in column j
    std::vector<int> lowHigh; // A(lo, hi) of edge e, in column hi
    std::vector<int> highLow; // A(hi, lo) of edge e, in column lo
  };

  // Builds the pattern of A directly (no triplets to sort): column j holds
  // the rows of its neighbours below j, then j, then those above j; scanning
  // the (lo, hi)-sorted edges fills each part in increasing row order
  laplacianLayout makePattern(const discretePatch &patch,
                              Eigen::SparseMatrix<double> &A)
  {
    const int n = (int)patch.points.size();
    const int ne = (int)patch.edges.size();
    std::vector<int> below(n, 0), above(n, 0);
    for(const auto &e : patch.edges) {
      below[e[1]]++;
      above[e[0]]++;
    }
    A.resize(n, n);
    A.resizeNonZeros(n + 2 * ne);
    int *outer = A.outerIndexPtr(), *inner = A.innerIndexPtr();
    laplacianLayout layout;
    layout.diagonal.resize(n);
    layout.lowHigh.resize(ne);
    layout.highLow.resize(ne);
    std::vector<int> nextBelow(n), nextAbove(n);
    outer[0] = 0;
    for(int j = 0; j < n; j++) {
      outer[j + 1] = outer[j] + below[j] + 1 + above[j];
      nextBelow[j] = outer[j];
      layout.diagonal[j] = outer[j] + below[j];
      inner[layout.diagonal[j]] = j;
      nextAbove[j] = layout.diagonal[j] + 1;
    }
    for(int e = 0; e < ne; e++) {
      int lo = patch.edges[e][0], hi = patch.edges[e][1];
      layout.lowHigh[e] = nextBelow[hi]++;
      inner[layout.lowHigh[e]] = lo;
      layout.highLow[e] = nextAbove[lo]++;
      inner[layout.highLow[e]] = hi;
    }
    std::fill(A.valuePtr(), A.valuePtr() + A.nonZeros(), 0.);
    return layout;
  }

} // namespace

Eigen::SparseMatrix<double>
assembleWeightedLaplacian(const discretePatch &patch,
                          const triangleWeightFunction &weights)
{
  Eigen::SparseMatrix<double> A;
  laplacianLayout layout = makePattern(patch, A);
  double *value = A.valuePtr();
  for(std::size_t t = 0; t < patch.triangles.size(); t++) {
    const auto &tri = patch.triangles[t];
    triangleWeights w = weights(patch.points[tri[0]], patch.points[tri[1]],
                                patch.points[tri[2]]);
    for(int i = 0; i < 3; i++) {
      for(int k = 1; k < 3; k++) {
        int j = (i + k) % 3;
        // the edge of local nodes i and j is side i (j = i + 1) or side j
        int e = patch.triangleEdges[t][k == 1 ? i : j];
        value[tri[i] < tri[j] ? layout.lowHigh[e] : layout.highLow[e]] -=
          w[i][j];
        value[layout.diagonal[tri[i]]] += w[i][j];
      }
    }
  }
  return A;
}
} // namespace reparam

