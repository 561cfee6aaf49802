// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The spectral conformal map (Sec. 4, Eq. 27-29, after Mullen et al.): the
// least squares conformal energy minimized with the boundary's barycenter at
// zero and its moment of inertia fixed, instead of two pins. Free boundary,
// less distortion than pinned LSCM on elongated patches.

#ifndef SPECTRAL_CONFORMAL_MAP_H
#define SPECTRAL_CONFORMAL_MAP_H

#include "discretePatch.h"
#include "patchMap.h"

namespace reparam {

struct spectralMapInfo {
  double lambda = 0.; // the eigenvalue, conformal energy per boundary moment
  int iterations = 0; // Lanczos restarts
  int solves = 0; // back substitutions
};

// The Fiedler vector of L_C U = lambda B U, B = 1 on the unknowns of every
// boundary node (all of them: no subsampling). Scaled so that the boundary
// nodes' root mean square distance to their barycenter is 1, like the unit
// circle of the convex maps.
patchMap spectralConformalMap(const discretePatch &patch,
                              spectralMapInfo *info = nullptr);

} // namespace reparam

#endif
