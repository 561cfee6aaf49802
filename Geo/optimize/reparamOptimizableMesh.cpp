// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <unordered_map>
#include "BackgroundMeshTools.h"
#include "GEdge.h"
#include "GFace.h"
#include "MLine.h"
#include "MElement.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "closestTriangle.h"
#include "meshFidelity.h"
#include "reparamInputMesh.h"
#include "reparamCurvatureMetric.h"
#include "reparamOptimizableMesh.h"
#include "reparamReport.h"

namespace reparam {

namespace {

  void lockLines(const GEdge *ge,
                 const std::unordered_map<MVertex *, int> &index,
                 optimizableMesh &m)
  {
    for(MLine *l : ge->lines) {
      auto a = index.find(l->getVertex(0)), b = index.find(l->getVertex(1));
      if(a == index.end() || b == index.end()) continue;
      m.lockedEdges.insert(std::make_pair(std::min(a->second, b->second),
                                          std::max(a->second, b->second)));
    }
  }

} // namespace

optimizableMesh
optimizableMeshOf(const std::vector<GFace *> &faces,
                  const std::vector<bool> &reverse,
                  const std::function<bool(const MVertex *)> &movable,
                  const std::vector<GEdge *> &lockedCurves,
                  std::vector<MVertex *> &nodes, std::vector<int> &triangleFace)
{
  optimizableMesh m;
  std::unordered_map<MVertex *, int> index;
  auto indexOf = [&](MVertex *v, GFace *gf) {
    auto it = index.find(v);
    if(it != index.end()) return it->second;
    const int i = (int)nodes.size();
    index[v] = i;
    nodes.push_back(v);
    m.points.push_back(v->point());
    m.movable.push_back(movable(v));
    // the size asked (Mesh.MeshSize*, fields) where it is, on the face of
    // the first triangle it is a corner of
    SPoint2 uv;
    reparamMeshVertexOnFace(v, gf, uv);
    m.size.push_back(BGM_MeshSize(gf, uv.x(), uv.y(), v->x(), v->y(), v->z()));
    return i;
  };
  triangleFace.clear();
  for(std::size_t f = 0; f < faces.size(); f++)
    for(MTriangle *t : faces[f]->triangles) {
      std::array<int, 3> c;
      for(int k = 0; k < 3; k++) c[k] = indexOf(t->getVertex(k), faces[f]);
      if(f < reverse.size() && reverse[f]) std::swap(c[1], c[2]);
      m.triangles.push_back(c);
      triangleFace.push_back((int)f);
    }
  // curves inside a face (creases kept), and those asked: their edges stay
  for(GFace *gf : faces)
    for(GEdge *ge : gf->embeddedEdges()) lockLines(ge, index, m);
  for(GEdge *ge : lockedCurves) lockLines(ge, index, m);
  return m;
}

bool reparamOptimizableFace(const GFace *gf)
{
  const parametrizationRecord *map = findParametrization(gf);
  return map && map->map > 0 && gf->geomType() == GEntity::DiscreteSurface &&
         !gf->triangles.empty() && gf->quadrangles.empty() &&
         !gf->stl_triangles.empty() && !keptAsInput(gf) &&
         !reparamAnisotropicFace(gf);
}

bool meshReversedOnInput(const GFace *gf, const surfaceMesh &input,
                         const closestTriangleSearch &onInput)
{
  // a quadrangle by its first three corners
  const std::size_t elements = gf->getNumMeshElements();
  const std::size_t step = elements / 101 + 1;
  std::size_t against = 0, tested = 0;
  for(std::size_t i = 0; i < elements; i += step, tested++) {
    MElement *e = gf->getMeshElement(i);
    against +=
      triangleAgainstInput(e->getVertex(0)->point(), e->getVertex(1)->point(),
                           e->getVertex(2)->point(), input, onInput);
  }
  return 2 * against > tested;
}
} // namespace reparam

