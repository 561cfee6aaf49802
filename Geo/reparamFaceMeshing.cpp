// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "reparamCreaseCurves.h"
#include "reparamFaceMeshing.h"
#include "reparamSizeGrading.h"

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
