// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Reparam's patch layout inside Gmsh: the parameters it takes from the
// options and the input, and the verification of a part by the
// parametrization CreateGeometry will compute. The hook itself,
// reparamLayoutPatches, is declared in Gmsh's Geo/GModelParametrize.h
// (patches/0006).

#ifndef REPARAM_LAYOUT_H
#define REPARAM_LAYOUT_H

#include <vector>
#include "SPoint2.h"
#include "SPoint3.h"
#include "patchLayout.h"
#include "reparamParametrize.h"

class MTriangle;

class MVertex;

namespace reparam {

// A part is cut when its map puts a triangle's share of the (u, v) area
// below this fraction of its share of the 3D area
const double reparamMinCrowding = 1e-4;

// A part is cut when its area is more than this many times the area of the
// flat disk its boundary would bound (a hemisphere: 2)
const double reparamMaxLargeness = 4.;

// Area of a triangulation (triangleNodes: 3 node indices per triangle) and
// length of its boundary (edges of one triangle, all loops)
void areaAndBoundaryLength(const std::vector<SPoint3> &xyz,
                           const std::vector<int> &triangleNodes, double &area,
                           double &length);

// Area over that of the disk with the boundary's length (all loops): 1 for
// a flat disk, 2 for a hemisphere, large for a tube closed at one end
double boundaryLargeness(const std::vector<SPoint3> &xyz,
                         const std::vector<int> &triangleNodes);

// Smallest ratio, over the triangles, of their share of the (u, v) area to
// their share of the 3D area (input slivers left out): 1 for a map that
// preserves area, small where the map squeezes the surface
double mapCrowding(const std::vector<SPoint2> &uv,
                   const std::vector<SPoint3> &xyz,
                   const std::vector<int> &triangleNodes);

// Noise scale and criteria from Mesh.CompoundNoiseSize and the input
layoutParameters reparamLayoutParameters(const layoutMesh &mesh);

// The part is kept if the map CreateGeometry will compute for it is
// one-to-one and does not crowd it, and the part is not much larger than
// its boundary. Refused because its conformal maps fold, where they fail
// goes in `where` (if given).
partCheck reparamVerifyPart(const std::vector<MTriangle *> &triangles,
                            mapFailurePlace *where = nullptr);

// Whether Gmsh's classification must end a curve at node v (patches/0012):
// three cut edges or more of the last layout meet there (two boundary loops
// touching, a cut ending on another), so that the curves through it share
// a model point and their meshes meet there
// Forgets the last layout's nodes (CreateGeometry: the curves are made)
void reparamForgetJunctions();

} // namespace reparam

#endif
