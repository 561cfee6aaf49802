// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <map>
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
#include "meshFidelity.h"
#include "optimizeOnInput.h"
#include "reparamCurveMesh.h"
#include "reparamFaceEdits.h"
#include "reparamHooks.h"
#include "reparamInputMesh.h"
#include "reparamNoiseFaces.h"
#include "reparamOptimizableMesh.h"
#include "reparamOptimizeAcrossCuts.h"
#include "reparamOptions.h"
#include "reparamOverlappingFaces.h"
#include "reparamReport.h"
#include "reparamSizeGrading.h"
#include "reparamSlideCurveNodes.h"
#include "reparamSmoothQuads.h"
#include "reparamSurfaceMesh.h"
#include "unionFind.h"

namespace reparam {

namespace {

  // The triangles whose face's own optimization left none against the
  // input, farther than two rings from a cut: they are not tested again (a
  // quarter of the time here went to that). Near a cut, the points of a
  // triangle may be closest to the next face's input, whose triangles can
  // turn the other way: those are tested
  std::vector<bool> alongByFace(const cutGroup &g,
                                const std::vector<optimizationRecord> &before,
                                const std::vector<bool> &reverse,
                                const optimizableMesh &m,
                                const std::vector<MVertex *> &nodes,
                                const std::vector<int> &triangleFace)
  {
    std::vector<bool> trusted(g.faces.size());
    for(std::size_t f = 0; f < g.faces.size(); f++)
      trusted[f] = before[f].done && !before[f].againstAfter &&
                   before[f].reversed == reverse[f];
    // points within two rings of a cut node
    std::vector<bool> near(m.points.size(), false);
    for(std::size_t i = 0; i < nodes.size() && i < near.size(); i++)
      near[i] = nodes[i]->onWhat()->dim() == 1;
    for(int ring = 0; ring < 2; ring++) {
      std::vector<bool> next = near;
      for(const std::array<int, 3> &t : m.triangles)
        if(near[t[0]] || near[t[1]] || near[t[2]])
          for(int v : t) next[v] = true;
      near.swap(next);
    }
    std::vector<bool> along(m.triangles.size());
    for(std::size_t t = 0; t < m.triangles.size(); t++) {
      const std::array<int, 3> &c = m.triangles[t];
      along[t] =
        trusted[triangleFace[t]] && !near[c[0]] && !near[c[1]] && !near[c[2]];
    }
    return along;
  }

  // The inputs of the faces as one triangulation; inputFace[t]: the index in
  // `faces` of input triangle t's face
  surfaceMesh inputOfFaces(const std::vector<GFace *> &faces,
                           std::vector<int> &inputFace)
  {
    std::vector<surfaceMesh> inputs;
    for(GFace *gf : faces) inputs.push_back(inputTriangulationOf(gf));
    inputFace.clear();
    return unionAsTriangles(inputs, nullptr, &inputFace);
  }

  // Writes the optimized mesh of a group back into its faces and curves
  class groupWriter {
  public:
    groupWriter(const cutGroup &g, const optimizableMesh &m,
                const std::vector<MVertex *> &nodes, const surfaceMesh &input,
                const std::vector<int> &inputFace,
                const closestTriangleSearch &onInput)
      : _g(g), _m(m), _nodes(nodes), _input(input), _inputFace(inputFace),
        _onInput(onInput)
    {
    }

    // the face of each triangle of m, as written
    std::vector<int> write()
    {
      const std::vector<MVertex *> out = writeNodes();
      std::vector<int> triangleFace = writeTriangles(out);
      dropCrossedCurves();
      for(auto &e : _leaving) {
        std::vector<MVertex *> &own = e.first->mesh_vertices;
        own.erase(
          std::remove_if(own.begin(), own.end(),
                         [&](MVertex *v) { return e.second.count(v) > 0; }),
          own.end());
      }
      for(MVertex *v : _gone) delete v;
      return triangleFace;
    }

    std::size_t crossedCurves() const { return _crossed; }

  private:
    // the index in the group of the face whose input is under p (landing:
    // the input triangle p was put on, -1 if unknown)
    int faceAt(const SPoint3 &p, int landing) const
    {
      if(landing < 0) landing = _onInput.closest(p).triangle;
      return landing < 0 ? 0 : _inputFace[landing];
    }

    MVertex *newFaceNode(const SPoint3 &p, GFace *gf)
    {
      const SPoint2 uv = gf->parFromPoint(p);
      MVertex *v = new MFaceVertex(p.x(), p.y(), p.z(), gf, uv.x(), uv.y());
      gf->mesh_vertices.push_back(v);
      return v;
    }

    void leave(MVertex *v, bool destroy)
    {
      _leaving[v->onWhat()].insert(v);
      if(destroy) _gone.insert(v);
    }

    std::vector<MVertex *> writeNodes()
    {
      std::vector<MVertex *> out(_m.points.size(), nullptr);
      std::vector<bool> kept(_nodes.size(), false);
      for(std::size_t i = 0; i < _m.points.size(); i++) {
        const SPoint3 &p = _m.points[i];
        const int origin = _m.origin[i];
        if(origin >= 0) kept[origin] = true;
        if(origin >= 0 && _m.landing[i] < 0) {
          out[i] = _nodes[origin]; // not moved
          continue;
        }
        GFace *gf = _g.faces[faceAt(p, _m.landing[i])];
        if(origin < 0) {
          out[i] = newFaceNode(p, gf);
          continue;
        }
        MVertex *v = _nodes[origin];
        if(v->onWhat()->dim() != 2) {
          // a cut's node moved off it; a model point keeps its own node,
          // which no triangle uses any more: its place (Gmsh reads a
          // discrete point's from it) and its point element stay
          out[i] = newFaceNode(p, gf);
          if(v->onWhat()->dim() == 1) leave(v, true);
          continue;
        }
        if(v->onWhat() != gf) {
          leave(v, false);
          v->setEntity(gf);
          gf->mesh_vertices.push_back(v);
        }
        const SPoint2 uv = gf->parFromPoint(p);
        v->setXYZ(p.x(), p.y(), p.z());
        v->setParameter(0, uv.x());
        v->setParameter(1, uv.y());
        out[i] = v;
      }
      // nodes collapsed away (only movable ones: of the faces, the cuts or
      // the points only cuts meet, which keep theirs as above)
      for(std::size_t i = 0; i < _nodes.size(); i++)
        if(!kept[i] && _nodes[i]->onWhat()->dim() != 0) leave(_nodes[i], true);
      return out;
    }

    std::vector<int> writeTriangles(const std::vector<MVertex *> &out)
    {
      std::vector<MTriangle *> old;
      std::vector<int> oldFace;
      for(std::size_t f = 0; f < _g.faces.size(); f++) {
        const std::vector<MTriangle *> &own = _g.faces[f]->triangles;
        old.insert(old.end(), own.begin(), own.end());
        oldFace.insert(oldFace.end(), own.size(), (int)f);
      }
      std::vector<bool> kept(old.size(), false);
      std::vector<MTriangle *> triangles(_m.triangles.size(), nullptr);
      std::vector<int> triangleFace(_m.triangles.size(), 0);
      for(std::size_t t = 0; t < _m.triangles.size(); t++) {
        MVertex *c[3];
        SPoint3 centroid(0., 0., 0.);
        for(int k = 0; k < 3; k++) {
          c[k] = out[_m.triangles[t][k]];
          centroid += _m.points[_m.triangles[t][k]];
        }
        centroid *= 1. / 3.;
        const int origin = _m.triangleOrigin[t];
        // a triangle as it was stays on its face; a changed one goes to the
        // face whose input is under its centroid
        bool same = origin >= 0;
        for(int k = 0; k < 3 && same; k++)
          same = old[origin]->getVertex(k) == c[k] &&
                 _m.landing[_m.triangles[t][k]] < 0;
        if(origin < 0)
          triangles[t] = new MTriangle(c[0], c[1], c[2]);
        else {
          triangles[t] = old[origin];
          kept[origin] = true;
          for(int k = 0; k < 3; k++) triangles[t]->setVertex(k, c[k]);
        }
        triangleFace[t] = same ? oldFace[origin] : faceAt(centroid, -1);
        for(int k = 0; k < 3; k++) {
          MVertex *a = c[k], *b = c[(k + 1) % 3];
          _edges.insert(std::make_pair(std::min(a, b), std::max(a, b)));
        }
      }
      // a face left without a triangle (a small part whose triangles all
      // lie over its neighbours' input) takes back those it had, and so on
      // if that empties another (a triangle back on its own face stays):
      // no face of the model goes unmeshed
      for(bool changed = true; changed;) {
        changed = false;
        std::vector<std::size_t> count(_g.faces.size(), 0);
        for(int f : triangleFace) count[f]++;
        for(std::size_t t = 0; t < triangleFace.size(); t++) {
          const int origin = _m.triangleOrigin[t];
          if(origin < 0 || count[oldFace[origin]] ||
             triangleFace[t] == oldFace[origin])
            continue;
          triangleFace[t] = oldFace[origin];
          changed = true;
        }
      }
      giveEmptyFacesATriangle(triangleFace);
      std::vector<std::vector<MTriangle *> > byFace(_g.faces.size());
      for(std::size_t t = 0; t < _m.triangles.size(); t++)
        byFace[triangleFace[t]].push_back(triangles[t]);
      for(std::size_t t = 0; t < old.size(); t++)
        if(!kept[t]) delete old[t];
      for(std::size_t f = 0; f < _g.faces.size(); f++)
        _g.faces[f]->triangles = byFace[f];
      return triangleFace;
    }

    // A face none of whose triangles is left, even as changed (a face
    // narrower than the mesh size, Geo/layout/reparamNoiseFaces.h, whose slivers
    // were collapsed away), takes the triangle nearest to the centre of its
    // input from a face that has others: no face of the model goes unmeshed
    void giveEmptyFacesATriangle(std::vector<int> &triangleFace) const
    {
      std::vector<std::size_t> count(_g.faces.size(), 0);
      for(int f : triangleFace) count[f]++;
      for(std::size_t f = 0; f < _g.faces.size(); f++) {
        if(count[f]) continue;
        SPoint3 centre(0., 0., 0.);
        std::size_t n = 0;
        for(std::size_t t = 0; t < _input.triangles.size(); t++)
          if(_inputFace[t] == (int)f)
            for(int k : _input.triangles[t]) {
              centre += _input.points[k];
              n++;
            }
        if(!n) continue;
        centre *= 1. / n;
        int nearest = -1;
        double best = 1e300;
        for(std::size_t t = 0; t < _m.triangles.size(); t++) {
          if(count[triangleFace[t]] < 2) continue;
          SPoint3 c(0., 0., 0.);
          for(int k : _m.triangles[t]) c += _m.points[k];
          const double d = centre.distance(c * (1. / 3.));
          if(d < best) {
            best = d;
            nearest = (int)t;
          }
        }
        if(nearest < 0) continue;
        count[triangleFace[nearest]]--;
        triangleFace[nearest] = (int)f;
        count[f]++;
      }
    }

    // A cut whose segments are not all edges of the new mesh any more keeps
    // no 1D element (its nodes the mesh still uses stay on it)
    void dropCrossedCurves()
    {
      for(GEdge *ge : _g.cuts) {
        bool followed = true;
        for(MLine *l : ge->lines) {
          MVertex *a = l->getVertex(0), *b = l->getVertex(1);
          followed =
            followed && !_gone.count(a) && !_gone.count(b) &&
            _edges.count(std::make_pair(std::min(a, b), std::max(a, b)));
        }
        if(followed) continue;
        for(MLine *l : ge->lines) delete l;
        ge->lines.clear();
        ge->deleteVertexArrays();
        _crossed++;
      }
    }

    const cutGroup &_g;
    const optimizableMesh &_m;
    const std::vector<MVertex *> &_nodes;
    const surfaceMesh &_input;
    const std::vector<int> &_inputFace;
    const closestTriangleSearch &_onInput;
    std::map<GEntity *, std::set<MVertex *> > _leaving;
    std::set<MVertex *> _gone;
    std::set<std::pair<MVertex *, MVertex *> > _edges;
    std::size_t _crossed = 0;
  };

  // The faces' optimization records and reports, for their new meshes: the
  // group's counts go to its largest face, each face gets its own count of
  // triangles against the input
  void recordGroup(const cutGroup &g,
                   const std::vector<optimizationRecord> &before,
                   const meshOptimizationResult &r, const optimizableMesh &m,
                   const std::vector<int> &triangleFace, double seconds)
  {
    std::vector<std::size_t> against(g.faces.size(), 0);
    for(std::size_t t = 0; t < m.triangles.size(); t++)
      against[triangleFace[t]] += m.against[t];
    std::size_t largest = 0;
    for(std::size_t f = 0; f < g.faces.size(); f++)
      if(g.faces[f]->triangles.size() > g.faces[largest]->triangles.size())
        largest = f;
    for(std::size_t f = 0; f < g.faces.size(); f++) {
      GFace *gf = g.faces[f];
      optimizationRecord o = before[f];
      if(!o.done) {
        o.done = true;
        o.kappaMinBefore = r.minBefore;
      }
      if(f == largest) {
        o.seconds += seconds;
        o.inserted += r.inserted;
        o.splits += r.splits;
        o.collapses += r.collapses;
        o.flips += r.flips;
        o.moves += r.moves;
      }
      o.againstAfter = against[f];
      o.reversed = false;
      o.acrossCuts = true;
      o.group = g.faces[0]->tag();
      o.countTaken = false;
      o.elements = gf->getNumMeshElements();
      o.firstElement = o.elements ? gf->getMeshElement(0) : nullptr;
      recordOptimization(gf, o);
      const faceReport *report = findFaceReport(gf);
      const double meshTime = report ? report->meshTime : 0.;
      reparamReportMeshedFace(gf, meshTime + (f == largest ? seconds : 0.));
    }
  }

  // The triangles against the input the faces' own records count (each
  // against its own input: a face narrower than the size judged against
  // its neighbours' input too may find its triangles over a fold or spike
  // of theirs pointing against it: bench/README.md, "Across the cuts"), or
  // `fallback` when a face has none
  std::size_t againstRecorded(const std::vector<optimizationRecord> &records,
                              std::size_t fallback)
  {
    std::size_t against = 0;
    for(const optimizationRecord &o : records) {
      if(!o.done) return fallback;
      // (relative to the face's own orientation, which Gmsh turns along
      // the input's after: a reversed mesh is no count of its own)
      against += o.againstAfter;
    }
    return against;
  }

  // Whether every curve at gv is one the group may cross: a point only the
  // layout's cuts (or the curves of faces that are noise at the mesh scale)
  // meet, where the input has no feature (a closed cut's point, the ends of a
  // cut between two others), whose node may move like theirs; a point
  // embedded in a face (no curve) or on a feature curve, a border or another
  // group's curve stays
  bool onlyCrossableCurvesMeet(GVertex *gv, const std::set<GEdge *> &cuts)
  {
    const std::vector<GEdge *> around = gv->edges();
    if(around.empty()) return false;
    for(GEdge *ge : around)
      if(!cuts.count(ge)) return false;
    return true;
  }

  // Whether this group's meshes are those the optimization left
  bool alreadyOptimized(const cutGroup &g)
  {
    for(GFace *gf : g.faces) {
      const optimizationRecord *o = findOptimization(gf);
      if(!o || !o->acrossCuts) return false;
    }
    return true;
  }

  // What optimizeGroup did: nothing to change, changed, or refused (the
  // group's worst triangle would be worse, or more of its triangles against
  // the input)
  enum class groupResult { unchanged, changed, refused };

  // refuseWorse: leave the meshes as they are if the worst triangle gets
  // worse or more triangles point against the input than the faces' own
  // records count
  groupResult optimizeGroup(const cutGroup &g, bool refuseWorse)
  {
    const double t0 = TimeOfDay();
    std::vector<int> inputFace;
    const surfaceMesh input = inputOfFaces(g.faces, inputFace);
    const closestTriangleSearch onInput(input.points, input.triangles);
    // each face turned along the input (Gmsh orients them after this)
    std::vector<bool> reverse;
    std::vector<optimizationRecord> before;
    for(GFace *gf : g.faces) {
      reverse.push_back(meshReversedOnInput(gf, input, onInput));
      const optimizationRecord *o = findOptimization(gf);
      before.push_back(o ? *o : optimizationRecord());
    }
    std::set<GEdge *> cuts(g.cuts.begin(), g.cuts.end());
    std::set<GEdge *> locked;
    for(GFace *gf : g.faces)
      for(GEdge *ge : gf->edges())
        if(!cuts.count(ge)) locked.insert(ge);
    std::set<GFace *> faces(g.faces.begin(), g.faces.end());
    auto movable = [&](const MVertex *v) {
      GEntity *e = v->onWhat();
      if(e->dim() == 0) return onlyCrossableCurvesMeet((GVertex *)e, cuts);
      return (e->dim() == 2 && faces.count((GFace *)e)) ||
             (e->dim() == 1 && cuts.count((GEdge *)e));
    };
    std::vector<MVertex *> nodes;
    std::vector<int> triangleFace;
    optimizableMesh m = optimizableMeshOf(
      g.faces, reverse, movable,
      std::vector<GEdge *>(locked.begin(), locked.end()), nodes, triangleFace);
    meshOptimizationOptions o;
    o.collapseBelow = getReparamOptions().optimize >= 2 ? 0.6 : 0.;
    // the faces' own optimization inserted the input nodes their meshes cut
    // off; here an input node by a cut would come in at the cost of the
    // worst triangle (bench/README.md, "Across the cuts")
    o.insertAbove = 0.;
    o.knownAlong = alongByFace(g, before, reverse, m, nodes, triangleFace);
    const meshOptimizationResult r = optimizeOnInput(m, input, onInput, o);
    if(!r.flips && !r.moves && !r.inserted && !r.splits && !r.collapses &&
       !r.cavities) {
      Msg::Debug("Reparam: surfaces %s: nothing to change across their cuts",
                 reparamTagList(g.faces).c_str());
      return groupResult::unchanged;
    }
    const std::size_t against = againstRecorded(before, r.againstBefore);
    if(refuseWorse && (r.minAfter < r.minBefore || r.againstAfter > against)) {
      Msg::Info("Reparam: surfaces %s: optimization across their curves "
                "refused (kappa min %.3g -> %.3g, %lu -> %lu triangles "
                "against the input)",
                reparamTagList(g.faces).c_str(), r.minBefore, r.minAfter,
                against, r.againstAfter);
      return groupResult::refused;
    }
    groupWriter writer(g, m, nodes, input, inputFace, onInput);
    triangleFace = writer.write();
    const double seconds = TimeOfDay() - t0;
    recordGroup(g, before, r, m, triangleFace, seconds);
    Msg::Info("Reparam: surfaces %s optimized across their %lu cut curves "
              "(%lu crossed): kappa min %.3g -> %.3g, %lu -> %lu triangles "
              "below %g, %lu -> %lu against the input; %lu input nodes the "
              "mesh cut off inserted, %lu long edges split, %lu short ones "
              "collapsed, %lu tangles re-meshed, %lu flips and %lu node moves "
              "(%g s)",
              reparamTagList(g.faces).c_str(), g.cuts.size(),
              writer.crossedCurves(), r.minBefore, r.minAfter, r.belowBefore,
              r.belowAfter, o.target, r.againstBefore, r.againstAfter,
              r.inserted, r.splits, r.collapses, r.cavities, r.flips, r.moves,
              seconds);
    return groupResult::changed;
  }

} // namespace

std::vector<cutGroup>
facesJoinedBy(GModel *m, const std::function<bool(GFace *)> &member,
              const std::function<bool(GEdge *)> &joins, bool alone,
              const std::function<bool(GEdge *)> &crossable)
{
  std::vector<GFace *> faces;
  std::map<GFace *, int> index;
  for(auto it = m->firstFace(); it != m->lastFace(); ++it)
    if(member(*it)) {
      index[*it] = (int)faces.size();
      faces.push_back(*it);
    }
  unionFind sets(faces.size());
  std::vector<bool> joined(faces.size(), false);
  std::vector<GEdge *> cuts;
  for(auto it = m->firstEdge(); it != m->lastEdge(); ++it) {
    GEdge *ge = *it;
    const std::vector<GFace *> sides = ge->faces();
    // two faces: a border has one, a slit inside a face too
    if(sides.size() != 2 || !index.count(sides[0]) || !index.count(sides[1]) ||
       !joins(ge))
      continue;
    const int a = index[sides[0]], b = index[sides[1]];
    sets.join(a, b);
    joined[a] = joined[b] = true;
    if(crossable(ge)) cuts.push_back(ge);
  }
  std::map<int, cutGroup> groups;
  for(std::size_t f = 0; f < faces.size(); f++)
    if(joined[f] || alone) groups[sets.find((int)f)].faces.push_back(faces[f]);
  for(GEdge *ge : cuts)
    groups[sets.find(index[ge->faces()[0]])].cuts.push_back(ge);
  std::vector<cutGroup> list;
  for(auto &g : groups) list.push_back(g.second);
  return list;
}

std::vector<cutGroup> facesJoinedByCuts(GModel *m,
                                        const std::set<GEdge *> &noiseCurves)
{
  auto crossable = [&noiseCurves](GEdge *ge) {
    return noiseCurves.count(ge) || reparamIsCrossableCurve(ge);
  };
  return facesJoinedBy(
    m, [](GFace *gf) { return reparamOptimizableFace(gf); }, crossable, false,
    crossable);
}

namespace {

  // The optimizations once every face is meshed (Mesh.CompoundOptimize)
  int optimizeMeshedModel(GModel *m)
  {
    int changed = 0;
    const std::set<GEdge *> noise = reparamNoiseFaceCurves(m);
    // the groups by the layout's cuts alone, for the refused ones (the faces
    // and curves are the same before and after any group is optimized)
    std::vector<cutGroup> byCuts;
    bool grouped = false;
    for(const cutGroup &g : facesJoinedByCuts(m, noise)) {
      if(alreadyOptimized(g)) continue;
      bool crossesNoise = false;
      for(GEdge *ge : g.cuts) crossesNoise = crossesNoise || noise.count(ge);
      if(!crossesNoise) {
        changed += optimizeGroup(g, false) == groupResult::changed;
        continue;
      }
      // across the curves of a noise face, only on top of the groups by the
      // cuts alone, and only if the worst triangle gains and no more
      // triangles point against the input (gmsh2x_pelvis_tlem2: a noise
      // face's curves joined to a group of cut parts took its kappa min
      // 0.028 -> 0.004, or to 0.042 with other flips before, 0.48 without
      // them)
      if(!grouped) {
        byCuts = facesJoinedByCuts(m, {});
        grouped = true;
      }
      std::set<GFace *> members(g.faces.begin(), g.faces.end());
      for(const cutGroup &part : byCuts)
        if(members.count(part.faces[0]) && !alreadyOptimized(part) &&
           optimizeGroup(part, false) == groupResult::changed)
          changed++;
      changed += optimizeGroup(g, true) == groupResult::changed;
    }
    // then the nodes of the curves no optimizer moved
    if(reparamSlideCurveNodes(m)) changed++;
    // and the faces recombined into quadrangles
    changed += reparamSmoothQuadMeshes(m);
    return changed;
  }

} // namespace

} // namespace reparam

using namespace reparam;

int reparamOptimizeMeshedModel(GModel *m)
{
  reparamRestoreRefusedSurfaces(m);
  if(getReparamOptions().parametrization == (int)compoundParametrization::gmsh)
    return 0;
  int changed = getReparamOptions().optimize ? optimizeMeshedModel(m) : 0;
  // last, on the mesh as it stays (an optimization across the cuts may part
  // two faces meshed onto each other, or meet them)
  changed += (int)reparamSeparateOverlappingFaces(m);
  return changed;
}

