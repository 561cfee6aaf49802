// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <array>
#include <map>
#include <set>
#include <string>
#include "BackgroundMeshTools.h"
#include "Context.h"
#include "GFace.h"
#include "GModel.h"
#include "GmshMessage.h"
#include "MLine.h"
#include "MPoint.h"
#include "MVertex.h"
#include "creaseChains.h"
#include "discreteEdge.h"
#include "discreteVertex.h"
#include "reparamConePoints.h"
#include "reparamCurveMesh.h"
#include "reparamCreaseCurves.h"

namespace reparam {

namespace {

  // The crease curves made, by model
  std::map<const GModel *, std::set<const GEdge *> > &creaseCurves()
  {
    static std::map<const GModel *, std::set<const GEdge *> > curves;
    return curves;
  }

  // The crease curves taken out of a face being recombined
  std::map<GFace *, std::vector<GEdge *> > &hiddenCurves()
  {
    static std::map<GFace *, std::vector<GEdge *> > curves;
    return curves;
  }

  // The model point at p embedded in gf (a tip kept before), else a new
  // one, with its mesh node
  GVertex *pointAt(GFace *gf, const SPoint3 &p)
  {
    for(GVertex *v : gf->embeddedVertices())
      if(v->x() == p.x() && v->y() == p.y() && v->z() == p.z()) return v;
    GModel *m = gf->model();
    for(auto it = m->firstVertex(); it != m->lastVertex(); ++it)
      if((*it)->x() == p.x() && (*it)->y() == p.y() && (*it)->z() == p.z())
        return *it;
    discreteVertex *v = new discreteVertex(m, m->getMaxElementaryNumber(0) + 1,
                                           p.x(), p.y(), p.z());
    m->add(v);
    MVertex *node = new MVertex(p.x(), p.y(), p.z(), v);
    v->mesh_vertices.push_back(node);
    v->points.push_back(new MPoint(node));
    return v;
  }

  // A discrete curve along the chain's points, embedded in gf
  bool embedChain(GFace *gf, const std::vector<SPoint3> &points,
                  const std::vector<int> &chain)
  {
    GModel *m = gf->model();
    GVertex *begin = pointAt(gf, points[chain.front()]);
    GVertex *end = pointAt(gf, points[chain.back()]);
    if(begin->mesh_vertices.empty() || end->mesh_vertices.empty()) return false;
    discreteEdge *curve =
      new discreteEdge(m, m->getMaxElementaryNumber(1) + 1, begin, end);
    m->add(curve);
    MVertex *previous = begin->mesh_vertices[0];
    for(std::size_t i = 1; i < chain.size(); i++) {
      MVertex *next = end->mesh_vertices[0];
      if(i + 1 < chain.size()) {
        const SPoint3 &p = points[chain[i]];
        next = new MVertex(p.x(), p.y(), p.z(), curve);
        curve->mesh_vertices.push_back(next);
      }
      curve->lines.push_back(new MLine(previous, next));
      previous = next;
    }
    if(curve->createGeometry()) {
      m->remove(curve);
      delete curve;
      return false;
    }
    gf->addEmbeddedEdge(curve);
    creaseCurves()[m].insert(curve);
    return true;
  }

  // Whether crease ge of gf is too small for the mesh size at its middle
  // (creaseTooSmallForMesh), against gf's other curves that do not end
  // where it does
  bool tooSmallForTheMesh(GFace *gf, GEdge *ge)
  {
    std::vector<SPoint3> crease;
    if(!reparamInputPolyline(ge, crease) || crease.size() < 2) return false;
    const SPoint3 &middle = crease[crease.size() / 2];
    const double size =
      BGM_MeshSize(ge, 0., 0., middle.x(), middle.y(), middle.z());
    std::vector<GEdge *> curves = gf->edges();
    curves.insert(curves.end(), gf->embeddedEdges().begin(),
                  gf->embeddedEdges().end());
    std::vector<std::vector<SPoint3> > others;
    for(GEdge *other : curves) {
      std::vector<SPoint3> line;
      const bool touches = other->getBeginVertex() == ge->getBeginVertex() ||
                           other->getBeginVertex() == ge->getEndVertex() ||
                           other->getEndVertex() == ge->getBeginVertex() ||
                           other->getEndVertex() == ge->getEndVertex();
      if(other != ge && !touches && reparamInputPolyline(other, line))
        others.push_back(line);
    }
    return creaseTooSmallForMesh(crease, others, size);
  }

  // The crease curves taken out of their faces for their size, by model
  std::map<const GModel *, std::set<GEdge *> > &smallCreases()
  {
    static std::map<const GModel *, std::set<GEdge *> > curves;
    return curves;
  }

  // Whether gv is embedded in a face of m or ends a curve still in use
  bool pointInUse(GModel *m, GVertex *gv)
  {
    for(GEdge *ge : gv->edges())
      if(!reparamCreaseCurveHidden(ge)) return true;
    for(auto it = m->firstFace(); it != m->lastFace(); ++it)
      for(GVertex *v : (*it)->embeddedVertices())
        if(v == gv) return true;
    return false;
  }

} // namespace

int reparamEmbedCreaseCurves(GFace *gf, const std::vector<MVertex *> &nodes,
                             const std::vector<SPoint3> &points,
                             const std::vector<int> &triangleNodes)
{
  const double size = reparamLayoutNoiseSize();
  if(size <= 0.) return 0;
  std::vector<std::array<int, 3> > triangles(triangleNodes.size() / 3);
  for(std::size_t t = 0; t < triangles.size(); t++)
    for(int j = 0; j < 3; j++) triangles[t][j] = triangleNodes[3 * t + j];
  std::vector<SPoint3> boundary;
  for(std::size_t i = 0; i < points.size() && i < nodes.size(); i++) {
    GEntity *on = nodes[i]->onWhat();
    if(on && on->dim() < 2) boundary.push_back(points[i]);
  }
  const std::vector<std::vector<int> > chains = creaseChains(
    points, triangles,
    [&points](int a, int b) {
      return reparamIsMergedCrease(points[a], points[b]);
    },
    boundary, 0.5 * size, 2. * size);
  int added = 0;
  for(const auto &chain : chains)
    if(chain.front() != chain.back()) added += embedChain(gf, points, chain);
  if(added)
    Msg::Info("Reparam: surface %d: %d sharp crease%s inside it kept as "
              "embedded curve%s",
              gf->tag(), added, added > 1 ? "s" : "", added > 1 ? "s" : "");
  return added;
}

int reparamHideSmallCreaseCurves(GModel *m)
{
  auto found = creaseCurves().find(m);
  if(found == creaseCurves().end()) return 0;
  std::set<GEdge *> &small = smallCreases()[m];
  std::set<int> faces;
  for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
    GFace *gf = *it;
    std::vector<GEdge *> &embedded = gf->embeddedEdges();
    std::vector<GEdge *> kept, hidden;
    for(GEdge *ge : embedded)
      (found->second.count(ge) && tooSmallForTheMesh(gf, ge) ? hidden : kept)
        .push_back(ge);
    if(hidden.empty()) continue;
    embedded.swap(kept);
    std::vector<GEdge *> &out = hiddenCurves()[gf];
    out.insert(out.end(), hidden.begin(), hidden.end());
    small.insert(hidden.begin(), hidden.end());
    faces.insert(gf->tag());
  }
  if(small.empty()) return 0;
  std::string tags;
  for(int tag : faces) tags += (tags.empty() ? "" : ", ") + std::to_string(tag);
  Msg::Info("Reparam: %lu crease curve%s too small for the mesh size (bent, "
            "or ending by another curve) not kept (surface%s %s)",
            small.size(), small.size() > 1 ? "s" : "",
            faces.size() > 1 ? "s" : "", tags.c_str());
  return (int)small.size();
}

void reparamDeleteHiddenCreaseMeshes(GModel *m)
{
  auto found = smallCreases().find(m);
  if(found == smallCreases().end()) return;
  for(GEdge *ge : found->second) {
    ge->deleteMesh();
    for(GVertex *gv : {ge->getBeginVertex(), ge->getEndVertex()})
      if(gv && !pointInUse(m, gv)) gv->deleteMesh();
  }
}

bool reparamCreaseCurveHidden(const GEdge *ge)
{
  auto found = smallCreases().find(ge->model());
  return found != smallCreases().end() &&
         found->second.count(const_cast<GEdge *>(ge));
}

void reparamHideCreaseCurvesFromQuads(GFace *gf)
{
  if(!CTX::instance()->mesh.recombineAll && !gf->meshAttributes.recombine)
    return;
  const std::set<const GEdge *> &creases = creaseCurves()[gf->model()];
  std::vector<GEdge *> &embedded = gf->embeddedEdges();
  std::vector<GEdge *> kept, hidden;
  for(GEdge *ge : embedded) (creases.count(ge) ? hidden : kept).push_back(ge);
  if(hidden.empty()) return;
  embedded.swap(kept);
  for(GEdge *ge : hidden) ge->deleteMesh();
  std::vector<GEdge *> &out = hiddenCurves()[gf];
  out.insert(out.end(), hidden.begin(), hidden.end());
  Msg::Info("Reparam: surface %d: %lu crease curve%s not kept, for its "
            "quadrangles",
            gf->tag(), hidden.size(), hidden.size() > 1 ? "s" : "");
}

void reparamRestoreCreaseCurves(GFace *gf)
{
  auto it = hiddenCurves().find(gf);
  if(it == hiddenCurves().end()) return;
  auto small = smallCreases().find(gf->model());
  for(GEdge *ge : it->second) {
    gf->addEmbeddedEdge(ge);
    if(small != smallCreases().end()) small->second.erase(ge);
  }
  hiddenCurves().erase(it);
}
} // namespace reparam

