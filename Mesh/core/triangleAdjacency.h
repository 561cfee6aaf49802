// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The edges of a triangulation (any: non-manifold, several components) and
// the triangles around each: what the patch layout walks to grow, clean and
// cut patches.

#ifndef TRIANGLE_ADJACENCY_H
#define TRIANGLE_ADJACENCY_H

#include <array>
#include <vector>

namespace reparam {

struct triangleAdjacency {
  // Unique edges (lo, hi), lo < hi, sorted
  std::vector<std::array<int, 2> > edges;
  // triangleEdges[t][k]: the edge of nodes k and k + 1 (mod 3) of triangle t
  std::vector<std::array<int, 3> > triangleEdges;
  // The triangles of edge e: edgeTriangles[edgeStart[e] .. edgeStart[e + 1])
  std::vector<int> edgeStart, edgeTriangles;

  int numTriangles(int e) const { return edgeStart[e + 1] - edgeStart[e]; }
  // Across a manifold edge (two triangles) the other triangle; -1 across a
  // boundary or non-manifold edge
  int across(int e, int t) const
  {
    if(numTriangles(e) != 2) return -1;
    int a = edgeTriangles[edgeStart[e]], b = edgeTriangles[edgeStart[e] + 1];
    return a == t ? b : a;
  }
  // The edge (lo, hi), or -1
  int find(int a, int b) const;
};

triangleAdjacency
makeTriangleAdjacency(const std::vector<std::array<int, 3> > &triangles);

// For each triangle part[i] of a mesh of numTriangles triangles, the index
// in `part` of the triangle across each of its edges (k: nodes k and k + 1),
// -1 across a boundary or non-manifold edge or where that triangle is not
// in the part. Costs the part's size, not the mesh's: the layout asks it of
// parts of a few triangles on meshes of a million.
std::vector<std::array<int, 3> >
partNeighbours(const triangleAdjacency &adjacency, const std::vector<int> &part,
               std::size_t numTriangles);

} // namespace reparam

#endif
