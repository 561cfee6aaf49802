// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The Fiedler vector of a weighted graph: the eigenvector of the second
// smallest eigenvalue of its Laplacian. Its level sets cut a patch where a
// cut is short compared with the parts it leaves (spectral bisection), and
// smoothly, not in METIS's zig-zags.

#ifndef FIEDLER_VECTOR_H
#define FIEDLER_VECTOR_H

#include <array>
#include <vector>
#include <Eigen/Core>
#include "reparamStatus.h"

namespace reparam {

struct fiedlerResult {
  reparamError error;
  Eigen::VectorXd x; // unit norm, orthogonal to the constant vector
  double lambda = 0.;
};

// Graph of n nodes, edges (i, j) with weights w > 0; it must be connected.
fiedlerResult fiedlerVector(int n, const std::vector<std::array<int, 2> > &edges,
                            const std::vector<double> &weights);

} // namespace reparam

#endif
