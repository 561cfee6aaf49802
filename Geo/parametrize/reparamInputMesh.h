// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The safety net: a discrete face that no map can parametrize (its part of
// the layout could not be verified, or CreateGeometry got another patch
// than ClassifySurfaces' layout made) keeps its input triangles in the mesh,
// stitched to the 1D meshes of its curves, with one warning naming it and
// the reason, instead of being left out of the mesh (a hole). Hooks in
// discreteFace::createGeometry and discreteFace::mesh (patches/0011).

#ifndef REPARAM_INPUT_MESH_H
#define REPARAM_INPUT_MESH_H

#include <string>
#include <vector>

#include <cstddef>

class GFace;
class GModel;

namespace reparam {
// Called when gf's planar mesh keeps `against` triangles pointing against
// the input after every repair: meshes gf with its input triangles
// stitched to its curves' nodes, with one warning, if that leaves no more
// against the input (and turns none in the stitching); false otherwise
bool reparamMeshFaceWithItsInput(GFace *gf, std::size_t against);
// The same for any `reason` (the warning's end), if that leaves no more
// than `against` triangles against the input (SIZE_MAX: gf has no mesh
// otherwise, and the stitching may turn triangles too)
bool reparamMeshFaceWithItsInput(GFace *gf, std::size_t against,
                                 const std::string &reason);

// The faces of m meshed with their input triangles
std::vector<int> facesKeptAsInput(GModel *m);
bool keptAsInput(const GFace *gf);

} // namespace reparam

#endif
