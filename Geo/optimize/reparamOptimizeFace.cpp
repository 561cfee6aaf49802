// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// The new mesh of a discrete face optimized on its input triangulation
// (Mesh.CompoundOptimize; hook in discreteFace::mesh, patches/0001, after the
// planar mesher and before the face's report): Mesh/optimize/optimizeOnInput.h
// on the face's triangles, its curves' nodes and edges (boundary and embedded)
// kept, and each moved or new node given the (u, v) the face's parametric
// interface has for the input point it lies on, so that it still maps it there.

#include <algorithm>
#include <set>
#include "GEdge.h"
#include "GFace.h"
#include "GmshMessage.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "OS.h"
#include "closestTriangle.h"
#include "optimizeOnInput.h"
#include "reparamCurveMesh.h"
#include "reparamHooks.h"
#include "reparamInputMesh.h"
#include "reparamOptimizableMesh.h"
#include "reparamCurvatureMetric.h"
#include "reparamOptions.h"
#include "reparamReport.h"
#include "reparamSurfaceMesh.h"
#include "surfaceMesh.h"

namespace reparam {

namespace {

  // Whether gf shares a smooth cut with another face Reparam parametrized:
  // the faces' optimization across their cuts (Geo/optimize/reparamOptimizeAcrossCuts.h)
  // will smooth gf's nodes with the cuts' free
  bool joinedByCut(GFace *gf)
  {
    for(GEdge *ge : gf->edges()) {
      const std::vector<GFace *> sides = ge->faces();
      if(sides.size() != 2 || !reparamIsCrossableCurve(ge)) continue;
      GFace *other = sides[0] == gf ? sides[1] : sides[0];
      const parametrizationRecord *map = findParametrization(other);
      if(other != gf && map && map->map > 0) return true;
    }
    return false;
  }

  // The (u, v) of point p of gf's input, as gf's parametric interface
  // knows it: Gmsh replaces the map of a planar face by coordinates on its
  // mean plane (discreteFace::param::checkPlanar), without changing
  // stl_vertices_uv
  SPoint2 uvOf(GFace *gf, const SPoint3 &p) { return gf->parFromPoint(p); }

  // The node of each point of m: moved nodes get the (u, v) of the input
  // point they lie on, new nodes (input nodes inserted, edges split) are
  // created; the nodes of gf that no point keeps (edges collapsed) are
  // deleted
  std::vector<MVertex *> writeNodes(GFace *gf, const optimizableMesh &m,
                                    const std::vector<MVertex *> &nodes)
  {
    std::vector<MVertex *> out(m.points.size(), nullptr);
    std::vector<bool> kept(nodes.size(), false);
    for(std::size_t i = 0; i < m.points.size(); i++) {
      const SPoint3 &p = m.points[i];
      const int origin = m.origin[i];
      if(origin < 0) {
        const SPoint2 uv = uvOf(gf, p);
        out[i] = new MFaceVertex(p.x(), p.y(), p.z(), gf, uv.x(), uv.y());
        gf->mesh_vertices.push_back(out[i]);
        continue;
      }
      out[i] = nodes[origin];
      kept[origin] = true;
      if(m.landing[i] < 0) continue;
      out[i]->setXYZ(p.x(), p.y(), p.z());
      const SPoint2 uv = uvOf(gf, p);
      out[i]->setParameter(0, uv.x());
      out[i]->setParameter(1, uv.y());
    }
    std::set<MVertex *> gone;
    for(std::size_t i = 0; i < nodes.size(); i++)
      if(!kept[i]) gone.insert(nodes[i]); // only face nodes are collapsed
    if(!gone.empty()) {
      std::vector<MVertex *> &own = gf->mesh_vertices;
      own.erase(std::remove_if(own.begin(), own.end(),
                               [&](MVertex *v) { return gone.count(v) > 0; }),
                own.end());
      for(MVertex *v : gone) delete v;
    }
    return out;
  }

  // gf's triangles as m's: kept ones reused, new ones created, removed ones
  // deleted
  void writeBack(GFace *gf, const optimizableMesh &m,
                 const std::vector<MVertex *> &nodes)
  {
    const std::vector<MVertex *> out = writeNodes(gf, m, nodes);
    std::vector<MTriangle *> triangles;
    std::vector<bool> kept(gf->triangles.size(), false);
    for(std::size_t t = 0; t < m.triangles.size(); t++) {
      MVertex *c[3] = {out[m.triangles[t][0]], out[m.triangles[t][1]],
                       out[m.triangles[t][2]]};
      const int origin = m.triangleOrigin[t];
      if(origin < 0) {
        triangles.push_back(new MTriangle(c[0], c[1], c[2]));
        continue;
      }
      MTriangle *old = gf->triangles[origin];
      kept[origin] = true;
      for(int k = 0; k < 3; k++) old->setVertex(k, c[k]);
      triangles.push_back(old);
    }
    for(std::size_t t = 0; t < gf->triangles.size(); t++)
      if(!kept[t]) delete gf->triangles[t];
    gf->triangles = triangles;
  }

} // namespace

} // namespace reparam

using namespace reparam;

bool reparamOptimizeMeshedFace(GFace *gf)
{
  const parametrizationRecord *map = findParametrization(gf);
  if(!getReparamOptions().optimize || !map || map->map <= 0 ||
     gf->geomType() != GEntity::DiscreteSurface || gf->triangles.empty() ||
     !gf->quadrangles.empty() || gf->stl_triangles.empty() ||
     gf->stl_vertices_uv.size() != gf->stl_vertices_xyz.size() ||
     findOptimization(gf) || keptAsInput(gf) || reparamAnisotropicFace(gf))
    return false;
  const double t0 = TimeOfDay();
  // only the face's own nodes move: curves and points stay
  std::vector<MVertex *> nodes;
  std::vector<int> triangleFace;
  optimizableMesh m = optimizableMeshOf(
    {gf}, {}, [gf](const MVertex *v) { return v->onWhat() == gf; }, {}, nodes,
    triangleFace);
  const surfaceMesh input = inputTriangulationOf(gf);
  const closestTriangleSearch onInput(input.points, input.triangles);
  meshOptimizationOptions o;
  o.reversed = meshReversedOnInput(gf, input, onInput);
  // 2: coarsen too where the curves' short segments made the mesh finer
  // than asked (fewer triangles, edges closer to the size; slower)
  o.collapseBelow = getReparamOptions().optimize >= 2 ? 0.6 : 0.;
  if(joinedByCut(gf)) o.smoothPasses = 0;
  const meshOptimizationResult r = optimizeOnInput(m, input, onInput, o);
  if(r.flips || r.moves || r.inserted || r.splits || r.collapses || r.cavities)
    writeBack(gf, m, nodes);
  optimizationRecord done;
  done.done = true;
  done.kappaMinBefore = r.minBefore;
  done.seconds = TimeOfDay() - t0;
  done.inserted = r.inserted;
  done.splits = r.splits;
  done.collapses = r.collapses;
  done.flips = r.flips;
  done.moves = r.moves;
  done.againstBefore = r.againstBefore;
  done.againstAfter = r.againstAfter;
  done.reversed = o.reversed;
  done.elements = gf->getNumMeshElements();
  done.firstElement = gf->getMeshElement(0);
  recordOptimization(gf, done);
  if(!r.belowBefore && !r.againstBefore && !r.inserted && !r.splits &&
     !r.collapses)
    return true;
  Msg::Info("Reparam: surface %d: optimized on the input: kappa min %.3g -> "
            "%.3g, %lu -> %lu triangles below %g, %lu -> %lu against the "
            "input; %lu input nodes the mesh cut off inserted (%lu onto a "
            "node moved there), %lu long edges split, %lu short ones "
            "collapsed, %lu tangles re-meshed, %lu flips and %lu node moves "
            "in %lu passes (%g s)",
            gf->tag(), r.minBefore, r.minAfter, r.belowBefore, r.belowAfter,
            o.target, r.againstBefore, r.againstAfter, r.inserted, r.snapped,
            r.splits, r.collapses, r.cavities, r.flips, r.moves, r.passes,
            TimeOfDay() - t0);
  return true;
}

