// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Reparam's side of BAMG (Mesh.Algorithm = 7; hooks in meshGFaceBamg,
// patches/0023).
//
// The most vertices BAMG may make for a face: BAMG builds its arrays for
// that many at each of its calls, their constructors touching every page,
// 900000 by default whatever the face: on the thousands of small faces of a
// segmentation-like STL most of the time went to page faults
// (bench/README.md, "BAMG").
//
// A face whose BAMG mesh fails: BAMG meshes the face Gmsh's Delaunay mesher
// meshed first, and gave up on some faces of the segmentation-like STLs
// (`we loss some 1 edges ... Fatal error in the meshgenerator 1100`),
// which Gmsh reports as an error, the face keeping that first mesh.

#ifndef REPARAM_BAMG_H
#define REPARAM_BAMG_H

class GFace;

namespace reparam {

// For a face of `vertices` vertices (the mesh BAMG starts from): 32 times
// that, at least 20000 and at most BAMG's 900000. BAMG refines that mesh to
// the metric, and stops inserting points at the bound: on the 33 meshes of
// bench/RESULTS-meshers.md, with and without Mesh.CompoundCurvatureMetric
// (bench/RESULTS-anisotropic.md), no face made more than 5336 vertices
long bamgMaxVertices(long vertices);

// Whether BAMG failed on gf since the last call (then forgotten): the
// validity hook meshes it again (Geo/planar/reparamMeshValidity.cpp)
bool takeBamgFailure(const GFace *gf);

} // namespace reparam

#endif
