// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// What Reparam sets up around the planar mesher of a discrete face, and
// takes down after (hook in discreteFace::mesh, patches/0014): the sizes of
// its curves graded into it (Geo/reparamSizeGrading.h), and for a face
// recombined into quadrangles its crease curves taken out
// (Geo/reparamCreaseCurves.h). Also whether Gmsh's recombination may use
// the face's parametrization (hook in recombineIntoQuads, patches/0015), and
// whether curves and surfaces may be meshed in parallel (patches/0018).

#ifndef REPARAM_FACE_MESHING_H
#define REPARAM_FACE_MESHING_H

class GFace;
class GModel;

void reparamBeginFaceMeshing(GFace *gf);
void reparamEndFaceMeshing(GFace *gf);

// Whether the quadrangles Blossom made on a discrete face may be smoothed
// and cleaned in its (u, v) plane, as on a CAD face: Gmsh skips that on
// every discrete face, which had no parametrization it could trust; one
// that Reparam parametrized (Mesh.CompoundParametrization > 0) has a
// one-to-one map. Gmsh's own map keeps Gmsh's behaviour (the reference).
bool reparamRecombineWithParametrization(GFace *gf);

// Whether Mesh1D and Mesh2D may mesh m's curves and surfaces in parallel
// (Gmsh built with OpenMP, General.NumThreads > 1; hook in Generator.cpp,
// patches/0018): not when m has discrete curves or surfaces and Reparam
// works on them (Mesh.CompoundParametrization > 0), whose hooks keep shared
// state (corner snapping, input meshes, optimization records, reports);
// then logs it once per call with several threads. Reparam's own layout
// runs on the threads (Mesh/patchLayout.h).
bool reparamMeshInParallel(GModel *m);

#endif
