// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include "GFace.h"
#include "GmshMessage.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "closestTriangle.h"
#include "invertedElementRepair.h"
#include "meshFidelity.h"
#include "reparamInputMesh.h"
#include "reparamMeshValidity.h"
#include "reparamOptimizeFace.h"
#include "reparamReport.h"

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
    // is slow (a mean value face of gmsh2x_king_ascii with 53 triangles
    // against it: minutes); past the budget none counts as against, which
    // ends the repair (the optimization after it counts again)
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
    return repair.after;
  }

} // namespace

bool reparamKeepPlanarMesh(GFace *gf)
{
  // Reparam's own maps only: Gmsh's map keeps Gmsh's behaviour (reference)
  const parametrizationRecord *record = findParametrization(gf);
  if(!record || record->map <= 0 || gf->triangles.empty() ||
     !gf->quadrangles.empty())
    return false;
  // None against the input under it (the report's test, which samples the
  // input at the centroid and halfway to the corners) or none against the
  // normals at the nodes (Gmsh's test): kept. MeshAdapt would only cross
  // the same thin folds, slower (a 33-element face of gmsh2x_skull: 1
  // element failed Gmsh's test, none the report's; MeshAdapt left 1)
  // Mesh.CompoundOptimize turns back the triangles against the input with
  // the others it optimizes (Geo/reparamOptimizeFace.cpp): when none is
  // left, the mesh is kept without a second search of the input under
  // every triangle
  if(reparamOptimizeMeshedFace(gf)) {
    const optimizationRecord *o = findOptimization(gf);
    if(o && !o->againstAfter) return true;
  }
  const std::size_t left = repairInvertedTriangles(gf);
  if(!left) return true;
  // across a strip narrower than the mesh size whose curve meshes cross:
  // the input's own triangles, if they are better
  if(reparamMeshFaceWithItsInput(gf, left)) return true;
  const std::size_t against = countElementsAgainstFaceNormals(gf);
  if(!against) return true;
  if(100 * against > gf->triangles.size()) return false;
  Msg::Info("Reparam: surface %d: mesh kept with %lu of its %lu elements "
            "against the normals at their nodes (no MeshAdapt remesh)",
            gf->tag(), against, gf->triangles.size());
  return true;
}
