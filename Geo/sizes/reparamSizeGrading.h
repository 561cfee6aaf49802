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

// The size BGM_MeshSize gives at x on gf without the grading above (while
// gf is meshed: the size fields and options, not extended from the
// boundary)
double reparamUngradedMeshSize(GFace *gf, const SPoint3 &x);

} // namespace reparam

#endif
