// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Whether Gmsh may throw away a Delaunay or Frontal-Delaunay mesh of a face
// Reparam parametrized (hook in meshGFace, patches/0008). Gmsh remeshes a
// non-planar face with MeshAdapt as soon as one element disagrees with the
// normals of the input under its nodes; on scans those few elements cross
// folds thinner than the mesh size, which MeshAdapt crosses too (camelhead:
// 9 of 16999 elements with Frontal-Delaunay in 0.4 s; 27 with MeshAdapt in
// 35 s, Hausdorff distance 0.45 % -> 1.8 %).

#ifndef REPARAM_MESH_VALIDITY_H
#define REPARAM_MESH_VALIDITY_H

#include <cstddef>

class GFace;

// Elements of gf's triangles whose normal disagrees with the sum of the
// face's normals at their nodes (Gmsh's test), counted against the
// orientation most of them have
std::size_t countElementsAgainstFaceNormals(GFace *gf);

// For a discrete face Reparam parametrized (else false, and Gmsh's test
// decides): first optimizes it (Mesh.CompoundOptimize, which turns back the
// triangles pointing against the input), then splits the edges of those
// left (Mesh/invertedElementRepair), then true if none is left, or if at
// most 1 % of the elements fail Gmsh's test: the mesh is kept (logged)
bool reparamKeepPlanarMesh(GFace *gf);

#endif
