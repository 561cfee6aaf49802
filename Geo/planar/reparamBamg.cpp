// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <mutex>
#include <set>
#include "GFace.h"
#include "GmshMessage.h"
#include "reparamBamg.h"
#include "reparamCurvatureMetric.h"
#include "reparamHooks.h"
#include "reparamReport.h"

namespace reparam {

namespace {

  // the faces BAMG gave up on, until their mesh is replaced (BAMG's faces
  // are meshed on one thread; the lock for a model meshed again)
  std::mutex failedLock;
  std::set<const GFace *> failed;

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
  std::lock_guard<std::mutex> lock(failedLock);
  failed.insert(gf);
  return true;
}

namespace reparam {

bool takeBamgFailure(const GFace *gf)
{
  std::lock_guard<std::mutex> lock(failedLock);
  return failed.erase(gf) > 0;
}
} // namespace reparam

