// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include "BackgroundMeshTools.h"
#include "GFace.h"
#include "efficiencyIndex.h"
#include "faceQuality.h"
#include "quadQuality.h"
#include "reparamSurfaceMesh.h"
#include "reparamTriangleQuality.h"
#include "surfaceMesh.h"

namespace reparam {

faceQuality computeFaceQuality(const std::vector<GFace *> &faces)
{
  faceQuality q;
  std::vector<MTriangle *> triangles;
  double edges = 0., tauLogSum = 0.;
  for(GFace *gf : faces) {
    triangles.insert(triangles.end(), gf->triangles.begin(),
                     gf->triangles.end());
    surfaceMesh m = surfaceMeshOf(gf);
    for(const auto &e : m.quadrangles) {
      double eta =
        quadEta(m.points[e[0]], m.points[e[1]], m.points[e[2]], m.points[e[3]]);
      q.etaMin = q.quadrangles ? std::min(q.etaMin, eta) : eta;
      q.etaMean += eta;
      q.quadrangles++;
    }
    std::vector<std::array<int, 2> > unique =
      uniqueEdges(m.triangles, m.quadrangles);
    if(unique.empty()) continue;
    double tau = efficiencyIndex(m.points, unique, [gf](const SPoint3 &x) {
      return BGM_MeshSize(gf, 0., 0., x.x(), x.y(), x.z());
    });
    // tau is the exponential of a mean: combine faces on the mean
    tauLogSum += std::log(tau / 100.) * unique.size();
    edges += unique.size();
  }
  if(q.quadrangles) q.etaMean /= q.quadrangles;
  if(edges > 0.) q.tau = 100. * std::exp(tauLogSum / edges);
  q.edges = (std::size_t)edges;
  kappaStatistics k = computeKappaStatistics(triangles);
  q.triangles = k.triangles;
  q.kappaMin = k.min;
  q.kappaMean = k.mean;
  q.kappaShareBelow03 = k.shareBelow03;
  return q;
}
} // namespace reparam

