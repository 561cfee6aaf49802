// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// What Reparam sets up around the planar mesher of a discrete face, and
// takes down after (hook in discreteFace::mesh, patches/0014): the sizes of
// its curves graded into it (Geo/sizes/reparamSizeGrading.h), and for a face
// recombined into quadrangles its crease curves taken out
// (Geo/layout/reparamCreaseCurves.h). Also whether Gmsh's recombination may use
// the face's parametrization (hook in recombineIntoQuads, patches/0015), and
// whether curves and surfaces may be meshed in parallel (patches/0018).

#ifndef REPARAM_FACE_MESHING_H
#define REPARAM_FACE_MESHING_H

class GFace;
class GModel;

#endif
