// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <map>
#include <memory>
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
#include "gradedBoundarySize.h"
#include "reparamCreaseCurves.h"
#include "reparamCurveMesh.h"
#include "reparamOptions.h"
#include "reparamReport.h"
#include "reparamSizeGrading.h"

namespace {

  // Boundary nodes whose segments are this close to the size asked are
  // left out: they would barely change it, and every query goes through
  // the nodes smaller than the size it finds
  const double nearlyTheSize = 0.9;

  // One face at a time per thread: Gmsh meshes each face on one thread
  struct grading {
    GFace *face = nullptr;
    int meshSizeFromBoundary = -1; // the face's own setting, restored
    std::unique_ptr<gradedBoundarySize> size;
  };
  thread_local grading current;
  // reparamUngradedMeshSize is asking
  thread_local bool ungraded = false;

  // The nodes of gf's curves (embedded ones too) whose shortest segment is
  // shorter than the size asked there, with that length (Gmsh's size of a
  // boundary node, meshGFace.cpp)
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
    return std::unique_ptr<gradedBoundarySize>(
      new gradedBoundarySize(small, sizes, gradient, reach));
  }

  // The curves' sizes while they are meshed: read by every thread
  struct curveGrading {
    GModel *model = nullptr;
    std::unique_ptr<gradedBoundarySize> size;
  };
  curveGrading curves;

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
  // size (camelhead: two tips 0.3 sizes from a crease, kappa 0.42). Not
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

  // A curve's mesh with more segments than this is refused: Gmsh would
  // spend hours and gigabytes on it (coordinates of 1e30 with the default
  // Mesh.MeshSizeMax of 1e22: 4e8 segments on a square's side)
  const double mostSegments = 1e7;

  // The curves refused, with their meshing method, restored after Mesh1D,
  // and the surfaces on them, restored after Mesh2D
  std::vector<std::pair<GEdge *, int> > refusedCurves;
  std::vector<std::pair<GFace *, int> > refusedSurfaces;

  // One pass over m's discrete curves: the ones whose mesh would have more
  // than mostSegments segments refused (an error each), and, with a
  // gradient, the ends of those shorter than the size asked along them,
  // with the length of their segments, as the sources of the curves' sizes
  std::unique_ptr<gradedBoundarySize> measureCurves(GModel *m, double gradient)
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
    if(gradient > 0.) pointsNearCurves(m, ends, sizes);
    return std::unique_ptr<gradedBoundarySize>(
      new gradedBoundarySize(ends, sizes, gradient, reach));
  }

} // namespace

void reparamBeginCurveSizeGrading(GModel *m)
{
  if(getReparamOptions().parametrization == (int)compoundParametrization::gmsh)
    return;
  reparamHideSmallCreaseCurves(m);
  const double gradient = getReparamOptions().meshSizeGradient;
  std::unique_ptr<gradedBoundarySize> size = measureCurves(m, gradient);
  if(gradient <= 0. || !size->size()) return;
  Msg::Debug("Reparam: curve sizes graded from the ends of %lu short curves",
             size->size() / 2);
  curves.size = std::move(size);
  curves.model = m;
}

void reparamEndCurveSizeGrading(GModel *m)
{
  reparamDeleteHiddenCreaseMeshes(m);
  for(const auto &r : refusedCurves) {
    if(r.first->model() != m) continue;
    r.first->meshAttributes.method = r.second;
    for(GFace *gf : r.first->faces()) {
      if(gf->meshAttributes.method == MESH_NONE) continue;
      Msg::Warning("Reparam: surface %d not meshed: its curve %d is not",
                   gf->tag(), r.first->tag());
      refusedSurfaces.push_back({gf, gf->meshAttributes.method});
      gf->meshAttributes.method = MESH_NONE;
    }
  }
  refusedCurves.clear();
  if(curves.model == m) curves = curveGrading();
}

void reparamRestoreRefusedSurfaces(GModel *m)
{
  std::vector<std::pair<GFace *, int> > others;
  for(const auto &r : refusedSurfaces)
    if(r.first->model() == m)
      r.first->meshAttributes.method = r.second;
    else
      others.push_back(r);
  refusedSurfaces.swap(others);
}

bool reparamCurveSizesGraded(const GEdge *ge)
{
  return curves.model && ge->model() == curves.model &&
         ge->geomType() == GEntity::DiscreteCurve;
}

double reparamGradedCurveSize(const GEdge *ge, const SPoint3 &x, double size)
{
  if(!reparamCurveSizesGraded(ge)) return size;
  return (*curves.size)(x, size);
}

void reparamBeginSizeGrading(GFace *gf)
{
  // Reparam's maps only: Gmsh's own (0) keeps Gmsh's sizes (the reference)
  const parametrizationRecord *map = findParametrization(gf);
  const double gradient = getReparamOptions().meshSizeGradient;
  if(!map || map->map <= 0 || gradient <= 0. || !gf->getMeshSizeFromBoundary())
    return;
  current.size = boundarySizes(gf, gradient);
  current.face = gf;
  current.meshSizeFromBoundary = gf->meshAttributes.meshSizeFromBoundary;
  gf->setMeshSizeFromBoundary(0);
  Msg::Debug("Reparam: surface %d: sizes of %lu boundary nodes graded by %g",
             gf->tag(), current.size->size(), gradient);
}

void reparamEndSizeGrading(GFace *gf)
{
  if(current.face != gf) return;
  gf->setMeshSizeFromBoundary(current.meshSizeFromBoundary);
  current = grading();
}

double reparamGradedMeshSize(GEntity *ge, double x, double y, double z,
                             double size)
{
  if(!current.face || ge != current.face || ungraded) return size;
  return (*current.size)(SPoint3(x, y, z), size);
}

double reparamUngradedMeshSize(GFace *gf, const SPoint3 &x)
{
  ungraded = true;
  const double size = BGM_MeshSize(gf, 0., 0., x.x(), x.y(), x.z());
  ungraded = false;
  return size;
}
