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

// Optimizes the triangles of discrete face gf if Reparam parametrized it,
// Mesh.CompoundOptimize is on, its mesh has no quadrangle and is not the
// one it left already (the validity hook, Geo/planar/reparamMeshValidity.h, runs
// it first on Delaunay and Frontal-Delaunay meshes); logs what it did and
// records it for the report (findOptimization). False (nothing done)
// otherwise
bool reparamOptimizeMeshedFace(GFace *gf);

#endif
