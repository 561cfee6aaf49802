// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The triangles of one or several meshed discrete faces as the
// optimizableMesh of Mesh/optimize/optimizableMesh.h, and what the optimizer
// needs to know of them: which nodes may move, which edges stay, the mesh
// size asked at each node, and which way the triangles turn on the input.
// Used for one face (Geo/optimize/reparamOptimizeFace.cpp) and for the faces a patch
// was cut into (Geo/optimize/reparamOptimizeAcrossCuts.cpp).

#ifndef REPARAM_OPTIMIZABLE_MESH_H
#define REPARAM_OPTIMIZABLE_MESH_H

#include <functional>
#include <vector>
#include "optimizableMesh.h"

class GEdge;
class GFace;
class MVertex;

namespace reparam {
class closestTriangleSearch;
struct surfaceMesh;

// The triangles of `faces`, those of faces[f] turned over where reverse[f]
// (so that all turn the same way); nodes[i] is point i's node and
// triangleFace[t] the index in `faces` of triangle t's face. movable(v)
// tells whether node v may move; the edges of the faces' embedded curves
// and of lockedCurves are never flipped.
optimizableMesh optimizableMeshOf(
  const std::vector<GFace *> &faces, const std::vector<bool> &reverse,
  const std::function<bool(const MVertex *)> &movable,
  const std::vector<GEdge *> &lockedCurves, std::vector<MVertex *> &nodes,
  std::vector<int> &triangleFace);

// Whether the optimizers may change gf's triangles after it was meshed: a
// discrete face Reparam parametrized, meshed with triangles only, not kept
// as its input
bool reparamOptimizableFace(const GFace *gf);

// Whether most elements of gf's mesh turn against the input (searched by
// onInput, built on it; a quadrangle by its first three corners), counted
// on at most about a hundred of them: a planar mesh is consistently
// oriented
bool meshReversedOnInput(const GFace *gf, const surfaceMesh &input,
                         const closestTriangleSearch &onInput);

} // namespace reparam

#endif
