// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <array>
#include <mutex>
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
#include "reparamState.h"

namespace reparam {

namespace {

  // gf's crease curves taken out of it (for its quadrangles, or their
  // size) join those already out
  void recordHidden(GFace *gf, const std::vector<GEdge *> &hidden)
  {
    std::unique_lock<std::mutex> lock = lockRecords();
    std::vector<GEdge *> &out = faceRecordOf(gf).hiddenCreases;
    out.insert(out.end(), hidden.begin(), hidden.end());
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
    std::unique_lock<std::mutex> lock = lockRecords();
    modelRecordOf(m).creaseCurves.insert(curve);
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
  std::unique_lock<std::mutex> lock = lockRecords();
  modelRecord *record = findModelRecord(m);
  lock.unlock();
  if(!record) return 0;
  // (main thread: Mesh1D starts)
  const std::set<const GEdge *> &creases = record->creaseCurves;
  std::set<GEdge *> &small = record->smallCreases;
  std::set<int> faces;
  for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
    GFace *gf = *it;
    std::vector<GEdge *> &embedded = gf->embeddedEdges();
    std::vector<GEdge *> kept, hidden;
    for(GEdge *ge : embedded)
      (creases.count(ge) && tooSmallForTheMesh(gf, ge) ? hidden : kept)
        .push_back(ge);
    if(hidden.empty()) continue;
    embedded.swap(kept);
    recordHidden(gf, hidden);
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
  std::unique_lock<std::mutex> lock = lockRecords();
  const modelRecord *record = findModelRecord(m);
  lock.unlock();
  if(!record) return;
  for(GEdge *ge : record->smallCreases) {
    ge->deleteMesh();
    for(GVertex *gv : {ge->getBeginVertex(), ge->getEndVertex()})
      if(gv && !pointInUse(m, gv)) gv->deleteMesh();
  }
}

bool reparamCreaseCurveHidden(const GEdge *ge)
{
  std::unique_lock<std::mutex> lock = lockRecords();
  const modelRecord *record = findModelRecord(ge->model());
  return record && record->smallCreases.count(const_cast<GEdge *>(ge));
}

void reparamHideCreaseCurvesFromQuads(GFace *gf)
{
  if(!CTX::instance()->mesh.recombineAll && !gf->meshAttributes.recombine)
    return;
  std::unique_lock<std::mutex> lock = lockRecords();
  const std::set<const GEdge *> &creases =
    modelRecordOf(gf->model()).creaseCurves;
  lock.unlock();
  // (faces recombined are meshed on one thread)
  std::vector<GEdge *> &embedded = gf->embeddedEdges();
  std::vector<GEdge *> kept, hidden;
  for(GEdge *ge : embedded) (creases.count(ge) ? hidden : kept).push_back(ge);
  if(hidden.empty()) return;
  embedded.swap(kept);
  for(GEdge *ge : hidden) ge->deleteMesh();
  recordHidden(gf, hidden);
  Msg::Info("Reparam: surface %d: %lu crease curve%s not kept, for its "
            "quadrangles",
            gf->tag(), hidden.size(), hidden.size() > 1 ? "s" : "");
}

void reparamRestoreCreaseCurves(GFace *gf)
{
  // faces on other threads restore theirs (the model's small creases)
  std::unique_lock<std::mutex> lock = lockRecords();
  faceRecord *record = findFaceRecord(gf);
  if(!record) return;
  std::vector<GEdge *> hidden;
  hidden.swap(record->hiddenCreases);
  modelRecord *model = findModelRecord(gf->model());
  for(GEdge *ge : hidden) {
    gf->addEmbeddedEdge(ge);
    if(model) model->smallCreases.erase(ge);
  }
}
} // namespace reparam

