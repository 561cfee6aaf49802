// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Input nodes a new surface mesh cuts off, inserted into it: a crease just
// below the feature angle, or the sharp edges of a sliver patch the layout
// merged as noise (a step, a ridge) put the input's Hausdorff point at 0.35-0.7
// of the mesh size from the mesh, where a smooth surface of curvature radius R
// stays within h^2 / (8 R). Each such node is inserted where the mesh passes
// closest to it: into that triangle (split in three) or onto that edge (split
// with both its triangles), so the mesh passes through it. A new node next to a
// node of the mesh would make a short edge, and the triangles around it poor
// (bench/README.md, Optimization on the input): an inner node that near is
// moved onto the input node instead, and next to a node that may not move (a
// curve's) the input node is left out, the mesh passing within that distance of
// it already.

#ifndef FAR_INPUT_NODES_H
#define FAR_INPUT_NODES_H

#include <cstddef>
#include "optimizableMesh.h"

namespace reparam {

class closestTriangleSearch;

// Inserts into m the inner nodes of `input` (not on its boundary) farther
// from m than `share` times the mean edge of m's closest triangle, farthest
// first, at most one per triangle and its neighbours, only where none of the
// new triangles points against the input (reversed: m's triangles turn
// against the input's); they are not movable. A corner of that closest
// triangle nearer to the input node than 0.4 of its mean edge moves there
// instead if movable (where its triangles stay above kappa 0.2 and the new
// node's would be no better), and is not movable then; if not movable, the
// input node is left out. Returns how many input nodes the mesh now passes
// through, `moved` of them by a node moved there
std::size_t insertFarInputNodes(optimizableMesh &m, const surfaceMesh &input,
                                const closestTriangleSearch &onInput,
                                bool reversed, double share,
                                std::size_t *moved = nullptr);

} // namespace reparam

#endif
