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

void reparamBeginFaceMeshing(GFace *gf);

void reparamEndFaceMeshing(GFace *gf);

// Whether the quadrangles Blossom made on a discrete face may be smoothed
// and cleaned in its (u, v) plane, as on a CAD face: Gmsh skips that on
// every discrete face, which had no parametrization it could trust; one
// that Reparam parametrized (Mesh.CompoundParametrization > 0) has a
// one-to-one map. Gmsh's own map keeps Gmsh's behaviour (the reference).
bool reparamRecombineWithParametrization(GFace *gf);

// Whether Mesh1D (dim 1) or Mesh2D (dim 2) may mesh m's curves or surfaces
// in parallel (Gmsh built with OpenMP, General.NumThreads > 1; hook in
// Generator.cpp, patches/0018), where Reparam works on them
// (Mesh.CompoundParametrization > 0): curves not when m has discrete ones
// (the corner snapping gives an input corner to the first curve that takes
// it: the mesh would depend on the threads' order); surfaces unless a
// discrete one is recombined into quadrangles or meshed with the
// anisotropic metric (those steps change options and curves around the
// face) or with BAMG (which numbers the nodes of the curves in the nodes,
// shared by the faces on both sides, and whose holes are meshed again
// under another global algorithm). Logs it once per call with several threads.
// Reparam's state for the triangle meshes of faces is per thread or behind a
// mutex; its own layout runs on the threads too (Mesh/layout/patchLayout.h).
bool reparamMeshInParallel(GModel *m, int dim);

// Called by meshGenerator (patches/0020) around Gmsh's split of the curve
// segments a face's mesh could not recover: waits until no other face is
// being meshed (each holds a shared lock from reparamBeginFaceMeshing to
// reparamEndFaceMeshing; this thread's own is let go meanwhile), so that
// no thread reads those curves while they change
void reparamBeginCurveSplit();

void reparamEndCurveSplit();

#endif
