// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The tips of a discrete face (Mesh/layout/conePoints.h) and the corners of its
// sharp edges the patch layout merged away as noise (a spike of a scan:
// three sharp edges meeting inside the face) kept as mesh nodes: each
// becomes a model point embedded in the face when CreateGeometry has
// parametrized it, so that Gmsh's planar meshers put a node there.

#ifndef REPARAM_CONE_POINTS_H
#define REPARAM_CONE_POINTS_H

#include <array>
#include <vector>
#include "SPoint3.h"

class GFace;
class MVertex;

namespace reparam {

// The sharp edges of the last patch layout that no longer bound a patch
// (merged into one as noise), by their end points, and the mesh size the
// layout measured noise with
void reparamRecordMergedCreases(const std::vector<std::array<SPoint3, 2> > &edges,
                                double size);
// Whether (a, b) is one of those edges; the layout's noise size
bool reparamIsMergedCrease(const SPoint3 &a, const SPoint3 &b);
double reparamLayoutNoiseSize();

// gf's input nodes (as CreateGeometry parametrized them), their points and
// its triangles (3 node indices each): the nodes whose angles sum to less
// than pi (sharper than a cone of half-angle 30 degrees) and those where
// three merged sharp edges or more meet, at least half the layout's size
// from gf's curves and from each other, become points embedded in gf;
// returns how many were added
int reparamEmbedConePoints(GFace *gf, const std::vector<MVertex *> &nodes,
                           const std::vector<SPoint3> &points,
                           const std::vector<int> &triangleNodes);

} // namespace reparam

#endif
