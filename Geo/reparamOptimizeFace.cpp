// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <set>
#include <unordered_map>
#include "GEdge.h"
#include "GFace.h"
#include "BackgroundMeshTools.h"
#include "GmshMessage.h"
#include "MLine.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "OS.h"
#include "closestTriangle.h"
#include "meshFidelity.h"
#include "reparamOptimizeFace.h"
#include "reparamOptions.h"
#include "reparamReport.h"
#include "surfaceMeshOptimizer.h"

namespace {

  // gf's triangles as an optimizableMesh; nodes[i] is point i's node
  optimizableMesh meshOfFace(GFace *gf, std::vector<MVertex *> &nodes)
  {
    optimizableMesh m;
    std::unordered_map<MVertex *, int> index;
    auto indexOf = [&](MVertex *v) {
      auto it = index.find(v);
      if(it != index.end()) return it->second;
      const int i = (int)nodes.size();
      index[v] = i;
      nodes.push_back(v);
      m.points.push_back(v->point());
      // only the face's own nodes move: curves and points stay
      m.movable.push_back(v->onWhat() == gf);
      // the size asked (Mesh.MeshSize*, fields) where it is
      SPoint2 uv;
      reparamMeshVertexOnFace(v, gf, uv);
      m.size.push_back(
        BGM_MeshSize(gf, uv.x(), uv.y(), v->x(), v->y(), v->z()));
      return i;
    };
    for(MTriangle *t : gf->triangles)
      m.triangles.push_back({{indexOf(t->getVertex(0)),
                              indexOf(t->getVertex(1)),
                              indexOf(t->getVertex(2))}});
    // curves inside the face (creases kept): their edges stay
    for(GEdge *ge : gf->embeddedEdges())
      for(MLine *l : ge->lines) {
        auto a = index.find(l->getVertex(0)), b = index.find(l->getVertex(1));
        if(a == index.end() || b == index.end()) continue;
        m.lockedEdges.insert(std::make_pair(std::min(a->second, b->second),
                                            std::max(a->second, b->second)));
      }
    return m;
  }

  // Whether most triangles of m turn against the input (counted on at most
  // about a hundred of them: the planar mesh is consistently oriented)
  bool reversedOnInput(const optimizableMesh &m, const surfaceMesh &input,
                       const closestTriangleSearch &onInput)
  {
    const std::size_t step = m.triangles.size() / 101 + 1;
    std::size_t against = 0, tested = 0;
    for(std::size_t i = 0; i < m.triangles.size(); i += step, tested++) {
      const std::array<int, 3> &t = m.triangles[i];
      against += triangleAgainstInput(m.points[t[0]], m.points[t[1]],
                                      m.points[t[2]], input, onInput);
    }
    return 2 * against > tested;
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

bool reparamOptimizeMeshedFace(GFace *gf)
{
  const parametrizationRecord *map = findParametrization(gf);
  if(!getReparamOptions().optimize || !map || map->map <= 0 ||
     gf->geomType() != GEntity::DiscreteSurface || gf->triangles.empty() ||
     !gf->quadrangles.empty() || gf->stl_triangles.empty() ||
     gf->stl_vertices_uv.size() != gf->stl_vertices_xyz.size() ||
     findOptimization(gf))
    return false;
  const double t0 = TimeOfDay();
  std::vector<MVertex *> nodes;
  optimizableMesh m = meshOfFace(gf, nodes);
  const surfaceMesh input = inputTriangulationOf(gf);
  const closestTriangleSearch onInput(input.points, input.triangles);
  meshOptimizationOptions o;
  o.reversed = reversedOnInput(m, input, onInput);
  // 2: coarsen too where the curves' short segments made the mesh finer
  // than asked (fewer triangles, edges closer to the size; slower)
  o.collapseBelow = getReparamOptions().optimize >= 2 ? 0.6 : 0.;
  const meshOptimizationResult r = optimizeOnInput(m, input, onInput, o);
  if(r.flips || r.moves || r.inserted || r.splits || r.collapses)
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
            "input; %lu input nodes the mesh cut off inserted, %lu long "
            "edges split, %lu short ones collapsed, %lu flips and %lu node "
            "moves in %lu passes (%g s)",
            gf->tag(), r.minBefore, r.minAfter, r.belowBefore, r.belowAfter,
            o.target, r.againstBefore, r.againstAfter, r.inserted, r.splits,
            r.collapses, r.flips, r.moves, r.passes,
            TimeOfDay() - t0);
  return true;
}
