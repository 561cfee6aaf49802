// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "reparamCreaseCurves.h"
#include "reparamFaceMeshing.h"
#include "reparamReport.h"
#include "reparamSizeGrading.h"
#include "GFace.h"

void reparamBeginFaceMeshing(GFace *gf)
{
  reparamHideCreaseCurvesFromQuads(gf);
  reparamBeginSizeGrading(gf);
}

void reparamEndFaceMeshing(GFace *gf)
{
  reparamEndSizeGrading(gf);
  reparamRestoreCreaseCurves(gf);
}

bool reparamRecombineWithParametrization(GFace *gf)
{
  const parametrizationRecord *record = findParametrization(gf);
  return record && record->map > 0 && gf->haveParametrization();
}
