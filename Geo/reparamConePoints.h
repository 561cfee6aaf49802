// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The tips of a discrete face (Mesh/conePoints.h) kept as mesh nodes: each
// becomes a model point embedded in the face when CreateGeometry has
// parametrized it, so that Gmsh's planar meshers put a node there.

#ifndef REPARAM_CONE_POINTS_H
#define REPARAM_CONE_POINTS_H

#include <vector>
#include "SPoint3.h"

class GFace;
class MVertex;

// gf's input nodes (as CreateGeometry parametrized them), their points and
// its triangles (3 node indices each): the nodes whose angles sum to less
// than pi (sharper than a cone of half-angle 30 degrees) become points
// embedded in gf; returns how many were added
int reparamEmbedConePoints(GFace *gf, const std::vector<MVertex *> &nodes,
                           const std::vector<SPoint3> &points,
                           const std::vector<int> &triangleNodes);

#endif
