// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The sharp creases left inside a discrete face (Mesh/layout/creaseChains.h) kept
// as curves embedded in it when CreateGeometry has parametrized it, so that
// Gmsh's planar meshers put edges along them instead of cutting across.

#ifndef REPARAM_CREASE_CURVES_H
#define REPARAM_CREASE_CURVES_H

#include <vector>
#include "SPoint3.h"

class GEdge;
class GFace;
class GModel;
class MVertex;

namespace reparam {

// gf's input nodes, their points and its triangles (3 node indices each):
// the chains of sharp edges the last patch layout left inside gf, longer
// than twice the layout's noise size, kept half that size away from gf's
// curves, become discrete curves embedded in gf; returns how many
int reparamEmbedCreaseCurves(GFace *gf, const std::vector<MVertex *> &nodes,
                             const std::vector<SPoint3> &points,
                             const std::vector<int> &triangleNodes);

// Before the curves are meshed (the mesh size is known then, not when
// CreateGeometry kept the creases, at the input's scale): the crease curves
// too small for the mesh size asked at their middle (Mesh/layout/creaseChains.h,
// creaseTooSmallForMesh: shorter than three sizes and bent, ending within
// half a size of another curve of their face, or coming back beside
// themselves closer than half a size) taken out of their
// faces until each is meshed, and, once Mesh1D is done, their 1D meshes
// deleted with those of their end points no other curve or face uses
// (reparamDeleteHiddenCreaseMeshes). The mesh may then cut the crease: the
// optimization on the input puts back the input nodes it cuts off
// (Mesh/optimize/farInputNodes.h). Returns how many were taken out
int reparamHideSmallCreaseCurves(GModel *m);
void reparamDeleteHiddenCreaseMeshes(GModel *m);
// Whether ge is a crease curve taken out of its face
bool reparamCreaseCurveHidden(const GEdge *ge);

// While gf is recombined into quadrangles (Mesh.RecombineAll or the face's
// Recombine): its crease curves taken out of it and their 1D meshes
// deleted (Blossom pairs no triangles across an embedded curve, so the
// pieces the creases close off must each have an even count of triangles:
// else "Perfect Match failed"); the end puts the curves back, those
// taken out for their size too
void reparamHideCreaseCurvesFromQuads(GFace *gf);
void reparamRestoreCreaseCurves(GFace *gf);

} // namespace reparam

#endif
