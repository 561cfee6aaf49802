// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The sizes of a discrete face's 1D mesh carried into its 2D mesh with a
// gradient (Mesh.CompoundMeshSizeGradient), in place of Gmsh's linear
// interpolation (Mesh.MeshSizeExtendFromBoundary), while the planar mesher
// runs: see Mesh/sizes/gradedBoundarySize.h for why.

#ifndef REPARAM_SIZE_GRADING_H
#define REPARAM_SIZE_GRADING_H

#include "SPoint3.h"

class GEdge;
class GEntity;
class GFace;
class GModel;

namespace reparam {

// Called by discreteFace::mesh() (patches/0014) around the planar mesher:
// with Mesh.CompoundMeshSizeGradient > 0, where gf's sizes extend from its
// boundary (Mesh.MeshSizeExtendFromBoundary or the face's own setting),
// turns that extension off for gf and grades the sizes of its boundary
// nodes instead; the end restores gf's setting
void reparamBeginSizeGrading(GFace *gf);
void reparamEndSizeGrading(GFace *gf);

} // namespace reparam

// Called by GenerateMesh() around Mesh1D (patches/0014): with
// Mesh.CompoundMeshSizeGradient > 0 and Reparam's maps, the sizes along the
// discrete curves of m grow from the ends of the curves shorter than the
// size (a curve meshed with 2 segments of 0.1 h next to one of h: triangles
// of kappa 0.1 at their common end, which no 2D grading helps)
// Begin also refuses, with an error, the discrete curves whose mesh would
// have more than 1e7 segments (the size far below the model's scale), which
// Gmsh would spend hours on; End gives them back their meshing method, and
// takes the surfaces on them out of Mesh2D (a warning each: meshed without
// that curve, MeshAdapt would refine towards the same size for as long)
// until reparamRestoreRefusedSurfaces, called after Mesh2D.
// With Reparam's maps, Begin first takes the crease curves too small for
// the size out of their faces, and End deletes their 1D meshes
// (Geo/layout/reparamCreaseCurves.h): they are no sources of sizes. The faces
// narrower than the size (Mesh/sizes/narrowStrips.h) give their curves sizes of
// their width, which the faces' sizes then grow from.
void reparamBeginCurveSizeGrading(GModel *m);

void reparamEndCurveSizeGrading(GModel *m);

namespace reparam {
void reparamRestoreRefusedSurfaces(GModel *m);

// While the curves are meshed: whether ge bounds a face narrower than the
// size somewhere (Mesh/sizes/narrowStrips.h): its corners are the strip's, each
// one a node (Mesh/curves/curveCornerSnap.h)
bool reparamCurveAlongNarrowStrip(const GEdge *ge);

// While the curves are meshed: whether the sizes along ge are graded, and
// the graded size at x where smaller than `size`, else `size` (the 1D
// nodes are spread by it in Geo/curves/reparamCurveMesh.cpp)
bool reparamCurveSizesGraded(const GEdge *ge);
double reparamGradedCurveSize(const GEdge *ge, const SPoint3 &x, double size);

} // namespace reparam

// Called by BGM_MeshSize (patches/0014) with the size it found: the graded
// size at (x, y, z) of the face being meshed by this thread where smaller,
// else that size
double reparamGradedMeshSize(GEntity *ge, double x, double y, double z,
                             double size);

namespace reparam {

// The size BGM_MeshSize gives at x on gf without the grading above (while
// gf is meshed: the size fields and options, not extended from the
// boundary)
double reparamUngradedMeshSize(GFace *gf, const SPoint3 &x);

} // namespace reparam

#endif
