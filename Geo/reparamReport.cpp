// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The quality line of a newly meshed discrete face (hook in
// discreteFace::mesh, patches/0001).

#include "GFace.h"
#include "GModel.h"
#include "MLine.h"
#include "MTriangle.h"
// after its prerequisites (it includes none)
#include "GModelParametrize.h"
#include "GmshMessage.h"
#include "reparamOptions.h"
#include "triangleQuality.h"

void reparamReportMeshedFace(GFace *gf, double seconds)
{
  int map = getReparamOptions().parametrization;
  kappaStatistics k = computeKappaStatistics(gf->triangles);
  Msg::Info("Reparam: surface %d (%s map): planar mesh %.3g s, %lu "
            "triangles, %lu quadrangles, kappa min %.3f mean %.3f, "
            "%.1f%% below 0.3",
            gf->tag(), compoundParametrizationName(map), seconds,
            gf->triangles.size(), gf->quadrangles.size(), k.min, k.mean,
            100. * k.shareBelow03);
}
