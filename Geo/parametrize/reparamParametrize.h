// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// What Reparam's parametrization hook offers besides the hook itself
// (declared in Gmsh's Geo/GModelParametrize.h by patches/0001).

#ifndef REPARAM_GEO_PARAMETRIZE_H
#define REPARAM_GEO_PARAMETRIZE_H

#include <array>
#include <string>
#include <vector>
#include "SPoint2.h"
#include "SPoint3.h"

class GFace;
class MTriangle;
class MVertex;

namespace reparam {

struct mapOptionsRecord; // Geo/core/reparamFaceRecord.h
struct parametrizationRecord;

struct trianglePatch;

// Drops the maps the patch layout kept for CreateGeometry (a new layout
// starts without them)
void reparamForgetLayoutMaps();

// The parametrization CreateGeometry would compute for these triangles,
// computed without a word in the log (the patch layout tries hundreds of
// parts): 1 with the (u, v) and 3D points of the nodes and the triangles'
// node indices when it is one-to-one, else -1 and the reason in `why`; 0
// when Mesh.CompoundParametrization = 0 leaves it to Gmsh. Refused because
// its conformal maps fold, where they fail goes in `where` (if given): the
// layout cuts it there.
struct mapFailurePlace {
  // nodes of the triangles the maps leave flipped (else degenerate)
  std::vector<MVertex *> through;
  // a node of each of two boundary edges whose images cross
  std::vector<std::array<MVertex *, 2> > apart;
};
// `patch`: patchOfTriangles(triangles) when the caller built it already
// (taken from it), else built here.
int reparamTryParametrization(const std::vector<MTriangle *> &triangles,
                              std::vector<SPoint2> &uv,
                              std::vector<SPoint3> &xyz,
                              std::vector<int> &triangleNodes, std::string &why,
                              mapFailurePlace *where = nullptr,
                              trianglePatch *patch = nullptr);

// Whether every hole of these triangles (inner boundary loop) can be
// filled (Mesh/maps/holeFilling.h), as the parametrization fills them
// (Mesh.CompoundFillHoles; true without it, without holes, or for a planar
// part whose projection is one-to-one, meshed on its plane with its
// holes): false means
// reparamTryParametrization fails for that reason, whatever its maps give
bool reparamHolesFillable(const std::vector<MTriangle *> &triangles);
// The same of their patch (Geo/parametrize/reparamTrianglePatch.h)
bool reparamHolesFillable(const trianglePatch &patch);

// gf's map computed again with the options of now, from the arrays
// CreateGeometry wrote (gf->stl_vertices_xyz, stl_triangles; its triangles
// are gone once meshed), its nodes and triangles in the order of `orders`
// (Geo/core/reparamFaceRecord.h): 1 with their (u, v) in `uv` and `record`
// filled, logged as CreateGeometry logs it; -1 failed (why in `why`)
int reparamMapFaceArrays(GFace *gf, const mapOptionsRecord &orders,
                         std::vector<SPoint2> &uv,
                         parametrizationRecord &record, std::string &why);

// Why gf's last parametrization failed (for the safety net's warning)
std::string reparamLastFailure(const GFace *gf);

} // namespace reparam

#endif
