// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// A face whose planar mesh cannot be made: Gmsh's Delaunay-based meshers
// recover each segment of the face's curves in its (u, v) plane, split the
// segments they cannot recover and try again, and give up with an error
// after ten rounds, leaving the face without elements (a hole). Where the
// face is a concave sliver thinner than the mesh size, the chords of its
// curves' segments cross its other side in (u, v), and splitting them (down
// to 1e-9 of the diagonal, bench/README.md) does not help. The safety net
// then meshes the face with its input triangles stitched to its curves, with
// one warning naming it (hook in meshGFace.cpp's recoverEdge, patches/0008).

#ifndef REPARAM_LOST_SEGMENTS_H
#define REPARAM_LOST_SEGMENTS_H

class GFace;

namespace reparam {

// After gf's planar mesher (reparamEndFaceMeshing): gf meshed with its
// input triangles if the mesher lost a curve segment and left it empty;
// an error if even that fails
void meshFaceWithLostSegments(GFace *gf);

} // namespace reparam

#endif
