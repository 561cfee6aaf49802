// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// A cut of a part that pinches a side: a level set of the Fiedler vector can
// pass through a node twice, leaving the triangles of one side around that
// node in two fans that touch at the node only. That side's boundary then
// touches itself, no map flattens it as a disk, and the layout cut it again
// and again, each cut pinching the next part ("a node joins several
// boundary fans", level after level). The cut is moved instead: the
// smaller fans go to the other side, which they border across an edge.

#ifndef UNPINCH_CUT_H
#define UNPINCH_CUT_H

#include <array>
#include <vector>
#include "patchLayout.h"

namespace reparam {

struct triangleAdjacency;

// side[i] (0 or 1) of triangle part[i]: at every node where one side's
// triangles make several fans, all but the largest fan (by triangles) that
// border the other side across an edge move to it, until no such fan is
// left (a few rounds at most); returns how many fans moved. A fan that
// borders the other side nowhere stays (moved, it would be a part alone).
// `across`: the part's partNeighbours when the caller has them.
std::size_t
unpinchCut(const layoutMesh &mesh, const triangleAdjacency &adjacency,
           const std::vector<int> &part, std::vector<char> &side,
           const std::vector<std::array<int, 3> > *across = nullptr);

// A part whose own boundary touches itself at a node (its triangles make
// several fans there: a patch pinched by a merge or by the input) fails
// whatever its map; cut at random it stays pinched in one half. Its sides
// instead: the largest fan at the first such node and every triangle
// nearer to it than to the other fans (in triangles across edges) on side
// 0, the rest on side 1, then unpinchCut; empty when no node is pinched.
std::vector<char>
separateFansAtPinch(const layoutMesh &mesh, const triangleAdjacency &adjacency,
                    const std::vector<int> &part,
                    const std::vector<std::array<int, 3> > *across = nullptr);

} // namespace reparam

#endif
