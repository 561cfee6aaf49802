// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <map>
#include "GFace.h"
#include "MQuadrangle.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "reparamFaceEdits.h"
#include "surfaceMesh.h"

namespace reparam {

std::string reparamTagList(const std::vector<GFace *> &faces)
{
  std::string list;
  for(GFace *gf : faces)
    list += (list.empty() ? "" : ", ") + std::to_string(gf->tag());
  return list;
}

surfaceMesh reparamMeshOfFaces(const std::vector<GFace *> &faces,
                               std::vector<MVertex *> &nodes)
{
  surfaceMesh m;
  std::map<MVertex *, int> index;
  auto indexOf = [&](MVertex *v) {
    auto it = index.emplace(v, (int)nodes.size()).first;
    if(it->second == (int)nodes.size()) {
      nodes.push_back(v);
      m.points.push_back(v->point());
    }
    return it->second;
  };
  for(GFace *gf : faces)
    for(MTriangle *t : gf->triangles)
      m.triangles.push_back(
        {{indexOf(t->getVertex(0)), indexOf(t->getVertex(1)),
          indexOf(t->getVertex(2))}});
  for(GFace *gf : faces)
    for(MQuadrangle *q : gf->quadrangles)
      m.quadrangles.push_back(
        {{indexOf(q->getVertex(0)), indexOf(q->getVertex(1)),
          indexOf(q->getVertex(2)), indexOf(q->getVertex(3))}});
  return m;
}
} // namespace reparam

