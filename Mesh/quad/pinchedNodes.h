// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Nodes pinched between two elements: a node m of exactly two elements,
// each of which has both of m's edges, (a, m) and (m, b). Gmsh's
// recombination leaves one now and then (a triangle of three nodes in a
// row on a cut, folded onto the quadrangle across it; or two triangles
// around an inner node, the one lying on the other, their edge (a, b) used
// four times: bench/README.md#pinched-nodes). Without m the surface keeps
// its shape: each of the two elements loses its corner m, a quadrangle
// becoming a triangle and a triangle a segment, which goes.

#ifndef PINCHED_NODES_H
#define PINCHED_NODES_H

#include <array>
#include <vector>

namespace reparam {

struct surfaceMesh;

struct pinchedNode {
  int node; // m
  // the two elements: indices into the mesh's triangles, then quadrangles
  // (element i >= triangles.size() is quadrangle i - triangles.size())
  std::array<int, 2> elements;
  // what is left of them: the quadrangles' three other corners, in their
  // order (0, 1 or 2 triangles), and which element each came from
  std::vector<std::array<int, 3> > triangles;
  std::vector<int> from;
};

// The pinched nodes of m among the removable ones, none two of which share
// an element
std::vector<pinchedNode> pinchedNodes(const surfaceMesh &m,
                                      const std::vector<bool> &removable);

} // namespace reparam

#endif
