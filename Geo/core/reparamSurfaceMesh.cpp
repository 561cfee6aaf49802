// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <unordered_map>
#include "GFace.h"
#include "MQuadrangle.h"
#include "MTriangle.h"
#include "reparamSurfaceMesh.h"

namespace reparam {

namespace {

  template <int N, class Element>
  void addElements(const std::vector<Element *> &elements,
                   std::unordered_map<const MVertex *, int> &index,
                   surfaceMesh &mesh, std::vector<std::array<int, N> > &out)
  {
    for(Element *e : elements) {
      std::array<int, N> nodes;
      for(int j = 0; j < N; j++) {
        const MVertex *v = e->getVertex(j);
        auto it = index.insert(std::make_pair(v, (int)mesh.points.size()));
        if(it.second) mesh.points.push_back(v->point());
        nodes[j] = it.first->second;
      }
      out.push_back(nodes);
    }
  }

} // namespace

surfaceMesh surfaceMeshOf(const GFace *gf)
{
  surfaceMesh m;
  std::unordered_map<const MVertex *, int> index;
  GFace *f = const_cast<GFace *>(gf);
  addElements<3>(f->triangles, index, m, m.triangles);
  addElements<4>(f->quadrangles, index, m, m.quadrangles);
  return m;
}

surfaceMesh inputTriangulationOf(const GFace *gf)
{
  surfaceMesh m;
  m.points = gf->stl_vertices_xyz;
  const std::vector<int> &t = gf->stl_triangles;
  m.triangles.resize(t.size() / 3);
  for(std::size_t i = 0; i < m.triangles.size(); i++)
    m.triangles[i] = {{t[3 * i], t[3 * i + 1], t[3 * i + 2]}};
  return m;
}

} // namespace reparam
