// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// An edge named by the coordinates of its two ends, whatever their order:
// how the patch layout hands edges over to later stages (curve meshing,
// CreateGeometry) whose nodes are other objects at the same places.

#ifndef EDGE_BY_COORDINATES_H
#define EDGE_BY_COORDINATES_H

#include <array>
#include <tuple>
#include "SPoint3.h"

namespace reparam {

typedef std::array<double, 6> edgeByCoordinates;

inline edgeByCoordinates byCoordinates(const SPoint3 &a, const SPoint3 &b)
{
  const bool aFirst = std::make_tuple(a.x(), a.y(), a.z()) <
                      std::make_tuple(b.x(), b.y(), b.z());
  const SPoint3 &p = aFirst ? a : b, &q = aFirst ? b : a;
  return {{p.x(), p.y(), p.z(), q.x(), q.y(), q.z()}};
}

} // namespace reparam

#endif
