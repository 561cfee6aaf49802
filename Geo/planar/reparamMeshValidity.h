// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Whether Gmsh may throw away a Delaunay or Frontal-Delaunay mesh of a face
// Reparam parametrized (hook in meshGFace, patches/0008). Gmsh remeshes a
// non-planar face with MeshAdapt as soon as one element disagrees with the
// normals of the input under its nodes; on scans those few elements cross
// folds thinner than the mesh size, which MeshAdapt crosses too, far slower
// and farther from the input (bench/README.md, Elements against the input).

#ifndef REPARAM_MESH_VALIDITY_H
#define REPARAM_MESH_VALIDITY_H

#include <cstddef>

class GFace;

namespace reparam {

// Elements of gf's triangles whose normal disagrees with the sum of the
// face's normals at their nodes (Gmsh's test), counted against the
// orientation most of them have
std::size_t countElementsAgainstFaceNormals(GFace *gf);

// The segments of gf's curves its triangles use fewer times than the curve
// bounds it (once; twice for a curve on both sides, a slit, and for an
// embedded curve)
std::size_t countUnusedCurveSegments(GFace *gf);

// The edges of gf's triangles longer than twice the size asked at their
// ends (BGM_MeshSize without the grading from short curves, which the
// meshers follow loosely): where the planar mesher put no node inside the
// face (the optimization splits those longer than 1.6 times the size)
std::size_t countLongEdges(GFace *gf);

} // namespace reparam

#endif
