// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// A face's map follows the options. CreateGeometry computes the
// parametrization of a discrete face with the options of that moment; a
// user who chooses another map afterwards (the options window, the API, a
// .geo line after CreateGeometry) expects the next mesh to use it. Before
// the faces are meshed (reparamParametrizeAgain, Geo/reparamHooks.h), the
// map of every face whose Mesh.CompoundParametrization, FillHoles or Repair
// changed since is computed again, on the arrays the face keeps (its
// triangles are gone once it is meshed), in the order CreateGeometry's
// patch had (the same options give the same (u, v) either way). The options
// only the patch layout reads act at ClassifySurfaces: a change of them is
// named once.

#ifndef REPARAM_PARAMETRIZE_AGAIN_H
#define REPARAM_PARAMETRIZE_AGAIN_H

#include <string>
#include "reparamState.h"

namespace reparam {

// The options a map computed now reads (no orders)
mapOptionsRecord currentMapOptions();
// "Mesh.CompoundParametrization 6 -> 4, Mesh.CompoundFillHoles 1 -> 0";
// empty when the maps' options are the same
std::string mapOptionsChange(const mapOptionsRecord &was,
                             const mapOptionsRecord &now);

// The options the patch layout reads (Geo/core/reparamState.h)
layoutOptionsRecord currentLayoutOptions();
// The same kind of list for them
std::string layoutOptionsChange(const layoutOptionsRecord &was,
                                const layoutOptionsRecord &now);

} // namespace reparam

#endif
