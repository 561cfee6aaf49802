// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include "BackgroundMeshTools.h"
#include "Context.h"
#include "GEdge.h"
#include "GFace.h"
#include "GModel.h"
#include "GVertex.h"
#include "GmshMessage.h"
#include "MVertex.h"
#include "curveCornerSnap.h"
#include "edgeByCoordinates.h"
#include "gradedCurveNodes.h"
#include "reparamCurveMesh.h"
#include "reparamHooks.h"
#include "reparamOptions.h"
#include "reparamSizeGrading.h"
#include "reparamState.h"

namespace reparam {

namespace {

  // The input nodes a curve's mesh took as corners, and which curve: two
  // curves through the same input node (non-manifold input) must not both
  // put a node there
  std::map<pointByCoordinates, cornerOwner> &takenCorners()
  {
    return lastLayout().takenCorners;
  }

  // Whether another curve of ge's model holds the corner (a curve of a
  // model gone, or gone from it, holds none)
  bool takenByAnother(const cornerOwner &owner, GEdge *ge)
  {
    GModel *m = ge->model();
    return owner.curve != ge && owner.model == m &&
           m->getEdgeByTag(owner.tag) == owner.curve;
  }

  std::set<edgeByCoordinates> &smoothCuts() { return lastLayout().smoothCuts; }

  // Whether most segments of the polyline are smooth cuts of the layout
  bool isSmoothCut(const std::vector<SPoint3> &polyline)
  {
    if(smoothCuts().empty()) return false;
    std::size_t cuts = 0;
    for(std::size_t i = 0; i + 1 < polyline.size(); i++)
      cuts += smoothCuts().count(byCoordinates(polyline[i], polyline[i + 1]));
    return 2 * cuts > polyline.size() - 1;
  }

  // The input edges no mesh may cross: sharp (Gmsh's classification
  // lines), border and non-manifold ones
  std::set<edgeByCoordinates> &fixedEdges() { return lastLayout().fixedEdges; }

} // namespace

void reparamRecordFixedEdges(const std::vector<std::array<SPoint3, 2> > &edges)
{
  fixedEdges().clear();
  for(const auto &e : edges) fixedEdges().insert(byCoordinates(e[0], e[1]));
}

void reparamRecordSmoothCuts(const std::vector<std::array<SPoint3, 2> > &edges)
{
  // a new layout: new curves, whose meshes take their corners anew
  takenCorners().clear();
  smoothCuts().clear();
  for(const auto &e : edges) smoothCuts().insert(byCoordinates(e[0], e[1]));
}

namespace {

  // (of at least `fewest` segments)
  bool inputPolyline(GEdge *ge, std::vector<SPoint3> &polyline, int fewest = 2)
  {
    const Range<double> bounds = ge->parBounds(0);
    const int last = (int)std::lround(bounds.high());
    if(bounds.low() != 0. || last < fewest ||
       std::fabs(bounds.high() - last) > 1e-12)
      return false;
    polyline.resize(last + 1);
    for(int i = 0; i <= last; i++) {
      GPoint p = ge->point(i);
      polyline[i] = SPoint3(p.x(), p.y(), p.z());
    }
    return true;
  }

  // The nodes' parameters with the curve's ends, in increasing order; false
  // if a node has none or they are not in order (then left alone)
  bool nodeParameters(const std::vector<MVertex *> &nodes, double last,
                      std::vector<double> &params)
  {
    params.assign(nodes.size() + 2, 0.);
    params.back() = last;
    for(std::size_t k = 0; k < nodes.size(); k++)
      if(!nodes[k]->getParameter(0, params[k + 1])) return false;
    for(std::size_t k = 0; k + 1 < params.size(); k++)
      if(!(params[k] < params[k + 1])) return false;
    return true;
  }

  pointByCoordinates byCoordinates(const SPoint3 &p)
  {
    return {{p.x(), p.y(), p.z()}};
  }

  // The same nodes moved to the new parameters, new ones made or the last
  // ones dropped when a piece between corners got another count
  void moveNodes(GEdge *ge, const std::vector<double> &snapped,
                 std::vector<MVertex *> &nodes)
  {
    const std::size_t count = snapped.size() - 2;
    for(std::size_t k = count; k < nodes.size(); k++) delete nodes[k];
    const std::size_t kept = std::min(count, nodes.size());
    nodes.resize(count, nullptr);
    for(std::size_t k = 0; k < count; k++) {
      const double t = snapped[k + 1];
      GPoint p = ge->point(t);
      if(k >= kept) {
        // no size of its own (-1): Gmsh asks its size field when it needs
        nodes[k] = new MEdgeVertex(p.x(), p.y(), p.z(), ge, t);
        continue;
      }
      nodes[k]->setParameter(0, t);
      nodes[k]->setXYZ(p.x(), p.y(), p.z());
    }
  }

} // namespace

bool reparamIsCrossableCurve(GEdge *ge)
{
  std::vector<SPoint3> polyline;
  if(ge->geomType() != GEntity::DiscreteCurve || !inputPolyline(ge, polyline))
    return false;
  for(std::size_t i = 0; i + 1 < polyline.size(); i++)
    if(fixedEdges().count(byCoordinates(polyline[i], polyline[i + 1])))
      return false;
  return true;
}

namespace {

  // Whether Gmsh's 1D mesher would give the curve an even number of
  // segments: Blossom recombines a face of its into quadrangles
  // (meshGEdge.cpp's rule)
  bool evenForBlossom(GEdge *ge)
  {
    if(!CTX::instance()->mesh.algoRecombine || ge->faces().empty())
      return false;
    if(CTX::instance()->mesh.recombineAll) return true;
    for(GFace *gf : ge->faces())
      if(gf->meshAttributes.recombine) return true;
    return false;
  }

  // The nodes spread by the sizes graded from the ends of the short curves
  // (Geo/sizes/reparamSizeGrading.h), where they are smaller than Gmsh's
  void gradeCurveMesh(GEdge *ge, std::vector<MVertex *> &nodes)
  {
    std::vector<SPoint3> polyline;
    if(!reparamCurveSizesGraded(ge) || !inputPolyline(ge, polyline, 1)) return;
    auto gmshSize = [ge](const SPoint3 &x, double t) {
      return BGM_MeshSize(ge, t, 0., x.x(), x.y(), x.z());
    };
    bool smaller = false;
    for(std::size_t i = 0; i < polyline.size() && !smaller; i++) {
      const double size = gmshSize(polyline[i], (double)i);
      smaller = reparamGradedCurveSize(ge, polyline[i], size) < size;
    }
    if(!smaller) return;
    // a closed curve needs 3 segments to bound anything
    int fewest = std::max(1, CTX::instance()->mesh.minCurveNodes - 1);
    if(ge->getBeginVertex() == ge->getEndVertex()) fewest = std::max(fewest, 3);
    const std::vector<double> params = gradedCurveParameters(
      polyline,
      [&](const SPoint3 &x, double t) {
        return reparamGradedCurveSize(ge, x, gmshSize(x, t));
      },
      fewest, evenForBlossom(ge));
    const std::size_t before = nodes.size();
    moveNodes(ge, params, nodes);
    Msg::Debug("Reparam: curve %d: sizes graded from the short curves' ends "
               "(%lu nodes, %lu before)",
               ge->tag(), nodes.size(), before);
  }

} // namespace

} // namespace reparam

using namespace reparam;

void reparamSnapCurveMesh(GEdge *ge, std::vector<MVertex *> &nodes)
{
  if(ge->geomType() != GEntity::DiscreteCurve ||
     getReparamOptions().parametrization == (int)compoundParametrization::gmsh)
    return;
  gradeCurveMesh(ge, nodes);
  if(nodes.empty() || !getReparamOptions().curveCorners) return;
  std::vector<SPoint3> polyline;
  std::vector<double> params;
  if(!inputPolyline(ge, polyline) || isSmoothCut(polyline) ||
     !nodeParameters(nodes, polyline.size() - 1., params))
    return;
  // not on a model point, that another curve ends at (non-manifold input: a
  // curve through the end of others), nor on another curve's corner
  std::set<pointByCoordinates> vertices;
  for(auto it = ge->model()->firstVertex(); it != ge->model()->lastVertex();
      ++it)
    vertices.insert(byCoordinates((*it)->xyz()));
  auto allowed = [&](int i) {
    const pointByCoordinates p = byCoordinates(polyline[i]);
    auto it = takenCorners().find(p);
    return !vertices.count(p) &&
           (it == takenCorners().end() || !takenByAnother(it->second, ge));
  };
  std::vector<int> corners;
  const std::vector<double> snapped = snapCurveNodesToCorners(
    polyline, params, allowed, &corners, evenForBlossom(ge),
    reparamCurveAlongNarrowStrip(ge));
  for(int i : corners)
    takenCorners()[byCoordinates(polyline[i])] = {ge->model(), ge->tag(), ge};
  if(snapped == params) return;
  moveNodes(ge, snapped, nodes);
  Msg::Debug("Reparam: curve %d: nodes on the input's corners (%lu nodes, "
             "%lu before)",
             ge->tag(), nodes.size(), params.size() - 2);
}

namespace reparam {

bool reparamInputPolyline(GEdge *ge, std::vector<SPoint3> &polyline)
{
  return ge->geomType() == GEntity::DiscreteCurve &&
         inputPolyline(ge, polyline, 1);
}
} // namespace reparam

