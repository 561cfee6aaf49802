// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// What every map returns: (u, v) per node of the patch, a status, and the
// time of its stages for the log.

#ifndef PATCH_MAP_H
#define PATCH_MAP_H

#include <vector>
#include "reparamStatus.h"

namespace reparam {

struct patchMap {
  reparamError error;
  std::vector<double> uv; // u_i = uv[2i], v_i = uv[2i + 1]
  double assembleTime = 0.; // wall seconds
  double solveTime = 0.;
};

} // namespace reparam

#endif
