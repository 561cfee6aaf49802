// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

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

  // The (u, v) of point p on input triangle t of gf (barycentric
  // interpolation of its corners' (u, v): the map is linear on t)
  SPoint2 uvOnInputTriangle(GFace *gf, int t, const SPoint3 &p)
  {
    const int *c = &gf->stl_triangles[3 * t];
    const SPoint3 &a = gf->stl_vertices_xyz[c[0]],
                  &b = gf->stl_vertices_xyz[c[1]],
                  &d = gf->stl_vertices_xyz[c[2]];
    const SVector3 e1(a, b), e2(a, d), ep(a, p);
    const double g11 = dot(e1, e1), g12 = dot(e1, e2), g22 = dot(e2, e2);
    const double det = g11 * g22 - g12 * g12;
    double l1 = 0., l2 = 0.;
    if(det > 1e-14 * g11 * g22) {
      l1 = (g22 * dot(ep, e1) - g12 * dot(ep, e2)) / det;
      l2 = (g11 * dot(ep, e2) - g12 * dot(ep, e1)) / det;
    }
    const SPoint2 &ua = gf->stl_vertices_uv[c[0]],
                  &ub = gf->stl_vertices_uv[c[1]],
                  &ud = gf->stl_vertices_uv[c[2]];
    return ua + (ub - ua) * l1 + (ud - ua) * l2;
  }

  // Moved nodes get the (u, v) of the input point they lie on, new nodes
  // (input nodes inserted) their input node's
  void writeNodes(GFace *gf, const optimizableMesh &m,
                  std::vector<MVertex *> &nodes)
  {
    for(std::size_t i = 0; i < m.points.size(); i++) {
      const SPoint3 &p = m.points[i];
      if(i >= nodes.size()) {
        const SPoint2 uv = m.inputNode[i] >= 0 ?
                             gf->stl_vertices_uv[m.inputNode[i]] :
                             uvOnInputTriangle(gf, m.landing[i], p);
        MFaceVertex *v = new MFaceVertex(p.x(), p.y(), p.z(), gf, uv.x(),
                                         uv.y());
        gf->mesh_vertices.push_back(v);
        nodes.push_back(v);
        continue;
      }
      if(m.landing[i] < 0) continue;
      nodes[i]->setXYZ(p.x(), p.y(), p.z());
      const SPoint2 uv = uvOnInputTriangle(gf, m.landing[i], p);
      nodes[i]->setParameter(0, uv.x());
      nodes[i]->setParameter(1, uv.y());
    }
  }

  void writeBack(GFace *gf, const optimizableMesh &m,
                 std::vector<MVertex *> &nodes)
  {
    writeNodes(gf, m, nodes);
    for(std::size_t t = 0; t < m.triangles.size(); t++) {
      MVertex *c[3] = {nodes[m.triangles[t][0]], nodes[m.triangles[t][1]],
                       nodes[m.triangles[t][2]]};
      if(t >= gf->triangles.size()) {
        gf->triangles.push_back(new MTriangle(c[0], c[1], c[2]));
        continue;
      }
      for(int k = 0; k < 3; k++) gf->triangles[t]->setVertex(k, c[k]);
    }
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
  const meshOptimizationResult r = optimizeOnInput(m, input, onInput, o);
  if(r.flips || r.moves || r.inserted || r.splits) writeBack(gf, m, nodes);
  optimizationRecord done;
  done.done = true;
  done.kappaMinBefore = r.minBefore;
  done.seconds = TimeOfDay() - t0;
  done.inserted = r.inserted;
  done.splits = r.splits;
  done.flips = r.flips;
  done.moves = r.moves;
  done.againstBefore = r.againstBefore;
  done.againstAfter = r.againstAfter;
  done.reversed = o.reversed;
  done.elements = gf->getNumMeshElements();
  done.firstElement = gf->getMeshElement(0);
  recordOptimization(gf, done);
  if(!r.belowBefore && !r.againstBefore && !r.inserted && !r.splits)
    return true;
  Msg::Info("Reparam: surface %d: optimized on the input: kappa min %.3g -> "
            "%.3g, %lu -> %lu triangles below %g, %lu -> %lu against the "
            "input; %lu input nodes the mesh cut off inserted, %lu long "
            "edges split, %lu flips and %lu node moves in %lu passes (%g s)",
            gf->tag(), r.minBefore, r.minAfter, r.belowBefore, r.belowAfter,
            o.target, r.againstBefore, r.againstAfter, r.inserted, r.splits,
            r.flips, r.moves, r.passes,
            TimeOfDay() - t0);
  return true;
}
