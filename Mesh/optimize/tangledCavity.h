// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// A triangle of a new surface mesh folded over its neighbours (pointing against
// the input under it) that no flip nor single node move turns back: the kernel
// of every corner's ring is empty, as where two nodes crossed each other
// (bench/README.md, Tangles), or its corners are all on curves. The cavity of
// the triangles around its movable corners and across its free edges (or,
// failing that, t and those across its free edges) is re-meshed as a fan from
// one new node, put in the kernel of the cavity's boundary seen in the input's
// tangent plane and projected on the input, or else as the triangulation of its
// boundary with the best worst triangle. Left where the boundary itself folds
// in that plane (the curve meshes on both sides of a strip narrower than the
// mesh size crossing).

#ifndef TANGLED_CAVITY_H
#define TANGLED_CAVITY_H

#include <array>
#include <cstddef>
#include <vector>
#include "SPoint3.h"
#include "SVector3.h"

namespace reparam {

class closestTriangleSearch;
struct optimizableMesh;
struct surfaceMesh;

// The plane of the input triangle closest to a point, as a frame at the
// point: e1 x e2 is the triangle's normal (turned over where `reversed`),
// so that the mesh triangles along the input turn counterclockwise in it
struct tangentFrame {
  SPoint3 origin;
  SVector3 e1, e2;
  std::array<double, 2> of(const SPoint3 &p) const
  {
    const SVector3 d(origin, p);
    return {{dot(d, e1), dot(d, e2)}};
  }
  SPoint3 at(double u, double w) const
  {
    const SVector3 d = e1 * u + e2 * w;
    return SPoint3(origin.x() + d.x(), origin.y() + d.y(), origin.z() + d.z());
  }
};
// false where there is no input or its closest triangle is degenerate
bool inputTangentFrame(const surfaceMesh &input,
                       const closestTriangleSearch &onInput,
                       const SPoint3 &origin, bool reversed,
                       tangentFrame &frame);

// The centroid (mean of the corners) of the kernel of a star or polygon in
// such a plane, the region from which every edge (ax, ay, bx, by) is seen
// on its left (Mesh/checks/flipRepair.h's starKernel); false if empty
bool kernelCentroid(const std::vector<std::array<double, 4> > &edges,
                    std::array<double, 2> &centroid);

// Re-meshes the cavity around each triangle of m marked against the input
// (optimizableMesh::against) whose boundary is one loop, with no locked
// edge inside, that can be meshed with no triangle against the input
// (reversed: m's triangles turn against the input's). Removes the
// cavities' points and triangles from m (optimizableMesh::origin and
// triangleOrigin tell which stay); `centers` (if given) gets the new
// nodes. Returns how many cavities.
std::size_t remeshTangledCavities(optimizableMesh &m, const surfaceMesh &input,
                                  const closestTriangleSearch &onInput,
                                  bool reversed,
                                  std::vector<int> *centers = nullptr);

} // namespace reparam

#endif
