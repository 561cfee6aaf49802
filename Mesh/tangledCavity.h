// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// A triangle of a new surface mesh folded over its neighbours (pointing
// against the input under it) that no flip nor single node move turns
// back: the kernel of every corner's ring is empty, as where two nodes
// crossed each other (aneurysm: one triangle next to a cut, its three
// corners tangled). The cavity of the triangles around its movable corners
// is re-meshed as a fan from one new node, put in the kernel of the
// cavity's boundary seen in the input's tangent plane and projected on the
// input.

#ifndef TANGLED_CAVITY_H
#define TANGLED_CAVITY_H

#include <cstddef>
#include <vector>

class closestTriangleSearch;
struct optimizableMesh;
struct surfaceMesh;

// Re-meshes the cavity around each triangle of m marked against the input
// (optimizableMesh::against) whose boundary is one loop free of locked
// edges inside, with a kernel, and whose fan leaves no triangle against
// the input (reversed: m's triangles turn against the input's). Removes the
// cavities' points and triangles from m (optimizableMesh::origin and
// triangleOrigin tell which stay); `centers` (if given) gets the new
// nodes. Returns how many cavities.
std::size_t remeshTangledCavities(optimizableMesh &m, const surfaceMesh &input,
                                  const closestTriangleSearch &onInput,
                                  bool reversed,
                                  std::vector<int> *centers = nullptr);

#endif
