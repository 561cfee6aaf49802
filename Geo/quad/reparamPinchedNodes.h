// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The pinched nodes (Mesh/quad/pinchedNodes.h) Gmsh's recombination leaves in
// the quadrangle meshes of Reparam's faces, removed: an element folded
// onto its neighbour there points against the input (a triangle of three
// nodes of a cut), or two triangles lie on each other (an edge of four
// triangles; bench/README.md, Pinched nodes).

#ifndef REPARAM_PINCHED_NODES_H
#define REPARAM_PINCHED_NODES_H

#include <cstddef>
#include <set>
#include <vector>

class GEdge;
class GFace;

namespace reparam {

// Removes the pinched nodes of the faces' meshes among their inner nodes
// and the nodes of `cuts` (curves the mesh may cross whose faces are all
// among `faces`): the elements around each lose it, a quadrangle becoming a
// triangle (kept only if it points the way the quadrangle did), a triangle
// going; the cut's two segments at it become one. Changed faces are added
// to `changed`; returns how many nodes went
std::size_t reparamRemovePinchedNodes(const std::vector<GFace *> &faces,
                                      const std::set<GEdge *> &cuts,
                                      std::set<GFace *> &changed);

} // namespace reparam

#endif
