// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// A triangle of a new surface mesh folded over its neighbours (pointing
// against the input under it) that no flip nor single node move turns
// back: the kernel of every corner's ring is empty, as where two nodes
// crossed each other (aneurysm: one triangle next to a cut, its three
// corners tangled), or its corners are all on curves. The cavity of the
// triangles around its movable corners and across its free edges (or,
// failing that, t and those across its free edges) is re-meshed as a fan
// from one new node, put in the kernel of the cavity's boundary seen in the
// input's tangent plane and projected on the input, or else as the
// triangulation of its boundary with the best worst triangle. Left where
// the boundary itself folds in that plane (the curve meshes on both sides
// of a strip narrower than the mesh size crossing: pelvis_tlem2, adis16480).

#ifndef TANGLED_CAVITY_H
#define TANGLED_CAVITY_H

#include <cstddef>
#include <vector>

class closestTriangleSearch;
struct optimizableMesh;
struct surfaceMesh;

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

#endif
