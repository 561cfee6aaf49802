// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The least squares conformal energy (Eq. 17, 22) E_LSCM = E_D - A: the
// Dirichlet energy of u and v minus the area of the image, as one sparse
// Hermitian matrix over the complex unknowns z = u + i v.

#ifndef CONFORMAL_ASSEMBLY_H
#define CONFORMAL_ASSEMBLY_H

#include <complex>
#include <Eigen/SparseCore>
#include "discretePatch.h"

namespace reparam {

// H (n x n, Hermitian positive semi-definite) with E_LSCM = z^H H z / 2:
// H = A + i S, A the stiffness matrix and S the antisymmetric area term,
// which only boundary edges keep (the triangles' contributions cancel on
// interior edges). Its real form [A -S; S A] over (u, v) is the paper's
// 2n x 2n L_C; the complex form has the pattern of A, and its Cholesky
// factor costs half of L_C's (0.68 s against 1.5 s on 50k nodes). Images
// oriented like the patch's triangles have positive area, so minimizers
// preserve the orientation.
Eigen::SparseMatrix<std::complex<double> >
assembleConformalEnergy(const discretePatch &patch);

// The Dirichlet energy and the signed image area of a map: what L_C
// encodes, computed triangle by triangle (for checks and tests)
double dirichletEnergy(const discretePatch &patch,
                       const std::vector<double> &uv);
double imageArea(const discretePatch &patch, const std::vector<double> &uv);

} // namespace reparam

#endif
