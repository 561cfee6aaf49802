// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The least squares conformal energy (Eq. 17, 22) E_LSCM = E_D - A: the
// Dirichlet energy of u and v minus the area of the image, as one sparse
// matrix over interleaved unknowns (u_0, v_0, u_1, v_1, ...).

#ifndef CONFORMAL_ASSEMBLY_H
#define CONFORMAL_ASSEMBLY_H

#include <Eigen/SparseCore>
#include "discretePatch.h"

// L_C (2n x 2n, symmetric positive semi-definite) with E_LSCM = X^T L_C X / 2:
// the stiffness matrix on the u-u and v-v blocks, and the area term, which
// only boundary edges keep (the triangles' contributions cancel on interior
// edges), on the u-v blocks. Images oriented like the patch's triangles have
// positive area, so minimizers preserve the orientation.
Eigen::SparseMatrix<double> assembleConformalEnergy(const discretePatch &patch);

// The Dirichlet energy and the signed image area of a map: what L_C
// encodes, computed triangle by triangle (for checks and tests)
double dirichletEnergy(const discretePatch &patch, const std::vector<double> &uv);
double imageArea(const discretePatch &patch, const std::vector<double> &uv);

#endif
