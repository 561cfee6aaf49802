// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <mutex>
#include "GFace.h"
#include "GmshMessage.h"
#include "reparamBamg.h"
#include "reparamCurvatureMetric.h"
#include "reparamHooks.h"
#include "reparamReport.h"
#include "reparamState.h"

namespace reparam {

namespace {

  bool parametrizedByReparam(const GFace *gf)
  {
    const parametrizationRecord *record = findParametrization(gf);
    return record && record->map > 0;
  }

} // namespace

long bamgMaxVertices(long vertices)
{
  return std::min(900000L, std::max(20000L, 32L * vertices));
}

} // namespace reparam

using namespace reparam;

double reparamBamgMaxVertices(GFace *gf, int vertices)
{
  if(!parametrizedByReparam(gf)) return -1.1e100;
  return (double)bamgMaxVertices(vertices);
}

bool reparamBamgFailed(GFace *gf)
{
  if(!parametrizedByReparam(gf)) return false;
  if(reparamAnisotropicFace(gf))
    Msg::Warning("Reparam: surface %d: BAMG failed, meshed by Delaunay "
                 "instead (isotropic, at the curvature metric's smallest "
                 "size)",
                 gf->tag());
  else
    Msg::Info("Reparam: surface %d: BAMG failed, meshed by Delaunay instead",
              gf->tag());
  // kept until its mesh is replaced (takeBamgFailure)
  std::unique_lock<std::mutex> lock = lockRecords();
  faceRecordOf(gf).bamgFailed = true;
  return true;
}

namespace reparam {

bool takeBamgFailure(const GFace *gf)
{
  std::unique_lock<std::mutex> lock = lockRecords();
  faceRecord *r = findFaceRecord(gf);
  if(!r || !r->bamgFailed) return false;
  r->bamgFailed = false;
  return true;
}
} // namespace reparam

