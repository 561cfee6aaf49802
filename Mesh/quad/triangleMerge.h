// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Pairs of triangles merged into quadrangles. Blossom's recombination leaves
// the triangles it could not pair well in the parametric plane; after the
// quadrangles are squared up on the input (Mesh/quad/quadNodeSmoothing.h)
// some of those neighbours make a fair quadrangle in 3D, and every pair
// merged is two triangles fewer (bench/README.md#triangles-left-merged).

#ifndef TRIANGLE_MERGE_H
#define TRIANGLE_MERGE_H

#include <array>
#include <set>
#include <utility>
#include <vector>

namespace reparam {

struct surfaceMesh;

struct triangleMerge {
  int first, second; // triangles of the mesh
  // their four corners in the triangles' orientation: first's corners with
  // second's opposite one between the ends of their common edge
  std::array<int, 4> quadrangle;
  double eta;
};

// The pairs of m's triangles sharing an edge not in `locked` (pairs i < j:
// the 1D meshes' segments) whose quadrangle reaches eta minEta, best first,
// each triangle in one pair at most; only pairs running the same way along
// their common edge (consistently oriented)
std::vector<triangleMerge>
triangleMerges(const surfaceMesh &m,
               const std::set<std::pair<int, int> > &locked, double minEta);

} // namespace reparam

#endif
