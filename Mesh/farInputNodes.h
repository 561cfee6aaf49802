// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Input nodes a new surface mesh cuts off, inserted into it: a crease just
// below the feature angle (gmsh2x_implant: 39 degrees, cut at 0.39 h), or
// the sharp edges of a sliver patch the layout merged as noise (a step, a
// ridge of the skull) put the input's Hausdorff point at 0.35-0.7 of the
// mesh size from the mesh, where a smooth surface of curvature radius R
// stays within h^2 / (8 R). Each such node is inserted where the mesh passes
// closest to it: into that triangle (split in three) or onto that edge
// (split with both its triangles), so the mesh passes through it.

#ifndef FAR_INPUT_NODES_H
#define FAR_INPUT_NODES_H

#include <cstddef>

class closestTriangleSearch;
struct optimizableMesh;
struct surfaceMesh;

// Inserts into m the inner nodes of `input` (not on its boundary) farther
// from m than `share` times the mean edge of m's closest triangle, farthest
// first, at most one per triangle and its neighbours, only where none of the
// new triangles points against the input (reversed: m's triangles turn
// against the input's); they are not movable. Returns how many
std::size_t insertFarInputNodes(optimizableMesh &m, const surfaceMesh &input,
                                const closestTriangleSearch &onInput,
                                bool reversed, double share);

#endif
