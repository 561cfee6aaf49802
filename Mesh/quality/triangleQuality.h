// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Shape quality of triangles (Sec. 1 of the paper).

#ifndef TRIANGLE_QUALITY_H
#define TRIANGLE_QUALITY_H

#include <cstddef>
#include <vector>
#include "SPoint3.h"

namespace reparam {

// Eq. (3): kappa = 4 sin a sin b sin c / (sin a + sin b + sin c); 1 for the
// equilateral triangle, 0 for a flat one
double triangleKappa(const SPoint3 &p0, const SPoint3 &p1, const SPoint3 &p2);

// Below this kappa (sides about 100 times their distance apart) a triangle
// is a sliver, no better than a fold: no repair makes one (a tangle's
// cavity, Mesh/optimize/tangledCavity.cpp), and an input of such triangles is given
// to no face in place of its mesh (Geo/optimize/reparamOverlappingFaces.cpp)
const double sliverKappa = 0.01;

// Of a set of triangles (Geo/core/reparamTriangleQuality.h for Gmsh's)
struct kappaStatistics {
  std::size_t triangles = 0;
  double min = 0., mean = 0.;
  double shareBelow03 = 0.; // fraction of triangles with kappa < 0.3
};

} // namespace reparam

#endif
