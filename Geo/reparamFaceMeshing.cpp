// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "reparamCreaseCurves.h"
#include "reparamCurvatureMetric.h"
#include "reparamFaceMeshing.h"
#include "reparamOptions.h"
#include "reparamReport.h"
#include "reparamSizeGrading.h"
#include "Context.h"
#include "GFace.h"
#include "GModel.h"
#include "GmshDefines.h"
#include "GmshMessage.h"

namespace {

  // Mesh.CrossFieldClosestPoint while a face of Reparam's is meshed with
  // Frontal-Delaunay for quads (-1: not changed)
  int savedClosestPoint = -1;

  // The directions of a face's quadrangles: Gmsh's default takes them from
  // the closest point of the face's boundary, in the (u, v) plane, and the
  // curves of a patch layout follow input edges (a cut zig-zags across the
  // input's triangles): each zig and zag turns the quadrangles next to it.
  // The smooth field Gmsh can solve for instead (a Laplace problem on the
  // face's background mesh, Mesh.CrossFieldClosestPoint = 0) averages them
  // out: eta mean 0.80 -> 0.82 on aorta_gmsh, 0.82 -> 0.85 on tooth
  void useSmoothCrossField(GFace *gf)
  {
    if(gf->getMeshingAlgo() != ALGO_2D_FRONTAL_QUAD ||
       !reparamRecombineWithParametrization(gf) ||
       !CTX::instance()->mesh.crossFieldClosestPoint)
      return;
    savedClosestPoint = CTX::instance()->mesh.crossFieldClosestPoint;
    CTX::instance()->mesh.crossFieldClosestPoint = 0;
    Msg::Debug("Reparam: surface %d: smooth cross field for its quadrangles",
               gf->tag());
  }

  void restoreCrossField()
  {
    if(savedClosestPoint < 0) return;
    CTX::instance()->mesh.crossFieldClosestPoint = savedClosestPoint;
    savedClosestPoint = -1;
  }

} // namespace

void reparamBeginFaceMeshing(GFace *gf)
{
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
}

bool reparamRecombineWithParametrization(GFace *gf)
{
  const parametrizationRecord *record = findParametrization(gf);
  return record && record->map > 0 && gf->haveParametrization();
}

bool reparamMeshInParallel(GModel *m)
{
  if(Msg::GetMaxThreads() < 2 ||
     getReparamOptions().parametrization == (int)compoundParametrization::gmsh)
    return true;
  bool discrete = false;
  for(auto it = m->firstFace(); it != m->lastFace() && !discrete; ++it)
    discrete = (*it)->geomType() == GEntity::DiscreteSurface;
  for(auto it = m->firstEdge(); it != m->lastEdge() && !discrete; ++it)
    discrete = (*it)->geomType() == GEntity::DiscreteCurve;
  if(discrete)
    Msg::Info("Reparam: discrete curves and surfaces meshed on one thread "
              "(General.NumThreads = %d: Reparam's layout uses them)",
              Msg::GetMaxThreads());
  return !discrete;
}
