// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The new mesh of a discrete face optimized on its input triangulation
// (Mesh.CompoundOptimize; hook in discreteFace::mesh, patches/0001, after
// the planar mesher and before the face's report): Mesh/optimize/surfaceMeshOptimizer
// on the face's triangles, its curves' nodes and edges (boundary and
// embedded) kept, and each moved or new node given the (u, v) the face's
// parametric interface has for the input point it lies on, so that it still
// maps it there.

#ifndef REPARAM_OPTIMIZE_FACE_H
#define REPARAM_OPTIMIZE_FACE_H

class GFace;

#endif
