// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The causes of the poor triangles (kappa below 0.3) of a face's new mesh
// (Mesh/quality/poorTriangleCause.h), for the report.

#ifndef REPARAM_POOR_TRIANGLES_H
#define REPARAM_POOR_TRIANGLES_H

#include <array>
#include <cstddef>
#include "poorTriangleCause.h"

class GFace;

namespace reparam {

typedef std::array<std::size_t, numPoorTriangleCauses> poorTriangleCounts;

// How many triangles of gf below kappa 0.3 have each cause (indexed by
// poorTriangleCause); an edge lies on a curve when gf has one triangle on
// it or it is an edge of an embedded curve's mesh
poorTriangleCounts countPoorTriangleCauses(GFace *gf);

} // namespace reparam

#endif
