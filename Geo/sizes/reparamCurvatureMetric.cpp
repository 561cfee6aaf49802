// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <mutex>
#include "Context.h"
#include "GEdge.h"
#include "GFace.h"
#include "GmshDefines.h"
#include "GmshMessage.h"
#include "OS.h"
#include "curvatureMetric.h"
#include "reparamCurvatureMetric.h"
#include "reparamHooks.h"
#include "reparamOptions.h"
#include "reparamReport.h"
#include "reparamState.h"
#include "reparamSurfaceMesh.h"
#include "surfaceMesh.h"

namespace reparam {

namespace {

  const double noSize = 1e22;

  // The metric is graded on the input (reparamBeginAnisotropicMeshing) by
  // this ratio, the usual one for anisotropic metrics: with Gmsh's
  // 1.8 (Mesh.SmoothRatio, which is BAMG's, in the plane) the long elements
  // along a vessel reach across its bends (bench/README.md, "The metric
  // field")
  const double gradation = 1.3;

  curvatureFieldRecord &recordOf(const GFace *gf)
  {
    std::unique_lock<std::mutex> lock = lockRecords();
    return faceRecordOf(gf).curvature;
  }

  bool applies(const GFace *gf)
  {
    const parametrizationRecord *record = findParametrization(gf);
    return getReparamOptions().curvatureMetric > 0. && record &&
           record->map > 0 && gf->geomType() == GEntity::DiscreteSurface &&
           !gf->stl_triangles.empty();
  }

  // gf's field for the current options (built once: curvatures of its
  // input, a search structure)
  const curvatureMetricField *fieldOf(const GFace *gf)
  {
    if(!applies(gf)) return nullptr;
    curvatureSizes sizes;
    sizes.elementsPerCircle = getReparamOptions().curvatureMetric;
    sizes.hMin = CTX::instance()->mesh.lcMin;
    sizes.hMax = std::min(CTX::instance()->mesh.lcMax, CTX::instance()->lc);
    sizes.gradation = gradation;
    // (built on the thread that asks first, not under lockRecords)
    std::unique_lock<std::mutex> lock = lockCurvatureFields();
    curvatureFieldRecord &f = recordOf(gf);
    const std::size_t triangles = gf->stl_triangles.size() / 3;
    if(f.field && f.n == sizes.elementsPerCircle && f.hMin == sizes.hMin &&
       f.hMax == sizes.hMax && f.gradation == sizes.gradation &&
       f.inputTriangles == triangles)
      return f.field.get();
    const double t0 = TimeOfDay();
    const surfaceMesh input = inputTriangulationOf(gf);
    f.field.reset(new curvatureMetricField(input, sizes));
    f.n = sizes.elementsPerCircle;
    f.hMin = sizes.hMin;
    f.hMax = sizes.hMax;
    f.gradation = sizes.gradation;
    f.inputTriangles = triangles;
    Msg::Info("Reparam: surface %d: sizes from the curvature of its input "
              "(2 pi R / %g within [%g, %g], graded by %g; %lu nodes, %g s)",
              gf->tag(), sizes.elementsPerCircle, sizes.hMin, sizes.hMax,
              sizes.gradation, input.points.size(), TimeOfDay() - t0);
    return f.field.get();
  }

  // A curve's size: the smallest of its faces' metrics there, not the size
  // along it: the curve bends within the surface too (an open border,
  // a cut), which the surface's curvature does not tell (bench/README.md,
  // "The metric in Gmsh's size functions")
  double curveSize(GEdge *ge, const SPoint3 &p)
  {
    double size = noSize;
    for(GFace *gf : ge->faces()) {
      const curvatureMetricField *f = fieldOf(gf);
      if(f) size = std::min(size, f->smallestSizeAt(p));
    }
    return size;
  }

} // namespace

} // namespace reparam

using namespace reparam;

double reparamCurvatureMeshSize(GEntity *ge, double /* u */, double x, double y,
                                double z)
{
  if(!ge || getReparamOptions().curvatureMetric <= 0.) return noSize;
  const SPoint3 p(x, y, z);
  if(ge->dim() == 2) {
    const curvatureMetricField *f = fieldOf((GFace *)ge);
    return f ? f->smallestSizeAt(p) : noSize;
  }
  if(ge->dim() != 1) return noSize;
  return curveSize((GEdge *)ge, p);
}

void reparamIntersectCurvatureMetric(GEntity *ge, double /* u */, double x,
                                     double y, double z, SMetric3 &metric)
{
  if(!ge || getReparamOptions().curvatureMetric <= 0.) return;
  const SPoint3 p(x, y, z);
  if(ge->dim() == 2) {
    const curvatureMetricField *f = fieldOf((GFace *)ge);
    if(f) metric = intersectAlong(f->at(p), metric);
  }
  else if(ge->dim() == 1) {
    // a curve (BAMG's 1D meshes take the metric along them)
    const double size = curveSize((GEdge *)ge, p);
    if(size < noSize)
      metric = intersectAlong(metric, SMetric3(1. / (size * size)));
  }
}

namespace reparam {

bool reparamAnisotropicFace(const GFace *gf)
{
  return gf->getMeshingAlgo() == ALGO_2D_BAMG && applies(gf);
}

// Mesh.SmoothRatio while a face is meshed by BAMG with the metric (the
// user's saved, -1: not changed): BAMG grades the metric in the (u, v)
// plane, where the map's conformal factor changes the sizes as much as the
// surface does (a tube mapped to an annulus: by e^z), so BAMG's own grading
// is off (a ratio below 1.1) and the metric is graded on the input instead
void reparamBeginAnisotropicMeshing(GFace *gf)
{
  double &userSmoothRatio = savedGmshOptions().smoothRatio;
  if(!reparamAnisotropicFace(gf) || userSmoothRatio >= 0.) return;
  userSmoothRatio = CTX::instance()->mesh.smoothRatio;
  CTX::instance()->mesh.smoothRatio = 1.;
}

void reparamEndAnisotropicMeshing()
{
  double &userSmoothRatio = savedGmshOptions().smoothRatio;
  if(userSmoothRatio < 0.) return;
  CTX::instance()->mesh.smoothRatio = userSmoothRatio;
  userSmoothRatio = -1.;
}
} // namespace reparam

