// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Edge rotations that make a mesh of quadrangles more regular. Node moves
// (Mesh/quad/quadNodeSmoothing.h) cannot change how many quadrangles meet at a
// node, and a quadrangle at an inner node of valence 3 or 5 has a corner of
// 120 or 72 degrees at best (eta 0.67 or 0.8), and Frontal-Delaunay for
// quads and Blossom leave many such nodes (bench/README.md#irregular-nodes).
// Two quadrangles sharing an edge make a hexagon; rotating the edge
// to one of the hexagon's two other diagonals takes a quadrangle from each
// end of the old edge and gives one to each end of the new, so an edge
// between two nodes of valence 5 can move to two nodes of valence 3, and an
// irregular node can walk towards another of opposite sign.

#ifndef QUAD_EDGE_ROTATION_H
#define QUAD_EDGE_ROTATION_H

#include <cmath>
#include <set>
#include <utility>
#include <vector>

namespace reparam {

class closestTriangleSearch;
struct surfaceMesh;

struct quadRotationOptions {
  // both new quadrangles at least this eta (the node moves after only
  // better them) ...
  double minEta = 0.3;
  // ... and their normals (the cross product of their diagonals) within
  // this angle of the old pair's (radians): no fold across the input
  double maxTurn = M_PI / 6.;
  int maxPasses = 8;
  // the input surface the mesh lies on (searched by onInput; both null: not
  // checked): the new diagonal's midpoint no farther from it than the old
  // one's, or than `tolerance` times the new diagonal's length (a diagonal
  // across a crease or a tip cuts it off), and each new quadrangle on the
  // same side of the input under its centre as the old pair was
  const surfaceMesh *input = nullptr;
  const closestTriangleSearch *onInput = nullptr;
  double tolerance = 0.02;
};

struct quadRotationResult {
  std::size_t rotations = 0;
  // inner nodes (elements closed around them) of valence other than 4
  std::size_t irregularBefore = 0, irregularAfter = 0;
  int passes = 0;
};

// Per point of m, the valence it would have in a mesh of squares: 4 where
// m's elements close around it, else one more than its corners' angles
// summed over a right angle, rounded (3 on a straight border, 2 at a right
// corner), at least 2
std::vector<int> idealValences(const surfaceMesh &m);

// Per point of m, how many other points it shares an element edge with
std::vector<int> valences(const surfaceMesh &m);

// Per point of m, whether its elements close around it (each side from it
// shared by two elements); a point of no element does not
std::vector<bool> closedRings(const surfaceMesh &m);

// How many inner nodes of m (closedRings) have a valence other than 4
std::size_t irregularNodes(const surfaceMesh &m);

// Rotates edges between two quadrangles of m, pass after pass until none
// is rotated or o.maxPasses are done, where the squared distance of the
// four nodes' valences to their ideal (idealValences, computed before the
// first pass) falls, the new diagonal joins no two nodes joined already,
// and the new quadrangles pass o's tests. Only edges not in `locked`
// (pairs i < j: the 1D meshes' segments) between quadrangles of the same
// part (`part`, per quadrangle; empty: all one part) rotate; triangles stay
// as they are. The quadrangles keep their orientation and their places in
// m.quadrangles
quadRotationResult rotateQuadEdges(surfaceMesh &m, const std::vector<int> &part,
                                   const std::set<std::pair<int, int> > &locked,
                                   const quadRotationOptions &o = {});

} // namespace reparam

#endif
