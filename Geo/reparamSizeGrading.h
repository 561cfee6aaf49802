// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The sizes of a discrete face's 1D mesh carried into its 2D mesh with a
// gradient (Mesh.CompoundMeshSizeGradient), in place of Gmsh's linear
// interpolation (Mesh.MeshSizeExtendFromBoundary), while the planar mesher
// runs: see Mesh/gradedBoundarySize.h for why.

#ifndef REPARAM_SIZE_GRADING_H
#define REPARAM_SIZE_GRADING_H

class GEntity;
class GFace;

// Called by discreteFace::mesh() (patches/0014) around the planar mesher:
// with Mesh.CompoundMeshSizeGradient > 0, where gf's sizes extend from its
// boundary (Mesh.MeshSizeExtendFromBoundary or the face's own setting),
// turns that extension off for gf and grades the sizes of its boundary
// nodes instead; the end restores gf's setting
void reparamBeginSizeGrading(GFace *gf);
void reparamEndSizeGrading(GFace *gf);

// Called by BGM_MeshSize (patches/0014) with the size it found: the graded
// size at (x, y, z) of the face being meshed by this thread where smaller,
// else that size
double reparamGradedMeshSize(GEntity *ge, double x, double y, double z,
                             double size);

#endif
