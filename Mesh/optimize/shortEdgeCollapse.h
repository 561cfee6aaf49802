// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Inner edges of a new surface mesh much shorter than the mesh size asked
// there, collapsed. The planar mesher sizes a face by its boundary too
// (Mesh.MeshSizeExtendFromBoundary: the size interpolated from the curves'
// segments), so that the short segments of the layout's many curves make
// whole faces finer than asked, their edges off the size (bench/README.md,
// Optimization on the input).

#ifndef SHORT_EDGE_COLLAPSE_H
#define SHORT_EDGE_COLLAPSE_H

#include <cstddef>
#include <vector>
#include "optimizableMesh.h"

namespace reparam {

class closestTriangleSearch;

// Collapses the inner edges of m (not locked) shorter than `ratio` times the
// mean of optimizableMesh::size at their ends, shortest first: a movable end
// onto the other, or both movable ends onto the input point closest to the
// edge's midpoint. Kept only where the triangles around stay manifold (the
// ends share exactly the two opposite corners), turn by less than 45
// degrees, have no edge longer than 1.4 times the size, a worst kappa no
// lower than before unless both are above 0.6, pass within `tolerance`
// times the size of the point removed and of the input nodes around (or no
// farther than the old triangles did), and none points against the input
// (reversed: m's triangles turn against the input's). Removes the collapsed
// points and triangles from m (optimizableMesh::origin and triangleOrigin
// tell which stay). Returns how many edges; `kept` (if given) gets the
// points the collapsed edges became, to smooth around
std::size_t collapseShortEdges(optimizableMesh &m, const surfaceMesh &input,
                               const closestTriangleSearch &onInput,
                               bool reversed, double ratio, double tolerance,
                               std::vector<int> *kept = nullptr);

} // namespace reparam

#endif
