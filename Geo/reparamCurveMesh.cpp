// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <cmath>
#include <map>
#include <set>
#include "GEdge.h"
#include "GModel.h"
#include "GVertex.h"
#include "GmshMessage.h"
#include "MVertex.h"
#include "curveCornerSnap.h"
#include "edgeByCoordinates.h"
#include "reparamCurveMesh.h"
#include "reparamOptions.h"

namespace {

  // The input nodes a curve's mesh took as corners, and which curve: two
  // curves through the same input node (non-manifold input) must not both
  // put a node there
  typedef std::array<double, 3> pointByCoordinates;
  std::map<pointByCoordinates, const GEdge *> &takenCorners()
  {
    static std::map<pointByCoordinates, const GEdge *> corners;
    return corners;
  }

  std::set<edgeByCoordinates> &smoothCuts()
  {
    static std::set<edgeByCoordinates> cuts;
    return cuts;
  }

  // Whether most segments of the polyline are smooth cuts of the layout
  bool isSmoothCut(const std::vector<SPoint3> &polyline)
  {
    if(smoothCuts().empty()) return false;
    std::size_t cuts = 0;
    for(std::size_t i = 0; i + 1 < polyline.size(); i++)
      cuts += smoothCuts().count(byCoordinates(polyline[i], polyline[i + 1]));
    return 2 * cuts > polyline.size() - 1;
  }

} // namespace

void reparamRecordSmoothCuts(const std::vector<std::array<SPoint3, 2> > &edges)
{
  smoothCuts().clear();
  for(const auto &e : edges) smoothCuts().insert(byCoordinates(e[0], e[1]));
}

void reparamSnapCurveMesh(GEdge *ge, std::vector<MVertex *> &nodes)
{
  if(nodes.empty() || ge->geomType() != GEntity::DiscreteCurve ||
     getReparamOptions().parametrization ==
       (int)compoundParametrization::gmsh ||
     !getReparamOptions().curveCorners)
    return;
  // a discrete curve's parameter runs over its input nodes, node i at i
  const Range<double> bounds = ge->parBounds(0);
  const int last = (int)std::lround(bounds.high());
  if(bounds.low() != 0. || last < 2 || std::fabs(bounds.high() - last) > 1e-12)
    return;
  std::vector<SPoint3> polyline(last + 1);
  for(int i = 0; i <= last; i++) {
    GPoint p = ge->point(i);
    polyline[i] = SPoint3(p.x(), p.y(), p.z());
  }
  if(isSmoothCut(polyline)) return;
  std::vector<double> params(nodes.size() + 2);
  params.front() = 0.;
  params.back() = last;
  for(std::size_t k = 0; k < nodes.size(); k++)
    if(!nodes[k]->getParameter(0, params[k + 1])) return;
  for(std::size_t k = 0; k + 1 < params.size(); k++)
    if(!(params[k] < params[k + 1])) return; // not in order: leave it
  // nor where a model vertex is, that another curve ends at (non-manifold
  // input: a curve through the end of others)
  std::set<pointByCoordinates> vertices;
  for(auto it = ge->model()->firstVertex(); it != ge->model()->lastVertex();
      ++it)
    vertices.insert({{(*it)->x(), (*it)->y(), (*it)->z()}});
  auto allowed = [&](int i) {
    const pointByCoordinates p = {{polyline[i].x(), polyline[i].y(),
                                   polyline[i].z()}};
    if(vertices.count(p)) return false;
    auto it = takenCorners().find(p);
    return it == takenCorners().end() || it->second == ge;
  };
  std::vector<int> corners;
  const std::vector<double> snapped =
    snapCurveNodesToCorners(polyline, params, allowed, &corners);
  for(int i : corners)
    takenCorners()[{{polyline[i].x(), polyline[i].y(), polyline[i].z()}}] = ge;
  if(snapped == params) return;
  // the same nodes moved, new ones made or the last ones dropped when a
  // piece between corners got another count
  const std::size_t count = snapped.size() - 2;
  for(std::size_t k = count; k < nodes.size(); k++) delete nodes[k];
  const std::size_t kept = std::min(count, nodes.size());
  nodes.resize(count, nullptr);
  for(std::size_t k = 0; k < count; k++) {
    const double t = snapped[k + 1];
    GPoint p = ge->point(t);
    if(k >= kept) {
      nodes[k] = new MEdgeVertex(p.x(), p.y(), p.z(), ge, t);
      continue;
    }
    nodes[k]->setParameter(0, t);
    nodes[k]->setXYZ(p.x(), p.y(), p.z());
  }
  Msg::Debug("Reparam: curve %d: nodes on the input's corners (%lu nodes, "
             "%lu before)",
             ge->tag(), nodes.size(), params.size() - 2);
}
