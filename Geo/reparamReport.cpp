// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The quality line of a newly meshed discrete face (hook in
// discreteFace::mesh, patches/0001): shape of the elements and fidelity to
// the triangulation the face was parametrized from.

#include <algorithm>
#include <cstdio>
#include <string>
#include "GFace.h"
#include "GModel.h"
#include "MLine.h"
#include "MTriangle.h"
// after its prerequisites (it includes none)
#include "GModelParametrize.h"
#include "GmshMessage.h"
#include "OS.h"
#include "meshFidelity.h"
#include "reparamOptions.h"
#include "faceQuality.h"

void reparamReportMeshedFace(GFace *gf, double seconds)
{
  if(!getReparamOptions().report) return;
  int map = getReparamOptions().parametrization;
  faceQuality q = computeFaceQuality({gf});
  double t0 = TimeOfDay();
  meshFidelity f = compareToInput(inputTriangulationOf(gf), surfaceMeshOf(gf));
  double diagonal = f.diagonal > 0. ? f.diagonal : 1.;
  // The elements are oriented once all faces are meshed (orientMeshGFace,
  // by a vote of all elements: Geo/reparamOrient.cpp), so that the minority
  // is what will point against the input normals
  std::size_t inverted = std::min(f.inverted, f.elements - f.inverted);
  std::string eta;
  if(q.quadrangles) {
    char s[64];
    snprintf(s, sizeof(s), ", eta min %.3f mean %.3f", q.etaMin, q.etaMean);
    eta = s;
  }
  Msg::Info("Reparam: surface %d (%s map): planar mesh %.3g s, %lu "
            "triangles, %lu quadrangles, kappa min %.3f mean %.3f, "
            "%.1f%% below 0.3%s, tau %.1f%%, Hausdorff %.3g%% (mean %.3g%%) "
            "of the diagonal, %lu inverted (%.3g s)",
            gf->tag(), compoundParametrizationName(map), seconds, q.triangles,
            q.quadrangles, q.kappaMin, q.kappaMean, 100. * q.kappaShareBelow03,
            eta.c_str(), q.tau, 100. * f.hausdorff / diagonal,
            100. * f.meanDistance / diagonal, inverted, TimeOfDay() - t0);
}
