// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Gmsh's triangles as the patch the maps take (Mesh/core/discretePatch.h),
// in a canonical order: the same triangles given in another order (the
// patch layout verifies a part, CreateGeometry later gets it in the order of
// Gmsh's flood fill) make the same patch, hence the same (u, v) to the last
// bit, and a map cached by the layout is found again.

#ifndef REPARAM_TRIANGLE_PATCH_H
#define REPARAM_TRIANGLE_PATCH_H

#include <array>
#include <vector>
#include "SPoint3.h"
#include "discretePatch.h"

class MTriangle;
class MVertex;

namespace reparam {

struct trianglePatch {
  // Gmsh's nodes in order of first appearance in the triangles (Gmsh's own
  // numbering for its outputs), their points, and the triangles on them
  std::vector<MVertex *> nodes;
  std::vector<SPoint3> points;
  std::vector<std::array<int, 3> > triangles;
  // canonical[i]: the patch's index of nodes[i] (nodes sorted by Gmsh's
  // number)
  std::vector<int> canonical;
  discretePatch patch; // on the canonical nodes, triangles by Gmsh number
  reparamError error; // makeDiscretePatch's verdict
};

trianglePatch patchOfTriangles(const std::vector<MTriangle *> &triangles);

// Gmsh's node of the patch's node `patchNode`
MVertex *nodeOfPatch(const trianglePatch &p, int patchNode);

} // namespace reparam

#endif
