// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <array>
#include <cmath>
#include "GFace.h"
#include "GModel.h"
#include "GmshMessage.h"
#include "MVertex.h"
#include "conePoints.h"
#include "discreteVertex.h"
#include "reparamConePoints.h"

int reparamEmbedConePoints(GFace *gf, const std::vector<MVertex *> &nodes,
                           const std::vector<SPoint3> &points,
                           const std::vector<int> &triangleNodes)
{
  std::vector<std::array<int, 3> > triangles(triangleNodes.size() / 3);
  for(std::size_t t = 0; t < triangles.size(); t++)
    for(int j = 0; j < 3; j++) triangles[t][j] = triangleNodes[3 * t + j];
  // Sharper than a cone of half-angle 30 degrees (angles summing to pi):
  // a bump of a smooth surface sums to nearly 2 pi, a cube's corner (on
  // curves anyway) to 3 pi / 2
  const std::vector<int> tips = conePoints(points, triangles, M_PI);
  GModel *m = gf->model();
  int added = 0;
  for(int i : tips) {
    const SPoint3 &p = points[i];
    GEntity *on = i < (int)nodes.size() ? nodes[i]->onWhat() : nullptr;
    if(on && on->dim() < 2) continue; // on a curve or a point already
    bool there = false; // CreateGeometry run again
    for(GVertex *v : gf->embeddedVertices())
      there = there || (v->x() == p.x() && v->y() == p.y() && v->z() == p.z());
    if(there) continue;
    discreteVertex *v = new discreteVertex(
      m, m->getMaxElementaryNumber(0) + 1, p.x(), p.y(), p.z());
    m->add(v);
    gf->addEmbeddedVertex(v);
    added++;
  }
  if(added)
    Msg::Info("Reparam: surface %d: %d tip%s kept as mesh node%s (point%s "
              "embedded in it)",
              gf->tag(), added, added > 1 ? "s" : "", added > 1 ? "s" : "",
              added > 1 ? "s" : "");
  return added;
}
