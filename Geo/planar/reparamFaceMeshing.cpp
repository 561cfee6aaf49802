// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// What Reparam sets up around the planar mesher of a discrete face, and
// takes down after (hook in discreteFace::mesh, patches/0014): the sizes of
// its curves graded into it (Geo/sizes/reparamSizeGrading.h), and for a face
// recombined into quadrangles its crease curves taken out
// (Geo/layout/reparamCreaseCurves.h). Also whether Gmsh's recombination may use
// the face's parametrization (hook in recombineIntoQuads, patches/0015), and
// whether curves and surfaces may be meshed in parallel (patches/0018). A
// face its planar mesher left empty is meshed with its input
// (Geo/planar/reparamLostSegments.h).

#include "reparamCreaseCurves.h"
#include "reparamCurvatureMetric.h"
#include "reparamHooks.h"
#include "reparamLostSegments.h"
#include "reparamOptions.h"
#include "reparamReport.h"
#include "reparamSizeGrading.h"
#include "reparamState.h"
#include "Context.h"
#include "GFace.h"
#include "GModel.h"
#include "GmshDefines.h"
#include "GmshMessage.h"

namespace reparam {

namespace {

  // The directions of a face's quadrangles: Gmsh's default takes them from
  // the closest point of the face's boundary, in the (u, v) plane, and the
  // curves of a patch layout follow input edges (a cut zig-zags across the
  // input's triangles): each zig and zag turns the quadrangles next to it.
  // The smooth field Gmsh can solve for instead (a Laplace problem on the
  // face's background mesh, Mesh.CrossFieldClosestPoint = 0) averages them
  // out (bench/README.md, "A smooth cross field")
  void useSmoothCrossField(GFace *gf)
  {
    if(gf->getMeshingAlgo() != ALGO_2D_FRONTAL_QUAD ||
       !reparamRecombineWithParametrization(gf) ||
       !CTX::instance()->mesh.crossFieldClosestPoint)
      return;
    // the user's, restored once the face is meshed
    savedGmshOptions().crossFieldClosestPoint =
      CTX::instance()->mesh.crossFieldClosestPoint;
    CTX::instance()->mesh.crossFieldClosestPoint = 0;
    Msg::Debug("Reparam: surface %d: smooth cross field for its quadrangles",
               gf->tag());
  }

  void restoreCrossField()
  {
    int &savedClosestPoint = savedGmshOptions().crossFieldClosestPoint;
    if(savedClosestPoint < 0) return;
    CTX::instance()->mesh.crossFieldClosestPoint = savedClosestPoint;
    savedClosestPoint = -1;
  }

} // namespace

} // namespace reparam

using namespace reparam;

// Faces read their curves' meshes while they are meshed, on several threads
// with General.NumThreads > 1; Gmsh splits the segments of curves a face's
// mesh cannot recover (meshGFace.cpp, patches/0020) and has the faces on
// them meshed again: the split waits until no other face is being meshed
// (the shared curvesLock of a face is held from reparamBeginFaceMeshing to
// reparamEndFaceMeshing, faceMeshingContext::meshing: its nesting on this
// thread)
void reparamBeginFaceMeshing(GFace *gf)
{
  if(!thisThreadsFaceMeshing().meshing++) curvesLock().lock_shared();
  reparamHideCreaseCurvesFromQuads(gf);
  reparamBeginSizeGrading(gf);
  useSmoothCrossField(gf);
  reparamBeginAnisotropicMeshing(gf);
}

void reparamEndFaceMeshing(GFace *gf)
{
  reparamEndAnisotropicMeshing();
  restoreCrossField();
  reparamEndSizeGrading(gf);
  reparamRestoreCreaseCurves(gf);
  meshFaceWithLostSegments(gf);
  int &meshing = thisThreadsFaceMeshing().meshing;
  if(meshing > 0 && !--meshing) curvesLock().unlock_shared();
}

void reparamBeginCurveSplit()
{
  faceMeshingContext &context = thisThreadsFaceMeshing();
  if(context.splittingCurves) return;
  if(context.meshing) curvesLock().unlock_shared();
  curvesLock().lock();
  context.splittingCurves = true;
}

void reparamEndCurveSplit()
{
  faceMeshingContext &context = thisThreadsFaceMeshing();
  if(!context.splittingCurves) return;
  context.splittingCurves = false;
  curvesLock().unlock();
  if(context.meshing) curvesLock().lock_shared();
}

bool reparamRecombineWithParametrization(GFace *gf)
{
  const parametrizationRecord *record = findParametrization(gf);
  return record && record->map > 0 && gf->haveParametrization();
}

namespace reparam {

namespace {

  // Why Mesh2D meshes m's surfaces on one thread with Reparam (null: it
  // need not): the quadrangle steps take crease curves out of the face and
  // smooth across its neighbours, the anisotropic one changes
  // Mesh.SmoothRatio while a face is meshed
  const char *serialSurfacesReason(GModel *m)
  {
    for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
      GFace *gf = *it;
      if(gf->geomType() != GEntity::DiscreteSurface) continue;
      if(CTX::instance()->mesh.recombineAll || gf->meshAttributes.recombine)
        return "quadrangles";
      if(reparamAnisotropicFace(gf)) return "anisotropic metric";
      // BAMG numbers the nodes of a face's curves in the nodes themselves
      // (MVertex::setIndex), which the faces on both sides of a curve
      // share, and a face it leaves with a hole is meshed again under
      // another global algorithm (Geo/planar/reparamMesherFallback.cpp)
      if(gf->getMeshingAlgo() == ALGO_2D_BAMG) return "BAMG";
    }
    return nullptr;
  }

} // namespace

} // namespace reparam

bool reparamMeshInParallel(GModel *m, int dim)
{
  if(Msg::GetMaxThreads() < 2 ||
     getReparamOptions().parametrization == (int)compoundParametrization::gmsh)
    return true;
  if(dim == 2) {
    const char *reason = serialSurfacesReason(m);
    if(reason)
      Msg::Info("Reparam: discrete surfaces meshed on one thread (%s; "
                "General.NumThreads = %d: Reparam's layout uses them)",
                reason, Msg::GetMaxThreads());
    return !reason;
  }
  bool discrete = false;
  for(auto it = m->firstEdge(); it != m->lastEdge() && !discrete; ++it)
    discrete = (*it)->geomType() == GEntity::DiscreteCurve;
  if(discrete)
    Msg::Info("Reparam: discrete curves meshed on one thread (their nodes "
              "take the input's corners in turn; General.NumThreads = %d: "
              "the layout and the surfaces use them)",
              Msg::GetMaxThreads());
  return !discrete;
}

