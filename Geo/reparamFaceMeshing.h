// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// What Reparam sets up around the planar mesher of a discrete face, and
// takes down after (hook in discreteFace::mesh, patches/0014): the sizes of
// its curves graded into it (Geo/reparamSizeGrading.h), and for a face
// recombined into quadrangles its crease curves taken out
// (Geo/reparamCreaseCurves.h).

#ifndef REPARAM_FACE_MESHING_H
#define REPARAM_FACE_MESHING_H

class GFace;

void reparamBeginFaceMeshing(GFace *gf);
void reparamEndFaceMeshing(GFace *gf);

#endif
