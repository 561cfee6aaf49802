// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The map of a planar patch: its projection on its mean plane. Gmsh's
// discrete faces replace the (u, v) of a face whose nodes all lie within
// Geometry.MatchMeshTolerance times its diagonal of their mean plane by that
// projection ("Discrete surface N is planar, simplifying parametrization"),
// whatever map was computed, so a planar patch is meshed on its plane with
// all its boundary loops: no hole needs filling, and a conformal map that
// folds on the slivers of a CAD triangulation says nothing of it.

#ifndef PLANE_PROJECTION_H
#define PLANE_PROJECTION_H

#include "discretePatch.h"
#include "mapChain.h"
#include "patchMap.h"

namespace reparam {

// Whether every node of the patch lies within `tolerance` times the
// diagonal of its bounding box of the nodes' least squares plane (false for
// tolerance <= 0)
bool patchIsPlanar(const surfaceMesh &patch, double tolerance);

// The nodes' coordinates on the least squares plane of the patch, the
// plane's normal on the side that makes the total signed area positive,
// scaled like the free boundary maps (the boundary nodes' root mean square
// distance to their barycenter is 1); `scale`: uv length per 3D length
patchMap planeProjectionMap(const discretePatch &patch,
                            double *scale = nullptr);

// The projection of a planar patch checked like a map of the chain, its
// one attempt of map compoundParametrization::plane (no repair: Gmsh meshes
// the projection, not a repaired map). Flipped triangles no higher than
// `tolerance` times the patch's diagonal, and boundary crossings that a
// move of one node by that much undoes, are the input's own rounding (the
// scale Gmsh calls planar: nodes of a CAD export 1e-7 of the part apart
// where its outline doubles back) and do not count; a part folded onto
// itself at a larger scale is not one-to-one.
checkedMap planeProjection(const discretePatch &patch, double tolerance);

} // namespace reparam

#endif
