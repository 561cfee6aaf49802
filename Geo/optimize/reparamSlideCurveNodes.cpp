// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <map>
#include <memory>
#include <set>
#include "GEdge.h"
#include "GFace.h"
#include "GModel.h"
#include "GVertex.h"
#include "GmshMessage.h"
#include "MLine.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "OS.h"
#include "closestTriangle.h"
#include "curveNodeSlide.h"
#include "meshFidelity.h"
#include "reparamCurveMesh.h"
#include "reparamHooks.h"
#include "reparamOptimizableMesh.h"
#include "reparamReport.h"
#include "reparamSlideCurveNodes.h"
#include "reparamSurfaceMesh.h"
#include "triangleQuality.h"

namespace reparam {

namespace {

  // the rings worth a try: a triangle below this
  const double target = 0.6;
  // a triangle's normal turns by no more than this (radians) in a slide
  const double maxTurn = 0.5;
  // the curve's segments stay within this share of their length of the
  // input polyline (or no farther than they were)
  const double sag = 0.05;
  // ... and for the mean, this share: it is not worth cutting a corner of
  // the curve off (a node on a right-angled corner of a border moved 0.05
  // of its segments' length off it)
  const double meanSag = 0.01;
  // a node slides onto the polyline's node its chords pass farther from
  // than this share of their length (the optimization inserts the input
  // nodes a face's mesh passes a quarter of its edges from), if the worst
  // triangle around stays at or above the lower of its worst and
  // fidelityFloor (the optimization's target), and no triangle turns by
  // more than fidelityTurn (radians): onto a tip they turn with the input
  // (bench/README.md, Curve nodes slid along their curves)
  const double cutOff = 0.25, fidelityFloor = 0.6, fidelityTurn = 1.;

  struct triangleAround {
    MTriangle *triangle;
    GFace *face;
  };

  // A face's input and its closest-triangle search, built when first asked
  class faceInputs {
  public:
    const surfaceMesh &input(GFace *gf) { return entry(gf).mesh; }
    const closestTriangleSearch &search(GFace *gf) { return *entry(gf).search; }

  private:
    struct entryOf {
      surfaceMesh mesh;
      std::unique_ptr<closestTriangleSearch> search;
    };
    std::map<GFace *, entryOf> _entries;
    entryOf &entry(GFace *gf)
    {
      entryOf &e = _entries[gf];
      if(!e.search) {
        e.mesh = inputTriangulationOf(gf);
        e.search.reset(
          new closestTriangleSearch(e.mesh.points, e.mesh.triangles));
      }
      return e;
    }
  };

  // The curve's nodes with their neighbours along it: the lines run along
  // the curve, from its begin point to its end point
  struct alongCurve {
    std::map<MVertex *, MVertex *> before, after;
  };
  alongCurve neighboursOf(const GEdge *ge)
  {
    alongCurve n;
    for(MLine *l : ge->lines) {
      n.after[l->getVertex(0)] = l->getVertex(1);
      n.before[l->getVertex(1)] = l->getVertex(0);
    }
    return n;
  }

  // The parameter of a neighbour of a node of ge: a curve node has its own,
  // the begin point 0, the end point the polyline's last
  bool parameterOf(MVertex *v, const GEdge *ge, bool isBefore, double last,
                   double &t)
  {
    if(v->onWhat() == ge) return v->getParameter(0, t);
    if(v->onWhat() && v->onWhat()->dim() == 0) {
      t = isBefore ? 0. : last;
      return true;
    }
    return false;
  }

  // Whether any triangle of the ring changes sides with its face's input
  // when the node moves from `from` to `to`
  bool changesSides(MVertex *node, const std::vector<triangleAround> &ring,
                    const SPoint3 &from, const SPoint3 &to, faceInputs &inputs)
  {
    for(const triangleAround &a : ring) {
      SPoint3 p[2][3];
      for(int j = 0; j < 3; j++) {
        MVertex *v = a.triangle->getVertex(j);
        p[0][j] = v == node ? from : v->point();
        p[1][j] = v == node ? to : v->point();
      }
      const surfaceMesh &input = inputs.input(a.face);
      const closestTriangleSearch &search = inputs.search(a.face);
      if(triangleAgainstInput(p[0][0], p[0][1], p[0][2], input, search) !=
         triangleAgainstInput(p[1][0], p[1][1], p[1][2], input, search))
        return true;
    }
    return false;
  }

  double worstOf(const std::vector<triangleAround> &ring)
  {
    double worst = 1.;
    for(const triangleAround &a : ring) {
      MTriangle *t = a.triangle;
      worst = std::min(worst, triangleKappa(t->getVertex(0)->point(),
                                            t->getVertex(1)->point(),
                                            t->getVertex(2)->point()));
    }
    return worst;
  }

  // The ring as Mesh/optimize/curveNodeSlide.h takes it
  curveNodeRing ringOf(MVertex *node, const std::vector<triangleAround> &ring)
  {
    curveNodeRing r;
    for(const triangleAround &a : ring) {
      MTriangle *t = a.triangle;
      for(int j = 0; j < 3; j++)
        if(t->getVertex(j) == node)
          r.opposite.push_back({{t->getVertex((j + 1) % 3)->point(),
                                 t->getVertex((j + 2) % 3)->point()}});
    }
    return r;
  }

  struct slideCounts {
    int moved = 0;
    std::set<GFace *> faces;
    std::set<GEdge *> curves;
  };

  // What a sweep slides the nodes for
  enum class slideFor { fidelity, worst, mean };

  // One sweep over ge's nodes: for fidelity, every node whose chords cut
  // the curve's polyline off by more than a quarter of their length; for
  // the worst triangle, those whose worst is below the target; for the
  // mean, every node
  void
  slideAlong(GEdge *ge,
             const std::map<MVertex *, std::vector<triangleAround> > &around,
             faceInputs &inputs, slideCounts &counts, slideFor aim)
  {
    std::vector<SPoint3> polyline;
    if(!reparamInputPolyline(ge, polyline) || polyline.size() < 2) return;
    const alongCurve n = neighboursOf(ge);
    const double last = polyline.size() - 1.;
    for(MVertex *v : ge->mesh_vertices) {
      auto found = around.find(v);
      if(found == around.end() ||
         (aim == slideFor::worst && worstOf(found->second) >= target))
        continue;
      auto b = n.before.find(v), a = n.after.find(v);
      if(b == n.before.end() || a == n.after.end()) continue;
      curveNodeRing ring = ringOf(v, found->second);
      ring.polyline = polyline;
      if(!v->getParameter(0, ring.t) ||
         !parameterOf(b->second, ge, true, last, ring.before) ||
         !parameterOf(a->second, ge, false, last, ring.after))
        continue;
      const curveNodeSlide s =
        aim == slideFor::mean ?
          slideCurveNodeForMean(ring, target, 1e-3, maxTurn, meanSag) :
        aim == slideFor::worst ?
          slideCurveNode(ring, 1e-3, maxTurn, sag) :
          slideCurveNodeToFarthest(ring, cutOff, fidelityFloor, fidelityTurn);
      if(s.t == ring.t) continue;
      const GPoint p = ge->point(s.t);
      const SPoint3 to(p.x(), p.y(), p.z());
      if(changesSides(v, found->second, v->point(), to, inputs)) continue;
      v->setXYZ(to.x(), to.y(), to.z());
      v->setParameter(0, s.t);
      counts.moved++;
      counts.curves.insert(ge);
      for(const triangleAround &t : found->second) counts.faces.insert(t.face);
    }
  }

  // The discrete curves whose nodes may slide (no cut the mesh may cross:
  // Geo/optimize/reparamOptimizeAcrossCuts.h moves those), and the triangles around
  // their nodes, none of which lies in a face that may not change
  std::vector<GEdge *>
  slidableCurves(GModel *m,
                 std::map<MVertex *, std::vector<triangleAround> > &around)
  {
    std::vector<GEdge *> curves;
    std::set<MVertex *> nodes;
    for(auto it = m->firstEdge(); it != m->lastEdge(); ++it) {
      GEdge *ge = *it;
      if(ge->geomType() != GEntity::DiscreteCurve || ge->lines.empty() ||
         reparamIsCrossableCurve(ge))
        continue;
      curves.push_back(ge);
      nodes.insert(ge->mesh_vertices.begin(), ge->mesh_vertices.end());
    }
    std::set<MVertex *> fixed;
    for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
      GFace *gf = *it;
      const bool free = reparamOptimizableFace(gf);
      for(std::size_t i = 0; i < gf->getNumMeshElements(); i++) {
        MElement *e = gf->getMeshElement(i);
        for(std::size_t j = 0; j < e->getNumVertices(); j++) {
          MVertex *v = e->getVertex(j);
          if(!nodes.count(v)) continue;
          if(!free || e->getType() != TYPE_TRI)
            fixed.insert(v);
          else
            around[v].push_back({(MTriangle *)e, gf});
        }
      }
    }
    for(MVertex *v : fixed) around.erase(v);
    return curves;
  }

  double worstAround(const std::map<MVertex *, std::vector<triangleAround> > &a)
  {
    double worst = 1.;
    for(const auto &r : a) worst = std::min(worst, worstOf(r.second));
    return worst;
  }

} // namespace

int reparamSlideCurveNodes(GModel *m)
{
  const double start = TimeOfDay();
  std::map<MVertex *, std::vector<triangleAround> > around;
  const std::vector<GEdge *> curves = slidableCurves(m, around);
  if(around.empty()) return 0;
  const double before = worstAround(around);
  faceInputs inputs;
  slideCounts counts;
  for(slideFor aim : {slideFor::fidelity, slideFor::worst, slideFor::worst,
                      slideFor::mean, slideFor::mean})
    for(GEdge *ge : curves) slideAlong(ge, around, inputs, counts, aim);
  if(!counts.moved) return 0;
  // the reports' meshes, for the distances measured after
  for(GFace *gf : counts.faces) {
    const faceReport *report = findFaceReport(gf);
    if(report) reparamReportMeshedFace(gf, report->meshTime);
  }
  Msg::Info("Reparam: %d nodes of %lu curves slid along them (%lu surfaces): "
            "worst kappa around the curves %g -> %g (%g s)",
            counts.moved, counts.curves.size(), counts.faces.size(), before,
            worstAround(around), TimeOfDay() - start);
  return counts.moved;
}
} // namespace reparam

