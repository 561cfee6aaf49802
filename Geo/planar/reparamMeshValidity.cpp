// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include "GEdge.h"
#include "GFace.h"
#include "GmshDefines.h"
#include "GmshMessage.h"
#include "MEdge.h"
#include "MElement.h"
#include "MLine.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "closestTriangle.h"
#include "invertedElementRepair.h"
#include "meshFidelity.h"
#include "reparamBamg.h"
#include "reparamHooks.h"
#include "reparamInputMesh.h"
#include "reparamMesherFallback.h"
#include "reparamMeshValidity.h"
#include "reparamReport.h"
#include "reparamSizeGrading.h"
#include "reparamSurfaceMesh.h"

namespace reparam {

std::size_t countElementsAgainstFaceNormals(GFace *gf)
{
  std::size_t against = 0;
  for(MTriangle *t : gf->triangles) {
    SVector3 n(0., 0., 0.);
    for(int k = 0; k < 3; k++) {
      SPoint2 uv;
      reparamMeshVertexOnFace(t->getVertex(k), gf, uv);
      n += gf->normal(uv);
    }
    SVector3 d1(t->getVertex(0)->point(), t->getVertex(1)->point());
    SVector3 d2(t->getVertex(0)->point(), t->getVertex(2)->point());
    if(dot(n, crossprod(d1, d2)) < 0.) against++;
  }
  return std::min(against, gf->triangles.size() - against);
}

namespace {

  // Splits the edges of the triangles pointing against the input (the
  // report's test), in the orientation most triangles have; returns how
  // many still do
  std::size_t repairInvertedTriangles(GFace *gf)
  {
    const surfaceMesh input = inputTriangulationOf(gf);
    if(input.triangles.empty()) return 0;
    const closestTriangleSearch onInput(input.points, input.triangles);
    auto raw = [&](MTriangle *t) {
      return triangleAgainstInput(t->getVertex(0)->point(),
                                  t->getVertex(1)->point(),
                                  t->getVertex(2)->point(), input, onInput);
    };
    std::size_t against = 0;
    for(MTriangle *t : gf->triangles) against += raw(t);
    const bool reversed = 2 * against > gf->triangles.size();
    // bounded: each pass searches the input under every triangle three
    // times, and on a CAD input with huge triangles among tiny ones a search
    // is slow (minutes on a wound CAD face, bench/README.md, Elements against
    // the input); past the budget none counts as against, which ends the
    // repair (the optimization after it counts again)
    const std::size_t budget = 20 * gf->triangles.size() + 1000;
    std::size_t used = 0;
    invertedRepair repair = splitInvertedTriangles(gf, [&](MTriangle *t) {
      if(used >= budget) return false;
      used++;
      return raw(t) != reversed;
    });
    if(used >= budget) {
      forgetOptimization(gf);
      Msg::Info("Reparam: surface %d: repair of the triangles against the "
                "input stopped after %lu searches",
                gf->tag(), used);
      return 0;
    }
    // a mesh changed after its optimization is optimized again (in
    // discreteFace::mesh), with its own count of triangles against the input
    if(repair.changes || repair.moves) forgetOptimization(gf);
    if(repair.changes || repair.moves)
      Msg::Info("Reparam: surface %d: %lu triangles against the input, %lu "
                "after %lu edge splits or flips and %lu node moves in %lu "
                "passes",
                gf->tag(), repair.before, repair.after, repair.changes,
                repair.moves, repair.passes);
    if(repair.after && Msg::GetVerbosity() > 98)
      for(MTriangle *t : gf->triangles)
        if(raw(t) != reversed) {
          const SPoint3 c = t->barycenter();
          std::string corners;
          for(int k = 0; k < 3; k++) {
            const MVertex *v = t->getVertex(k);
            char text[128];
            snprintf(text, sizeof(text), " (%g, %g, %g) on %d %d", v->x(),
                     v->y(), v->z(), v->onWhat()->dim(), v->onWhat()->tag());
            corners += text;
          }
          Msg::Debug("Reparam: surface %d: triangle against the input at "
                     "(%g, %g, %g), corners (on entity dimension, tag)%s",
                     gf->tag(), c.x(), c.y(), c.z(), corners.c_str());
        }
    return repair.after;
  }

} // namespace

namespace {

  // A face whose mesh has edges longer than twice the size, none against
  // the input: the planar mesher did not fill it (a hole's wall of needle
  // triangles as tall as four sizes, whose (u, v) image squeezes its height:
  // Frontal-Delaunay finds no point to insert). MeshAdapt, which refines by
  // edge splits instead of points placed in (u, v), kept if it does better
  // (logged); Delaunay filled no such wall (bench/README.md, Faces left
  // nearly empty)
  void fillWithAnotherMesher(GFace *gf)
  {
    meshDefects defects;
    defects.longEdges = countLongEdges(gf);
    if(!defects.longEdges) return;
    Msg::Info("Reparam: surface %d: the planar mesh leaves %lu edges longer "
              "than twice the size",
              gf->tag(), defects.longEdges);
    reparamTryOtherMesher(gf, defects, ALGO_2D_MESHADAPT);
  }

  // A triangle mesh of a face Reparam parametrized: Gmsh's map keeps Gmsh's
  // behaviour (the reference)
  bool isReparamTriangleMesh(GFace *gf)
  {
    const parametrizationRecord *record = findParametrization(gf);
    return record && record->map > 0 && !gf->triangles.empty() &&
           gf->quadrangles.empty();
  }

} // namespace

namespace {

  // A quadrangle mesh of a face Reparam parametrized (Blossom's)
  bool isReparamQuadMesh(GFace *gf)
  {
    const parametrizationRecord *record = findParametrization(gf);
    return record && record->map > 0 && !gf->quadrangles.empty();
  }

  // Kept when at most 1 % of its elements point against the input under
  // them (the report's test): Gmsh's test, which takes the normals at the
  // nodes, fails a recombined mesh across a fold thinner than the mesh size
  // as it fails a triangle mesh, and MeshAdapt, remeshing the whole face,
  // crosses the same folds, slower and worse. Above 1 %, compared with the
  // other meshers' for that face instead of taking MeshAdapt's blindly
  // (bench/README.md, MeshAdapt for a whole face). The triangle repairs
  // above do not apply to quadrangles
  bool keepQuadMesh(GFace *gf)
  {
    // a mesh tried in place of another: compared there
    if(reparamTryingOtherMesher()) return true;
    const surfaceMesh input = inputTriangulationOf(gf);
    if(input.triangles.empty()) return false;
    const std::size_t elements = gf->getNumMeshElements();
    // in the orientation most of them have (Gmsh orients the face after)
    std::size_t against = countInverted(input, surfaceMeshOf(gf));
    against = std::min(against, elements - against);
    if(100 * against > elements) {
      // Delaunay's, the fastest, then MeshAdapt's (Gmsh's choice)
      meshDefects defects;
      defects.againstInput = against;
      if(!reparamTryOtherMesher(gf, defects, ALGO_2D_DELAUNAY))
        reparamTryOtherMesher(gf, defects, ALGO_2D_MESHADAPT);
      return true;
    }
    if(against)
      Msg::Info("Reparam: surface %d: quadrangle mesh kept with %lu of its "
                "%lu elements against the input (no MeshAdapt remesh)",
                gf->tag(), against, elements);
    return true;
  }

} // namespace

} // namespace reparam

using namespace reparam;

bool reparamKeepPlanarMesh(GFace *gf)
{
  if(isReparamQuadMesh(gf)) return keepQuadMesh(gf);
  if(!isReparamTriangleMesh(gf)) return false;
  // a mesh tried in place of another: compared there
  if(reparamTryingOtherMesher()) return true;
  // None against the input under it (the report's test, which samples the
  // input at the centroid and halfway to the corners) or none against the
  // normals at the nodes (Gmsh's test): kept. MeshAdapt would only cross
  // the same thin folds, slower (bench/README.md, Elements against the
  // input).
  // Mesh.CompoundOptimize turns back the triangles against the input with
  // the others it optimizes (Geo/optimize/reparamOptimizeFace.cpp): when none is
  // left, the mesh is kept without a second search of the input under
  // every triangle
  reparamOptimizeMeshedFace(gf);
  const optimizationRecord *o = findOptimization(gf);
  if(o && !o->againstAfter) {
    fillWithAnotherMesher(gf);
    return true;
  }
  const std::size_t left = repairInvertedTriangles(gf);
  if(!left) return true;
  // MeshAdapt, for this face only, where it leaves fewer
  meshDefects defects;
  defects.againstInput = left;
  if(reparamTryOtherMesher(gf, defects)) {
    // some still: the input's own triangles if they have fewer; in any
    // case not MeshAdapt
    const std::size_t after = countTrianglesAgainstInput(gf);
    if(after) reparamMeshFaceWithItsInput(gf, after);
    return true;
  }
  // across a strip narrower than the mesh size whose curve meshes cross:
  // the input's own triangles, if they are better
  if(reparamMeshFaceWithItsInput(gf, left)) return true;
  const std::size_t against = countElementsAgainstFaceNormals(gf);
  if(!against) return true;
  if(100 * against > gf->triangles.size()) {
    // Gmsh would remesh it with MeshAdapt: only if that has fewer
    meshDefects defects;
    defects.againstInput = left; // the mesh the repair left, unchanged since
    reparamTryOtherMesher(gf, defects, ALGO_2D_MESHADAPT);
    return true;
  }
  Msg::Info("Reparam: surface %d: mesh kept with %lu of its %lu elements "
            "against the normals at their nodes (no MeshAdapt remesh)",
            gf->tag(), against, gf->triangles.size());
  return true;
}

namespace reparam {

std::size_t countLongEdges(GFace *gf)
{
  std::map<MVertex *, double> size;
  auto sizeAt = [&](MVertex *v) {
    auto it = size.find(v);
    if(it != size.end()) return it->second;
    const double s = reparamUngradedMeshSize(gf, v->point());
    size[v] = s;
    return s;
  };
  std::set<std::pair<MVertex *, MVertex *> > seen;
  std::size_t count = 0;
  for(std::size_t e = 0; e < gf->getNumMeshElements(); e++) {
    MElement *el = gf->getMeshElement(e);
    for(int k = 0; k < el->getNumEdges(); k++) {
      MVertex *a = el->getEdge(k).getVertex(0),
              *b = el->getEdge(k).getVertex(1);
      if(!seen.insert(std::make_pair(std::min(a, b), std::max(a, b))).second)
        continue;
      count += a->distance(b) > (sizeAt(a) + sizeAt(b));
    }
  }
  return count;
}

std::size_t countUnusedCurveSegments(GFace *gf)
{
  // how many times each curve bounds gf: a curve listed twice is a slit
  std::map<GEdge *, int> bounds;
  for(GEdge *ge : gf->edges()) bounds[ge]++;
  for(GEdge *ge : gf->embeddedEdges()) bounds[ge] += 2;
  typedef std::pair<MVertex *, MVertex *> segment;
  auto key = [](MVertex *a, MVertex *b) {
    return a < b ? segment(a, b) : segment(b, a);
  };
  std::map<segment, int> expected;
  for(const auto &b : bounds)
    for(MLine *l : b.first->lines)
      expected[key(l->getVertex(0), l->getVertex(1))] += b.second;
  std::map<segment, int> used;
  for(std::size_t e = 0; e < gf->getNumMeshElements(); e++) {
    MElement *el = gf->getMeshElement(e);
    for(int k = 0; k < el->getNumEdges(); k++) {
      const MEdge edge = el->getEdge(k);
      auto it = expected.find(key(edge.getVertex(0), edge.getVertex(1)));
      if(it != expected.end()) used[it->first]++;
    }
  }
  std::size_t unused = 0;
  for(const auto &e : expected) {
    auto it = used.find(e.first);
    if(it == used.end() || it->second < e.second) unused++;
  }
  return unused;
}

} // namespace reparam

bool reparamPlanarMeshLeavesHole(GFace *gf)
{
  // quadrangle meshes too: Blossom's pairing, and Gmsh's smoothing of the
  // quadrangles in (u, v), can leave a quadrangle with two nodes of its
  // curve as a diagonal, the segment between them used by the face on its
  // other side only (a boundary loop more; bench/README.md, Curve segments
  // left unused)
  if(reparamTryingOtherMesher()) return false;
  // taken whatever the mesh: no face is left in the list for another model
  const bool bamgFailed = takeBamgFailure(gf);
  if(!(isReparamTriangleMesh(gf) || isReparamQuadMesh(gf))) return false;
  if(bamgFailed) {
    // the mesh BAMG started from, which Delaunay made under BAMG's global
    // algorithm without the sizes: any whole mesh of Delaunay's is better
    meshDefects failed;
    failed.againstInput = (std::size_t)-1;
    reparamTryOtherMesher(gf, failed, ALGO_2D_DELAUNAY);
  }
  meshDefects defects;
  defects.unusedCurveSegments = countUnusedCurveSegments(gf);
  if(!defects.unusedCurveSegments) return false;
  defects.againstInput = (std::size_t)-1; // any whole mesh is better
  Msg::Info("Reparam: surface %d: the planar mesh leaves %lu segment%s of "
            "its curves unused (a hole)",
            gf->tag(), defects.unusedCurveSegments,
            defects.unusedCurveSegments > 1 ? "s" : "");
  if(reparamTryOtherMesher(gf, defects) && !countUnusedCurveSegments(gf))
    return false;
  Msg::Info("Reparam: surface %d: remeshed with MeshAdapt", gf->tag());
  return true;
}

