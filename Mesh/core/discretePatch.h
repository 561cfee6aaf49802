// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// A triangulated patch to be parametrized: nodes, triangles and what the maps
// need of its topology (edges, boundary loops). Built once, read by every
// map, check and repair.

#ifndef DISCRETE_PATCH_H
#define DISCRETE_PATCH_H

#include <array>
#include <vector>
#include "SPoint3.h"
#include "reparamStatus.h"
#include "surfaceMesh.h"

namespace reparam {

// The nodes and triangles (no quadrangles), the triangles all oriented
// alike (makeDiscretePatch reorients the ones that disagree with the first)
struct discretePatch : surfaceMesh {
  // Unique edges (lo, hi), lo < hi, sorted
  std::vector<std::array<int, 2> > edges;
  // triangleEdges[t][k]: the edge of nodes k and k + 1 (mod 3) of triangle t
  std::vector<std::array<int, 3> > triangleEdges;
  std::size_t numReorientedTriangles = 0;
  // Cycles of node indices (first != last) with the patch on the left of
  // every edge, i.e. counterclockwise around the patch for its orientation
  std::vector<std::vector<int> > boundaryLoops;
  // The longest loop: the one mapped onto the unit circle
  int outerLoop = -1;

  int eulerCharacteristic() const
  {
    return (int)points.size() - (int)edges.size() + (int)triangles.size();
  }
  // Of a connected patch with boundaryLoops.size() boundaries
  int genus() const
  {
    return (2 - (int)boundaryLoops.size() - eulerCharacteristic()) / 2;
  }
};

// Builds the patch and checks the preconditions every map shares: finite
// coordinates, no degenerate triangle, manifold, one component, orientable.
// Closed and genus > 0 patches are built (their loops are valid) but flagged
// with noBoundary / notDiskTopology, which maps on a disk reject.
reparamError makeDiscretePatch(std::vector<SPoint3> points,
                               std::vector<std::array<int, 3> > triangles,
                               discretePatch &patch);

// Length of boundary loop `loop` in 3D
double boundaryLoopLength(const discretePatch &patch, int loop);

// Twice the signed area of the triangle (a, b, c) of the plane
inline double signedArea2(double ax, double ay, double bx, double by,
                          double cx, double cy)
{
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

} // namespace reparam

#endif
