// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include "BackgroundMeshTools.h"
#include "GEdge.h"
#include "GFace.h"
#include "GModel.h"
#include "GmshMessage.h"
#include "MElement.h"
#include "MLine.h"
#include "MQuadrangle.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "OS.h"
#include "closestTriangle.h"
#include "meshFidelity.h"
#include "quadDiagonalCollapse.h"
#include "quadEdgeRotation.h"
#include "quadNodeSplit.h"
#include "quadNodeSmoothing.h"
#include "quadQuality.h"
#include "quadSplit.h"
#include "reparamSurfaceMesh.h"
#include "triangleMerge.h"
#include "reparamCurveMesh.h"
#include "reparamFaceEdits.h"
#include "reparamHooks.h"
#include "reparamOptimizableMesh.h"
#include "reparamOptimizeAcrossCuts.h"
#include "reparamPinchedNodes.h"
#include "reparamReport.h"
#include "reparamResplitAgainst.h"
#include "reparamSmoothQuads.h"
#include "reparamState.h"

namespace reparam {

namespace {

  // The faces with quadrangles Reparam parametrized, joined by the curves
  // between two of them (a face without such a curve alone: its inner
  // nodes move); the nodes of a feature curve slide along it, with the
  // quadrangles of both its faces around them, those of the smooth cuts
  // move across them
  std::vector<cutGroup> cutGroupsOf(GModel *m)
  {
    return facesJoinedBy(
      m,
      [](GFace *gf) {
        return !gf->quadrangles.empty() &&
               reparamRecombineWithParametrization(gf);
      },
      [](GEdge *) { return true; }, true,
      [](GEdge *ge) { return reparamIsCrossableCurve(ge); });
  }

  // The group's elements as one mesh; nodes[i]: point i's node, quads[i]:
  // quadrangle i's element and part[i] the index of its face in g
  surfaceMesh meshOfGroup(const cutGroup &g, std::vector<MVertex *> &nodes,
                          std::vector<MQuadrangle *> &quads,
                          std::vector<int> &part)
  {
    surfaceMesh m;
    std::map<MVertex *, int> index;
    auto indexOf = [&](MVertex *v) {
      auto it = index.find(v);
      if(it != index.end()) return it->second;
      index[v] = (int)nodes.size();
      nodes.push_back(v);
      m.points.push_back(v->point());
      return (int)nodes.size() - 1;
    };
    for(std::size_t f = 0; f < g.faces.size(); f++) {
      GFace *gf = g.faces[f];
      for(MTriangle *t : gf->triangles)
        m.triangles.push_back(
          {{indexOf(t->getVertex(0)), indexOf(t->getVertex(1)),
            indexOf(t->getVertex(2))}});
      for(MQuadrangle *q : gf->quadrangles) {
        m.quadrangles.push_back(
          {{indexOf(q->getVertex(0)), indexOf(q->getVertex(1)),
            indexOf(q->getVertex(2)), indexOf(q->getVertex(3))}});
        quads.push_back(q);
        part.push_back((int)f);
      }
    }
    return m;
  }

  // The segments of the 1D meshes of the group's curves (bounding or
  // embedded in its faces), as pairs of points (i < j)
  std::set<std::pair<int, int> >
  curveSegmentsOf(const cutGroup &g, const std::vector<MVertex *> &nodes)
  {
    std::map<MVertex *, int> index;
    for(std::size_t i = 0; i < nodes.size(); i++) index[nodes[i]] = (int)i;
    std::set<GEdge *> curves;
    for(GFace *gf : g.faces) {
      for(GEdge *ge : gf->edges()) curves.insert(ge);
      for(GEdge *ge : gf->embeddedEdges()) curves.insert(ge);
    }
    std::set<std::pair<int, int> > segments;
    for(GEdge *ge : curves)
      for(MLine *l : ge->lines) {
        auto a = index.find(l->getVertex(0)), b = index.find(l->getVertex(1));
        if(a == index.end() || b == index.end()) continue;
        segments.insert(std::make_pair(std::min(a->second, b->second),
                                       std::max(a->second, b->second)));
      }
    return segments;
  }

  // Rotates the edges between quadrangles of one face towards valence 4
  // (Mesh/quad/quadEdgeRotation.h), before the node moves square them up
  quadRotationResult rotateEdges(const cutGroup &g, surfaceMesh &m,
                                 const std::vector<MVertex *> &nodes,
                                 const std::vector<int> &part,
                                 const surfaceMesh &input,
                                 const closestTriangleSearch &onInput)
  {
    quadRotationOptions o;
    o.input = &input;
    o.onInput = &onInput;
    return rotateQuadEdges(m, part, curveSegmentsOf(g, nodes), o);
  }

  // Per point, the index in g of the face it is an inner node of (-1: a
  // curve's or another face's node)
  std::vector<int> ownersOf(const cutGroup &g,
                            const std::vector<MVertex *> &nodes)
  {
    std::map<GEntity *, int> face;
    for(std::size_t f = 0; f < g.faces.size(); f++) face[g.faces[f]] = (int)f;
    std::vector<int> owner;
    for(MVertex *v : nodes) {
      auto it = face.find(v->onWhat());
      owner.push_back(it == face.end() ? -1 : it->second);
    }
    return owner;
  }

  // Moves v, an inner node of the group's face `owner`, to point p
  void moveNode(const cutGroup &g, MVertex *v, int owner, const SPoint3 &p)
  {
    const SPoint2 uv = g.faces[owner]->parFromPoint(p);
    v->setXYZ(p.x(), p.y(), p.z());
    v->setParameter(0, uv.x());
    v->setParameter(1, uv.y());
  }

  // Collapses quadrangles along a diagonal where the mesh gets more
  // regular (Mesh/quad/quadDiagonalCollapse.h): the merged nodes move, the
  // other node of each pair leaves its face (into `gone`, deleted by the
  // caller) and the collapsed quadrangles are deleted, from the faces and
  // from m, quads and part
  quadCollapseResult collapseDiagonals(const cutGroup &g, surfaceMesh &m,
                                       const std::vector<MVertex *> &nodes,
                                       std::vector<MQuadrangle *> &quads,
                                       std::vector<int> &part,
                                       const closestTriangleSearch &onInput,
                                       double worst,
                                       std::vector<MVertex *> &gone)
  {
    const std::vector<int> owner = ownersOf(g, nodes);
    std::vector<int> mergedInto;
    std::vector<bool> removed;
    quadCollapseOptions o;
    o.onInput = &onInput;
    o.minEta = std::max(o.minEta, worst);
    // the size field of the group's first face (the model's, for the
    // faces of one patch)
    GFace *first = g.faces.front();
    o.size = [first](const SPoint3 &x) {
      return BGM_MeshSize(first, 0., 0., x.x(), x.y(), x.z());
    };
    const quadCollapseResult r =
      collapseQuadDiagonals(m, part, owner, mergedInto, removed, o);
    if(!r.collapses) return r;
    for(std::size_t i = 0; i < nodes.size(); i++) {
      if(mergedInto[i] >= 0) {
        std::vector<MVertex *> &own = g.faces[owner[i]]->mesh_vertices;
        own.erase(std::remove(own.begin(), own.end(), nodes[i]), own.end());
        gone.push_back(nodes[i]);
      }
    }
    for(std::size_t i = 0; i < nodes.size(); i++)
      if(std::count(mergedInto.begin(), mergedInto.end(), (int)i))
        moveNode(g, nodes[i], owner[i], m.points[i]);
    std::set<MQuadrangle *> dropped;
    std::vector<std::array<int, 4> > keptCorners;
    std::vector<MQuadrangle *> keptQuads;
    std::vector<int> keptPart;
    for(std::size_t i = 0; i < quads.size(); i++) {
      if(removed[i]) {
        dropped.insert(quads[i]);
        continue;
      }
      keptCorners.push_back(m.quadrangles[i]);
      keptQuads.push_back(quads[i]);
      keptPart.push_back(part[i]);
    }
    for(GFace *gf : g.faces) {
      std::vector<MQuadrangle *> &own = gf->quadrangles;
      own.erase(
        std::remove_if(own.begin(), own.end(),
                       [&](MQuadrangle *q) { return dropped.count(q) > 0; }),
        own.end());
    }
    for(MQuadrangle *q : dropped) delete q;
    m.quadrangles.swap(keptCorners);
    quads.swap(keptQuads);
    part.swap(keptPart);
    return r;
  }

  // Splits nodes where the mesh gets more regular (Mesh/quad/quadNodeSplit.h):
  // the first half of a node moves, the second is a new node of its face
  // and the quadrangle between them a new element of it (nodes, quads and
  // part grow)
  quadNodeSplitResult
  splitNodes(const cutGroup &g, surfaceMesh &m, std::vector<MVertex *> &nodes,
             std::vector<MQuadrangle *> &quads, std::vector<int> &part,
             const surfaceMesh &input, const closestTriangleSearch &onInput,
             double worst)
  {
    std::vector<int> owner = ownersOf(g, nodes), splitFrom;
    quadNodeSplitOptions o;
    o.input = &input;
    o.onInput = &onInput;
    o.minEta = std::max(o.minEta, worst);
    const std::size_t points = m.points.size(), elements = quads.size();
    const quadNodeSplitResult r = splitQuadNodes(m, part, owner, splitFrom, o);
    for(std::size_t i = points; i < m.points.size(); i++) {
      const int v = splitFrom[i];
      moveNode(g, nodes[v], owner[v], m.points[v]);
      GFace *gf = g.faces[owner[i]];
      MVertex *w = new MFaceVertex(m.points[i].x(), m.points[i].y(),
                                   m.points[i].z(), gf, 0., 0.);
      moveNode(g, w, owner[i], m.points[i]);
      gf->mesh_vertices.push_back(w);
      nodes.push_back(w);
    }
    for(std::size_t q = elements; q < m.quadrangles.size(); q++) {
      const std::array<int, 4> &c = m.quadrangles[q];
      MQuadrangle *e =
        new MQuadrangle(nodes[c[0]], nodes[c[1]], nodes[c[2]], nodes[c[3]]);
      g.faces[part[q]]->quadrangles.push_back(e);
      quads.push_back(e);
    }
    return r;
  }

  // Edge rotations, then rounds of diagonal collapses, node splits and
  // rotations again; writes the new corners to the quadrangles
  quadRotationResult
  makeRegular(const cutGroup &g, surfaceMesh &m, std::vector<MVertex *> &nodes,
              std::vector<MQuadrangle *> &quads, std::vector<int> &part,
              const surfaceMesh &input, const closestTriangleSearch &onInput,
              double worst, quadCollapseResult &collapsed, std::size_t &splits,
              std::vector<MVertex *> &gone)
  {
    quadRotationResult r = rotateEdges(g, m, nodes, part, input, onInput);
    // a collapse or a split can let an edge rotate, and a rotation bring
    // two nodes of valence 3 across a quadrangle: a few rounds
    for(int round = 0; round < 4; round++) {
      const quadCollapseResult c =
        collapseDiagonals(g, m, nodes, quads, part, onInput, worst, gone);
      collapsed.collapses += c.collapses;
      const quadNodeSplitResult s =
        splitNodes(g, m, nodes, quads, part, input, onInput, worst);
      splits += s.splits;
      if(!c.collapses && !s.splits) break;
      const quadRotationResult again =
        rotateEdges(g, m, nodes, part, input, onInput);
      r.rotations += again.rotations;
      r.irregularAfter = again.irregularAfter;
    }
    if(!r.rotations && !collapsed.collapses && !splits) return r;
    for(std::size_t i = 0; i < quads.size(); i++)
      for(int k = 0; k < 4; k++)
        quads[i]->setVertex(k, nodes[m.quadrangles[i][k]]);
    return r;
  }

  meshIdentity meshMark(GFace *gf)
  {
    const std::size_t n = gf->getNumMeshElements();
    return meshIdentity{n, n ? gf->getMeshElement(0) : nullptr};
  }

  // The meshes this left, per face (faceRecord::smoothedQuads): a second
  // call (another Mesh.CompoundOptimize pass over the model) leaves them as
  // they are
  void markSmoothed(GFace *gf)
  {
    std::unique_lock<std::mutex> lock = lockRecords();
    faceRecordOf(gf).smoothedQuads = meshMark(gf);
  }

  bool alreadySmoothed(const cutGroup &g)
  {
    for(GFace *gf : g.faces) {
      std::unique_lock<std::mutex> lock = lockRecords();
      const faceRecord *r = findFaceRecord(gf);
      if(!r || !r->smoothedQuads || *r->smoothedQuads != meshMark(gf))
        return false;
    }
    return true;
  }

  // gf's mesh changed: drawn and reported again, and marked as left so
  void meshChanged(GFace *gf)
  {
    gf->deleteVertexArrays();
    const faceReport *report = findFaceReport(gf);
    reparamReportMeshedFace(gf, report ? report->meshTime : 0.);
    markSmoothed(gf);
  }

  // Writes the moved points back: a face node goes to the face whose input
  // it landed on, a cut node moved off its cut is replaced by a new node of
  // that face (and the cut keeps no 1D element). Returns the cuts crossed
  std::size_t writeBack(const cutGroup &g, const surfaceMesh &m,
                        const std::vector<MVertex *> &nodes,
                        const std::vector<int> &landing,
                        const std::vector<int> &inputFace)
  {
    std::map<MVertex *, MVertex *> replaced;
    std::set<GEdge *> crossed;
    for(std::size_t i = 0; i < nodes.size(); i++) {
      if(landing[i] < 0) continue;
      MVertex *v = nodes[i];
      const SPoint3 &p = m.points[i];
      GFace *gf = g.faces[inputFace[landing[i]]];
      const SPoint2 uv = gf->parFromPoint(p);
      GEntity *old = v->onWhat();
      if(old->dim() == 2) {
        if(old != gf) {
          std::vector<MVertex *> &own = old->mesh_vertices;
          own.erase(std::remove(own.begin(), own.end(), v), own.end());
          v->setEntity(gf);
          gf->mesh_vertices.push_back(v);
        }
        v->setXYZ(p.x(), p.y(), p.z());
        v->setParameter(0, uv.x());
        v->setParameter(1, uv.y());
        continue;
      }
      MVertex *nv = new MFaceVertex(p.x(), p.y(), p.z(), gf, uv.x(), uv.y());
      gf->mesh_vertices.push_back(nv);
      replaced[v] = nv;
      crossed.insert((GEdge *)old);
      std::vector<MVertex *> &own = old->mesh_vertices;
      own.erase(std::remove(own.begin(), own.end(), v), own.end());
    }
    for(GFace *gf : g.faces)
      for(std::size_t e = 0; e < gf->getNumMeshElements(); e++) {
        MElement *el = gf->getMeshElement(e);
        for(std::size_t k = 0; k < el->getNumVertices(); k++) {
          auto it = replaced.find(el->getVertex(k));
          if(it != replaced.end()) el->setVertex(k, it->second);
        }
      }
    for(GEdge *ge : crossed) {
      for(MLine *l : ge->lines) delete l;
      ge->lines.clear();
      ge->deleteVertexArrays();
    }
    for(auto &r : replaced) delete r.first;
    return crossed.size();
  }

  // The nodes of the group's feature curves and borders (the discrete
  // curves that are no cut of it and bound only its faces) as slides along
  // their input polylines, kept in `polylines`
  std::vector<polylineSlide>
  slidesOf(const cutGroup &g, const std::vector<MVertex *> &nodes,
           std::vector<std::unique_ptr<std::vector<SPoint3> > > &polylines)
  {
    std::vector<polylineSlide> slides(nodes.size());
    std::map<MVertex *, int> index;
    for(std::size_t i = 0; i < nodes.size(); i++) index[nodes[i]] = (int)i;
    const std::set<GFace *> faces(g.faces.begin(), g.faces.end());
    const std::set<GEdge *> cuts(g.cuts.begin(), g.cuts.end());
    std::set<GEdge *> curves;
    for(GFace *gf : g.faces)
      for(GEdge *ge : gf->edges()) curves.insert(ge);
    for(GEdge *ge : curves) {
      bool inside = !cuts.count(ge);
      for(GFace *gf : ge->faces()) inside = inside && faces.count(gf);
      std::unique_ptr<std::vector<SPoint3> > polyline(
        new std::vector<SPoint3>());
      if(!inside || !reparamInputPolyline(ge, *polyline)) continue;
      std::vector<std::pair<double, int> > along;
      for(MVertex *v : ge->mesh_vertices) {
        double t;
        auto it = index.find(v);
        if(it != index.end() && v->getParameter(0, t))
          along.push_back(std::make_pair(t, it->second));
      }
      std::sort(along.begin(), along.end());
      const Range<double> ends = ge->parBounds(0);
      for(std::size_t k = 0; k < along.size(); k++) {
        polylineSlide &s = slides[along[k].second];
        s.polyline = polyline.get();
        s.t = along[k].first;
        s.before = k ? along[k - 1].first : ends.low();
        s.after = k + 1 < along.size() ? along[k + 1].first : ends.high();
        s.previous = k ? along[k - 1].second : -1;
        s.next = k + 1 < along.size() ? along[k + 1].second : -1;
      }
      polylines.push_back(std::move(polyline));
    }
    return slides;
  }

  // The curve nodes slid: their new parameter and place
  void writeSlides(const surfaceMesh &m, const std::vector<MVertex *> &nodes,
                   const std::vector<polylineSlide> &slides,
                   const std::vector<double> &before)
  {
    for(std::size_t i = 0; i < nodes.size(); i++) {
      if(!slides[i].polyline || slides[i].t == before[i]) continue;
      nodes[i]->setParameter(0, slides[i].t);
      nodes[i]->setXYZ(m.points[i].x(), m.points[i].y(), m.points[i].z());
    }
  }

  bool smoothGroup(const cutGroup &g)
  {
    const double t0 = TimeOfDay();
    std::vector<surfaceMesh> inputs;
    for(GFace *gf : g.faces) inputs.push_back(inputTriangulationOf(gf));
    std::vector<int> inputFace;
    const surfaceMesh input = unionAsTriangles(inputs, nullptr, &inputFace);
    const closestTriangleSearch onInput(input.points, input.triangles);
    std::vector<MVertex *> nodes;
    std::vector<MQuadrangle *> quads;
    std::vector<int> part;
    surfaceMesh m = meshOfGroup(g, nodes, quads, part);
    double etaMinBefore, etaMeanBefore;
    etaOfQuadrangles(m, etaMinBefore, etaMeanBefore);
    quadCollapseResult collapsed;
    std::size_t splits = 0;
    std::vector<MVertex *> gone;
    const quadRotationResult rotated =
      makeRegular(g, m, nodes, quads, part, input, onInput, etaMinBefore,
                  collapsed, splits, gone);
    const std::set<GFace *> faces(g.faces.begin(), g.faces.end());
    const std::set<GEdge *> cuts(g.cuts.begin(), g.cuts.end());
    const std::set<MVertex *> goneSet(gone.begin(), gone.end());
    std::vector<bool> movable(nodes.size());
    for(std::size_t i = 0; i < nodes.size(); i++) {
      GEntity *e = nodes[i]->onWhat();
      movable[i] = !goneSet.count(nodes[i]) &&
                   ((e->dim() == 2 && faces.count((GFace *)e)) ||
                    (e->dim() == 1 && cuts.count((GEdge *)e)));
    }
    std::vector<std::unique_ptr<std::vector<SPoint3> > > polylines;
    std::vector<polylineSlide> slides = slidesOf(g, nodes, polylines);
    std::vector<double> slideFrom;
    for(const polylineSlide &s : slides) slideFrom.push_back(s.t);
    std::vector<int> landing;
    quadSmoothingOptions o;
    // the edges kept near their mean at each node (the size asked, from
    // BGM_MeshSize, pulled the small quadrangles of the CAD parts' graded
    // sizes: bench/README.md, "Smoothing in the parametric plane")
    o.size = meanQuadEdgeAtPoints(m);
    const quadSmoothingResult r =
      smoothQuadsOnInput(m, movable, onInput, landing, o, &slides);
    for(GFace *gf : g.faces) markSmoothed(gf);
    if(!r.moves && !rotated.rotations && !collapsed.collapses && !splits)
      return false;
    writeSlides(m, nodes, slides, slideFrom);
    const std::size_t crossed = writeBack(g, m, nodes, landing, inputFace);
    for(MVertex *v : gone) delete v;
    for(GFace *gf : g.faces) meshChanged(gf);
    Msg::Info("Reparam: surface%s %s: quadrangles squared up on the input "
              "(%lu edge rotations, %lu diagonal collapses and %lu node "
              "splits, inner nodes not of valence 4 %lu -> %lu; "
              "%lu node moves in %d sweeps, %lu of them along curves, %lu "
              "of %lu cut curves crossed): eta min %.3g -> %.3g, mean %.3g "
              "-> %.3g (%g s)",
              g.faces.size() > 1 ? "s" : "", reparamTagList(g.faces).c_str(),
              rotated.rotations, collapsed.collapses, splits,
              rotated.irregularBefore, rotated.irregularAfter, r.moves,
              r.sweeps, r.slides, crossed, g.cuts.size(), etaMinBefore,
              r.etaMinAfter, etaMeanBefore, r.etaMeanAfter, TimeOfDay() - t0);
    return true;
  }

  // the quadrangle of a pair needs this eta, as the edge rotations' do
  const double mergeEta = 0.3;

  // The quadrangles of gf below mergeEta split into two triangles
  // (Mesh/quad/quadSplit.h) better than them, where both point the way most of
  // the face does; returns how many, their worst eta in `worst` and the
  // worst of their triangles' kappa in `worstKappa`. Better is all it takes
  // (a floor of kappa left the worst quadrangles at sharp corners where two
  // curves meet: bench/README.md, "Quadrangles with a flat corner split")
  std::size_t splitQuadrangles(GFace *gf, double &worst, double &worstKappa)
  {
    if(gf->quadrangles.empty()) return 0;
    std::vector<MVertex *> nodes;
    const surfaceMesh m = reparamMeshOfFaces({gf}, nodes);
    const std::vector<quadSplit> splits = quadSplits(m, mergeEta, 0.);
    if(splits.empty()) return 0;
    const surfaceMesh input = inputTriangulationOf(gf);
    if(input.triangles.empty()) return 0;
    const closestTriangleSearch onInput(input.points, input.triangles);
    // Gmsh orients the face's elements once all are meshed, after this:
    // the way most of them point is the right one
    const bool side = meshReversedOnInput(gf, input, onInput);
    std::vector<bool> gone(gf->quadrangles.size(), false);
    std::size_t split = 0;
    for(const quadSplit &s : splits) {
      bool aside = false;
      for(const std::array<int, 3> &t : s.triangles)
        aside =
          aside || triangleAgainstInput(m.points[t[0]], m.points[t[1]],
                                        m.points[t[2]], input, onInput) != side;
      if(aside) continue;
      for(const std::array<int, 3> &t : s.triangles)
        gf->triangles.push_back(
          new MTriangle(nodes[t[0]], nodes[t[1]], nodes[t[2]]));
      gone[s.quadrangle] = true;
      worst = std::min(worst, s.eta);
      worstKappa = std::min(worstKappa, s.kappa);
      split++;
    }
    reparamDropMarked(gf->quadrangles, gone);
    return split;
  }

  // splitQuadrangles over the group's faces; logs and reports what changed
  bool splitGroupQuadrangles(const cutGroup &g)
  {
    std::size_t split = 0;
    double worst = 1., worstKappa = 1.;
    for(GFace *gf : g.faces) {
      const std::size_t n = splitQuadrangles(gf, worst, worstKappa);
      if(!n) continue;
      split += n;
      meshChanged(gf);
    }
    if(split)
      Msg::Info("Reparam: surface%s %s: %lu quadrangle%s of eta %.3g to %g "
                "(a flat or sharp corner, most often on a curve) split into "
                "triangles better than them, of kappa %.3g or more",
                g.faces.size() > 1 ? "s" : "", reparamTagList(g.faces).c_str(),
                split, split > 1 ? "s" : "", worst, mergeEta, worstKappa);
    return split > 0;
  }

  // The triangles Blossom left in gf merged in pairs into quadrangles
  // (Mesh/quad/triangleMerge.h) where the quadrangle's triangles along either
  // diagonal lie on the side of the input the pair was on; returns how
  // many pairs
  std::size_t mergeTriangles(GFace *gf, double minEta)
  {
    if(gf->triangles.size() < 2) return 0;
    std::vector<MVertex *> nodes;
    const surfaceMesh m = reparamMeshOfFaces({gf}, nodes);
    cutGroup one;
    one.faces.push_back(gf);
    const std::vector<triangleMerge> merges =
      triangleMerges(m, curveSegmentsOf(one, nodes), minEta);
    if(merges.empty()) return 0;
    const surfaceMesh input = inputTriangulationOf(gf);
    if(input.triangles.empty()) return 0;
    const closestTriangleSearch onInput(input.points, input.triangles);
    const std::vector<SPoint3> &p = m.points;
    auto against = [&](int a, int b, int c) {
      return triangleAgainstInput(p[a], p[b], p[c], input, onInput);
    };
    std::vector<bool> gone(gf->triangles.size(), false);
    std::size_t merged = 0;
    for(const triangleMerge &t : merges) {
      const std::array<int, 4> &q = t.quadrangle; // (a, d, b, c)
      const bool side = against(q[0], q[2], q[3]);
      if(against(q[2], q[0], q[1]) != side ||
         against(q[0], q[1], q[3]) != side || against(q[1], q[2], q[3]) != side)
        continue;
      gf->quadrangles.push_back(
        new MQuadrangle(nodes[q[0]], nodes[q[1]], nodes[q[2]], nodes[q[3]]));
      gone[t.first] = gone[t.second] = true;
      merged++;
    }
    reparamDropMarked(gf->triangles, gone);
    return merged;
  }

  // mergeTriangles over the group's faces, into quadrangles no worse than
  // mergeEta nor than the group's worst (the first alone lowered the worst:
  // bench/README.md, "Triangles left merged"); logs and reports what changed
  bool mergeGroupTriangles(const cutGroup &g)
  {
    double worst = 1.;
    for(GFace *gf : g.faces)
      for(MQuadrangle *q : gf->quadrangles)
        worst = std::min(
          worst, quadEta(q->getVertex(0)->point(), q->getVertex(1)->point(),
                         q->getVertex(2)->point(), q->getVertex(3)->point()));
    const double minEta = std::max(mergeEta, worst);
    std::size_t pairs = 0, left = 0;
    for(GFace *gf : g.faces) {
      const std::size_t merged = mergeTriangles(gf, minEta);
      left += gf->triangles.size();
      pairs += merged;
      if(!merged) continue;
      meshChanged(gf);
    }
    if(pairs)
      Msg::Info("Reparam: surface%s %s: %lu pairs of the triangles Blossom "
                "left merged into quadrangles of eta %.3g or more (%lu "
                "triangles left)",
                g.faces.size() > 1 ? "s" : "", reparamTagList(g.faces).c_str(),
                pairs, minEta, left);
    return pairs > 0;
  }

  // The pinched nodes Gmsh's recombination left, removed first
  // (Geo/quad/reparamPinchedNodes.h): the group's moves take an element folded
  // onto its neighbour as one to square up
  bool removePinchedNodes(const cutGroup &g)
  {
    std::set<GFace *> changed;
    if(!reparamRemovePinchedNodes(
         g.faces, std::set<GEdge *>(g.cuts.begin(), g.cuts.end()), changed))
      return false;
    for(GFace *gf : changed) meshChanged(gf);
    return true;
  }

  // Last, the elements left against the input split again with a
  // neighbour (Geo/quad/reparamResplitAgainst.h)
  bool resplitGroupAgainst(const cutGroup &g)
  {
    bool changed = false;
    for(GFace *gf : g.faces)
      if(reparamResplitElementsAgainstInput(gf)) {
        meshChanged(gf);
        changed = true;
      }
    return changed;
  }

} // namespace

int reparamSmoothQuadMeshes(GModel *m)
{
  int changed = 0;
  for(const cutGroup &g : cutGroupsOf(m))
    if(!alreadySmoothed(g)) {
      changed += removePinchedNodes(g);
      changed += smoothGroup(g);
      changed += splitGroupQuadrangles(g);
      changed += mergeGroupTriangles(g);
      changed += resplitGroupAgainst(g);
    }
  if(changed) m->destroyMeshCaches();
  return changed;
}
} // namespace reparam

