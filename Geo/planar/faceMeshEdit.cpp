// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "GFace.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "faceMeshEdit.h"

namespace reparam {

SPoint2 meshNodeUv(GFace *gf, MVertex *v)
{
  SPoint2 uv;
  reparamMeshVertexOnFace(v, gf, uv);
  return uv;
}

std::map<meshEdgeKey, std::vector<MTriangle *> > faceEdgeTriangles(GFace *gf)
{
  std::map<meshEdgeKey, std::vector<MTriangle *> > edges;
  for(MTriangle *t : gf->triangles)
    for(int k = 0; k < 3; k++)
      edges[meshEdge(t->getVertex(k), t->getVertex((k + 1) % 3))].push_back(t);
  return edges;
}

MFaceVertex *newFaceNode(GFace *gf, double u, double v)
{
  GPoint p = gf->point(u, v);
  if(!p.succeeded()) return nullptr;
  return new MFaceVertex(p.x(), p.y(), p.z(), gf, u, v);
}

void splitTriangleAt(MTriangle *t, MVertex *a, MVertex *b, MVertex *m,
                     std::vector<MTriangle *> &halves)
{
  MVertex *c = nullptr;
  int ia = -1;
  for(int k = 0; k < 3; k++) {
    if(t->getVertex(k) == a) ia = k;
    if(t->getVertex(k) != a && t->getVertex(k) != b) c = t->getVertex(k);
  }
  // t's turn is a, b, c or a, c, b
  if(t->getVertex((ia + 1) % 3) == b) {
    halves.push_back(new MTriangle(a, m, c));
    halves.push_back(new MTriangle(m, b, c));
  }
  else {
    halves.push_back(new MTriangle(a, c, m));
    halves.push_back(new MTriangle(m, c, b));
  }
}

void replaceTriangles(GFace *gf, const std::set<MTriangle *> &removed,
                      const std::vector<MTriangle *> &added)
{
  std::vector<MTriangle *> kept;
  kept.reserve(gf->triangles.size() + added.size());
  for(MTriangle *t : gf->triangles) {
    if(removed.count(t))
      delete t;
    else
      kept.push_back(t);
  }
  kept.insert(kept.end(), added.begin(), added.end());
  gf->triangles = kept;
}
} // namespace reparam

