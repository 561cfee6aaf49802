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
  // triangleOrder[k]: the triangle the patch has k-th (by Gmsh's number)
  std::vector<int> triangleOrder;
  discretePatch patch; // on the canonical nodes, triangles by Gmsh number
  reparamError error; // makeDiscretePatch's verdict
};

trianglePatch patchOfTriangles(const std::vector<MTriangle *> &triangles);

// The same patch made again from a face's arrays (the points and the
// triangles' node indices that the parametrization wrote, in its nodes'
// order) and the orders patchOfTriangles found: a face's map computed again
// once its triangles are gone (Geo/parametrize/reparamParametrizeAgain.h).
// Empty orders: the arrays' own. No Gmsh nodes (`nodes` stays empty).
trianglePatch patchOfArrays(const std::vector<SPoint3> &points,
                            const std::vector<int> &triangleNodes,
                            std::vector<int> canonical,
                            std::vector<int> triangleOrder);

// Gmsh's node of the patch's node `patchNode` (null without Gmsh's nodes)
MVertex *nodeOfPatch(const trianglePatch &p, int patchNode);

} // namespace reparam

#endif
