// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include "BackgroundMeshTools.h"
#include "GEdge.h"
#include "Context.h"
#include "GFace.h"
#include "GModel.h"
#include "GVertex.h"
#include "GmshDefines.h"
#include "GmshMessage.h"
#include "MLine.h"
#include "MVertex.h"
#include "closestTriangle.h"
#include "creaseChains.h"
#include "edgeByCoordinates.h"
#include "gradedBoundarySize.h"
#include "narrowStrips.h"
#include "reparamCreaseCurves.h"
#include "reparamCurveMesh.h"
#include "reparamHooks.h"
#include "reparamOptions.h"
#include "reparamReport.h"
#include "reparamSizeGrading.h"
#include "reparamState.h"
#include "reparamSurfaceMesh.h"
#include "surfaceMesh.h"

namespace reparam {

namespace {

  // Boundary nodes whose segments are this close to the size asked are
  // left out: they would barely change it, and every query goes through
  // the nodes smaller than the size it finds
  const double nearlyTheSize = 0.9;

  // The points embedded in gf (the tips Reparam keeps as nodes) closer
  // than the size asked to another one, with that distance: the triangles
  // between two such tips are that small, or thin (bench/README.md, "Sizes
  // from the curves"). Not below a twentieth of the size, like the tips
  // near curves
  void closeTips(GFace *gf, std::vector<SPoint3> &sources,
                 std::vector<double> &sizes)
  {
    std::vector<SPoint3> tips;
    for(GVertex *gv : gf->embeddedVertices())
      tips.push_back(SPoint3(gv->x(), gv->y(), gv->z()));
    for(std::size_t i = 0; i < tips.size(); i++) {
      double nearest = -1.;
      for(std::size_t j = 0; j < tips.size(); j++) {
        const double d = tips[i].distance(tips[j]);
        if(j != i && d > 0. && (nearest < 0. || d < nearest)) nearest = d;
      }
      const SPoint3 &p = tips[i];
      const double size = BGM_MeshSize(gf, 0., 0., p.x(), p.y(), p.z());
      if(nearest <= 0. || nearest >= nearlyTheSize * size) continue;
      sources.push_back(p);
      sizes.push_back(std::max(nearest, 0.05 * size));
    }
  }

  // The nodes of gf's curves (embedded ones too) whose shortest segment is
  // shorter than the size asked there, with that length (Gmsh's size of a
  // boundary node, meshGFace.cpp), and its close tips (above)
  std::unique_ptr<gradedBoundarySize> boundarySizes(GFace *gf, double gradient)
  {
    std::map<MVertex *, int> index;
    std::vector<SPoint3> nodes;
    std::vector<std::pair<int, int> > segments;
    std::vector<GEdge *> edges = gf->edges();
    for(GEdge *ge : gf->embeddedEdges()) edges.push_back(ge);
    for(GEdge *ge : edges) {
      for(MLine *l : ge->lines) {
        int ends[2];
        for(int k = 0; k < 2; k++) {
          MVertex *v = l->getVertex(k);
          auto it = index.emplace(v, (int)nodes.size()).first;
          if(it->second == (int)nodes.size()) nodes.push_back(v->point());
          ends[k] = it->second;
        }
        segments.push_back({ends[0], ends[1]});
      }
    }
    const std::vector<double> shortest =
      shortestSegmentAtNodes(nodes, segments);
    std::vector<SPoint3> small;
    std::vector<double> sizes;
    double reach = 0.;
    for(std::size_t i = 0; i < nodes.size(); i++) {
      const SPoint3 &p = nodes[i];
      const double size = BGM_MeshSize(gf, 0., 0., p.x(), p.y(), p.z());
      reach = std::max(reach, size);
      if(shortest[i] <= 0. || shortest[i] >= nearlyTheSize * size) continue;
      small.push_back(p);
      sizes.push_back(shortest[i]);
    }
    closeTips(gf, small, sizes);
    return std::unique_ptr<gradedBoundarySize>(
      new gradedBoundarySize(small, sizes, gradient, reach));
  }

  // A discrete curve's input polyline, its length and the size asked at
  // its middle; false for another kind of curve
  bool measureCurve(GEdge *ge, std::vector<SPoint3> &polyline, double &length,
                    double &size)
  {
    if(!reparamInputPolyline(ge, polyline)) return false;
    length = 0.;
    for(std::size_t i = 0; i + 1 < polyline.size(); i++)
      length += polyline[i].distance(polyline[i + 1]);
    const SPoint3 &middle = polyline[polyline.size() / 2];
    size = BGM_MeshSize(ge, 0., 0., middle.x(), middle.y(), middle.z());
    return true;
  }

  // Points embedded in a discrete face (the tips Reparam keeps as nodes)
  // closer than the size to one of its curves (embedded ones too: the
  // creases it keeps), as sources of the curves'
  // sizes: the curve's nodes there get about that distance apart, and the
  // face's sizes grow from them, instead of one triangle across at the
  // size (bench/README.md, "Sizes from the curves"). Not
  // below a twentieth of the size: a tip nearly on the curve is noise
  void pointsNearCurves(GModel *m, std::vector<SPoint3> &sources,
                        std::vector<double> &sizes)
  {
    for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
      GFace *gf = *it;
      if(gf->geomType() != GEntity::DiscreteSurface ||
         gf->embeddedVertices().empty())
        continue;
      // the face's curves' input polylines, once for all its points
      std::vector<GEdge *> edges = gf->edges();
      for(GEdge *ge : gf->embeddedEdges()) edges.push_back(ge);
      std::vector<std::vector<SPoint3> > polylines;
      for(GEdge *ge : edges) {
        std::vector<SPoint3> polyline;
        if(reparamInputPolyline(ge, polyline))
          polylines.push_back(std::move(polyline));
      }
      for(GVertex *gv : gf->embeddedVertices()) {
        const SPoint3 p(gv->x(), gv->y(), gv->z());
        const double size = BGM_MeshSize(gv, 0., 0., p.x(), p.y(), p.z());
        double nearest = -1.;
        for(const std::vector<SPoint3> &polyline : polylines) {
          const double d = distanceToPolyline(p, polyline);
          if(d >= 0. && (nearest < 0. || d < nearest)) nearest = d;
        }
        if(nearest <= 0. || nearest >= nearlyTheSize * size) continue;
        // the size grows by half the distance: about `nearest` at the curve
        sources.push_back(p);
        sizes.push_back(std::max(0.5 * nearest, 0.05 * size));
      }
    }
  }

  // Strips narrower than this share of the size get sizes of their width,
  // but no finer than that share: a strip of a twentieth of the size along
  // a long curve would get twenty times its nodes
  const double finestStrip = 0.25;

  // gf's input points laid out in its parametrization, when it has one
  // (else in space): a bent strip is straight there
  std::vector<SPoint3> flatInput(const GFace *gf, const surfaceMesh &input)
  {
    std::vector<SPoint3> flat = input.points;
    if(gf->stl_vertices_uv.size() == flat.size())
      for(std::size_t i = 0; i < flat.size(); i++)
        flat[i] =
          SPoint3(gf->stl_vertices_uv[i].x(), gf->stl_vertices_uv[i].y(), 0.);
    return flat;
  }

  // The input edges of gf's curves that cut across smooth parts of the
  // surface: the final optimization crosses them
  // (Geo/optimize/reparamOptimizeAcrossCuts.h), they are no strip's sides
  std::set<edgeByCoordinates> crossableEdges(GFace *gf)
  {
    std::set<edgeByCoordinates> cuts;
    for(GEdge *ge : gf->edges()) {
      std::vector<SPoint3> polyline;
      if(!reparamIsCrossableCurve(ge) || !reparamInputPolyline(ge, polyline))
        continue;
      for(std::size_t i = 0; i + 1 < polyline.size(); i++)
        cuts.insert(byCoordinates(polyline[i], polyline[i + 1]));
    }
    return cuts;
  }

  // The curves of gf with a strip's point on them (every corner of theirs
  // becomes a node, Mesh/curves/curveCornerSnap.h)
  void alongStrips(GFace *gf, const surfaceMesh &input,
                   const std::vector<stripWidth> &strips,
                   std::set<const GEdge *> &along)
  {
    std::set<edgeByCoordinates> edges;
    for(const stripWidth &s : strips)
      edges.insert(byCoordinates(input.points[s.a], input.points[s.b]));
    for(GEdge *ge : gf->edges()) {
      std::vector<SPoint3> polyline;
      if(along.count(ge) || !reparamInputPolyline(ge, polyline)) continue;
      for(std::size_t i = 0; i + 1 < polyline.size(); i++)
        if(edges.count(byCoordinates(polyline[i], polyline[i + 1]))) {
          along.insert(ge);
          break;
        }
    }
  }

  // The strips of gf but those along a curve whose other face folds
  // within a quarter of the size beside it (a crease of 60 degrees or more
  // there, Mesh/layout/creaseChains.h): that face's triangles on the curve's
  // short segments reach over the fold and turn over (bench/README.md,
  // "Narrow strips")
  std::vector<stripWidth>
  keepUnfolded(GFace *gf, const surfaceMesh &input,
               const std::vector<stripWidth> &strips,
               const std::function<double(const SPoint3 &)> &size,
               std::map<GFace *, surfaceMesh> &inputs,
               std::set<const GEdge *> &foldedCurves)
  {
    if(strips.empty()) return strips;
    std::set<edgeByCoordinates> folded;
    for(GEdge *ge : gf->edges()) {
      std::vector<SPoint3> polyline;
      if(!reparamInputPolyline(ge, polyline) || polyline.size() < 2) continue;
      const double near = finestStrip * size(polyline[polyline.size() / 2]);
      bool folds = false;
      for(GFace *other : ge->faces()) {
        if(other == gf || folds ||
           other->geomType() != GEntity::DiscreteSurface)
          continue;
        auto it = inputs.find(other);
        if(it == inputs.end())
          it = inputs.emplace(other, inputTriangulationOf(other)).first;
        folds = creaseWithin(it->second.points, it->second.triangles, polyline,
                             near, M_PI / 3.);
      }
      if(!folds) continue;
      foldedCurves.insert(ge);
      for(std::size_t i = 0; i + 1 < polyline.size(); i++)
        folded.insert(byCoordinates(polyline[i], polyline[i + 1]));
    }
    std::vector<stripWidth> kept;
    for(const stripWidth &s : strips)
      if(!folded.count(byCoordinates(input.points[s.a], input.points[s.b])))
        kept.push_back(s);
    return kept;
  }

  // The boundary points of the discrete faces narrower there than the size
  // (Mesh/sizes/narrowStrips.h), with their width, as sources of the curves'
  // sizes: a strip's curves then get nodes about its width apart and the
  // faces' sizes grow from them
  void narrowStrips(GModel *m, std::vector<SPoint3> &sources,
                    std::vector<double> &sizes, std::set<const GEdge *> &along,
                    std::set<const GEdge *> &folded)
  {
    std::size_t points = 0, faces = 0;
    std::map<GFace *, surfaceMesh> inputs;
    for(auto it = m->firstFace(); it != m->lastFace(); ++it) {
      GFace *gf = *it;
      const parametrizationRecord *map = findParametrization(gf);
      if(gf->geomType() != GEntity::DiscreteSurface || !map || map->map <= 0)
        continue;
      const surfaceMesh input = inputTriangulationOf(gf);
      const auto size = [gf](const SPoint3 &x) {
        return BGM_MeshSize(gf, 0., 0., x.x(), x.y(), x.z());
      };
      const std::set<edgeByCoordinates> cuts = crossableEdges(gf);
      const auto side = [&](int a, int b) {
        return !cuts.count(byCoordinates(input.points[a], input.points[b]));
      };
      const std::vector<stripWidth> strips =
        keepUnfolded(gf, input,
                     narrowStripWidths(input, flatInput(gf, input), size,
                                       nearlyTheSize, side),
                     size, inputs, folded);
      for(const stripWidth &s : strips) {
        sources.push_back(s.point);
        sizes.push_back(std::max(s.width, finestStrip * size(s.point)));
      }
      points += strips.size();
      faces += !strips.empty();
      alongStrips(gf, input, strips, along);
    }
    if(points)
      Msg::Info("Reparam: %lu surface%s narrower than the size: their curves "
                "get sizes of their width at %lu points",
                faces, faces > 1 ? "s" : "", points);
  }

  // A curve's mesh with more segments than this is refused: Gmsh would
  // spend hours and gigabytes on it (coordinates of 1e30 with the default
  // Mesh.MeshSizeMax of 1e22: 4e8 segments on a square's side)
  const double mostSegments = 1e7;

  // One pass over m's discrete curves: the ones whose mesh would have more
  // than mostSegments segments refused (an error each), and, with a
  // gradient, the ends of those shorter than the size asked along them,
  // with the length of their segments, as the sources of the curves' sizes
  std::unique_ptr<gradedBoundarySize>
  measureCurves(GModel *m, double gradient, std::set<const GEdge *> &along,
                std::set<const GEdge *> &folded,
                std::unique_ptr<gradedBoundarySize> &withoutStrips,
                std::vector<std::pair<GEdge *, int> > &refusedCurves)
  {
    const int segments = std::max(1, CTX::instance()->mesh.minCurveNodes - 1);
    std::vector<SPoint3> ends;
    std::vector<double> sizes;
    double reach = 0.;
    for(auto it = m->firstEdge(); it != m->lastEdge(); ++it) {
      GEdge *ge = *it;
      std::vector<SPoint3> polyline;
      double length, size;
      if(reparamCreaseCurveHidden(ge) ||
         !measureCurve(ge, polyline, length, size))
        continue;
      if(length / size > mostSegments) {
        Msg::Error("Reparam: curve %d would get %.3g segments (length %g, "
                   "mesh size %g): not meshed. Set Mesh.MeshSizeMin and "
                   "Mesh.MeshSizeMax (or Mesh.MeshSizeFactor) to the "
                   "model's scale",
                   ge->tag(), length / size, length, size);
        refusedCurves.push_back({ge, ge->meshAttributes.method});
        ge->meshAttributes.method = MESH_NONE;
        continue;
      }
      reach = std::max(reach, size);
      if(gradient <= 0. || length <= 0. || length >= nearlyTheSize * size)
        continue;
      for(const SPoint3 &p : {polyline.front(), polyline.back()}) {
        ends.push_back(p);
        sizes.push_back(length / segments);
      }
    }
    if(gradient > 0.) {
      pointsNearCurves(m, ends, sizes);
      if(getReparamOptions().meshSizeFromStrips) {
        withoutStrips.reset(
          new gradedBoundarySize(ends, sizes, gradient, reach));
        narrowStrips(m, ends, sizes, along, folded);
      }
    }
    return std::unique_ptr<gradedBoundarySize>(
      new gradedBoundarySize(ends, sizes, gradient, reach));
  }

} // namespace

} // namespace reparam

using namespace reparam;

void reparamBeginCurveSizeGrading(GModel *m)
{
  if(getReparamOptions().parametrization == (int)compoundParametrization::gmsh)
    return;
  reparamHideSmallCreaseCurves(m);
  std::unique_lock<std::mutex> lock = lockRecords();
  modelRecord &record = modelRecordOf(m);
  lock.unlock();
  // (main thread: Mesh1D starts)
  const double gradient = getReparamOptions().meshSizeGradient;
  std::set<const GEdge *> along, folded;
  std::unique_ptr<gradedBoundarySize> withoutStrips;
  std::unique_ptr<gradedBoundarySize> size = measureCurves(
    m, gradient, along, folded, withoutStrips, record.refusedCurves);
  if(gradient <= 0. || !size->size()) return;
  Msg::Debug("Reparam: curve sizes graded from %lu sources", size->size());
  curveSizeGrading &curves = record.curveSizes;
  curves.size = std::move(size);
  curves.alongStrips.swap(along);
  curves.folded.swap(folded);
  curves.withoutStrips = std::move(withoutStrips);
}

void reparamEndCurveSizeGrading(GModel *m)
{
  reparamDeleteHiddenCreaseMeshes(m);
  std::unique_lock<std::mutex> lock = lockRecords();
  modelRecord *record = findModelRecord(m);
  lock.unlock();
  if(!record) return;
  for(const auto &r : record->refusedCurves) {
    if(r.first->model() != m) continue;
    r.first->meshAttributes.method = r.second;
    for(GFace *gf : r.first->faces()) {
      if(gf->meshAttributes.method == MESH_NONE) continue;
      Msg::Warning("Reparam: surface %d not meshed: its curve %d is not",
                   gf->tag(), r.first->tag());
      record->refusedSurfaces.push_back({gf, gf->meshAttributes.method});
      gf->meshAttributes.method = MESH_NONE;
    }
  }
  record->refusedCurves.clear();
  record->curveSizes = curveSizeGrading();
}

namespace reparam {

void reparamRestoreRefusedSurfaces(GModel *m)
{
  std::unique_lock<std::mutex> lock = lockRecords();
  modelRecord *record = findModelRecord(m);
  lock.unlock();
  if(!record) return;
  std::vector<std::pair<GFace *, int> > others;
  for(const auto &r : record->refusedSurfaces)
    if(r.first->model() == m)
      r.first->meshAttributes.method = r.second;
    else
      others.push_back(r);
  record->refusedSurfaces.swap(others);
}

namespace {

  // The sizes along ge's model's curves while they are meshed, if graded
  // and ge is a discrete curve
  const curveSizeGrading *curveGradingOf(const GEdge *ge)
  {
    std::unique_lock<std::mutex> lock = lockRecords();
    const modelRecord *record = findModelRecord(ge->model());
    if(!record || !record->curveSizes.size ||
       ge->geomType() != GEntity::DiscreteCurve)
      return nullptr;
    return &record->curveSizes;
  }

} // namespace

bool reparamCurveSizesGraded(const GEdge *ge)
{
  return curveGradingOf(ge) != nullptr;
}

bool reparamCurveAlongNarrowStrip(const GEdge *ge)
{
  const curveSizeGrading *curves = curveGradingOf(ge);
  return curves && curves->alongStrips.count(ge);
}

double reparamGradedCurveSize(const GEdge *ge, const SPoint3 &x, double size)
{
  const curveSizeGrading *curves = curveGradingOf(ge);
  if(!curves) return size;
  if(curves->withoutStrips && curves->folded.count(ge))
    return (*curves->withoutStrips)(x, size);
  return (*curves->size)(x, size);
}

void reparamBeginSizeGrading(GFace *gf)
{
  // Reparam's maps only: Gmsh's own (0) keeps Gmsh's sizes (the reference)
  const parametrizationRecord *map = findParametrization(gf);
  const double gradient = getReparamOptions().meshSizeGradient;
  if(!map || map->map <= 0 || gradient <= 0. || !gf->getMeshSizeFromBoundary())
    return;
  faceSizeGrading &current = thisThreadsFaceMeshing().grading;
  current.size = boundarySizes(gf, gradient);
  current.face = gf;
  current.meshSizeFromBoundary = gf->meshAttributes.meshSizeFromBoundary;
  gf->setMeshSizeFromBoundary(0);
  Msg::Debug("Reparam: surface %d: sizes of %lu boundary nodes graded by %g",
             gf->tag(), current.size->size(), gradient);
}

void reparamEndSizeGrading(GFace *gf)
{
  faceSizeGrading &current = thisThreadsFaceMeshing().grading;
  if(current.face != gf) return;
  gf->setMeshSizeFromBoundary(current.meshSizeFromBoundary);
  current = faceSizeGrading();
}

} // namespace reparam

double reparamGradedMeshSize(GEntity *ge, double x, double y, double z,
                             double size)
{
  const faceMeshingContext &context = thisThreadsFaceMeshing();
  const faceSizeGrading &current = context.grading;
  if(!current.face || ge != current.face || context.ungradedSize) return size;
  return (*current.size)(SPoint3(x, y, z), size);
}

namespace reparam {

double reparamUngradedMeshSize(GFace *gf, const SPoint3 &x)
{
  faceMeshingContext &context = thisThreadsFaceMeshing();
  context.ungradedSize = true;
  const double size = BGM_MeshSize(gf, 0., 0., x.x(), x.y(), x.z());
  context.ungradedSize = false;
  return size;
}
} // namespace reparam
