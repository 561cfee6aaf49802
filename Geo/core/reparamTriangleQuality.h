// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The shape quality (kappa, Eq. (3)) of Gmsh's triangles: what the report
// and the plugins measure on a meshed model.

#ifndef REPARAM_TRIANGLE_QUALITY_H
#define REPARAM_TRIANGLE_QUALITY_H

#include <vector>
#include "triangleQuality.h"

class MTriangle;

namespace reparam {

kappaStatistics computeKappaStatistics(const std::vector<MTriangle *> &t);

} // namespace reparam

#endif
