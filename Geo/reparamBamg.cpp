// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include "GFace.h"
#include "GmshMessage.h"
#include "reparamBamg.h"
#include "reparamCurvatureMetric.h"
#include "reparamReport.h"

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

double reparamBamgMaxVertices(GFace *gf, int vertices)
{
  if(!parametrizedByReparam(gf)) return -1.1e100;
  return (double)bamgMaxVertices(vertices);
}

bool reparamBamgFailed(GFace *gf)
{
  if(!parametrizedByReparam(gf)) return false;
  if(reparamAnisotropicFace(gf))
    Msg::Warning("Reparam: surface %d: BAMG failed, its isotropic Delaunay "
                 "mesh kept (%lu triangles, at the curvature metric's "
                 "smallest size)",
                 gf->tag(), gf->triangles.size());
  else
    Msg::Info("Reparam: surface %d: BAMG failed, its Delaunay mesh kept "
              "(%lu triangles)",
              gf->tag(), gf->triangles.size());
  return true;
}
