// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <map>
#include <set>
#include <utility>
#include "GEdge.h"
#include "GEntity.h"
#include "GFace.h"
#include "MLine.h"
#include "MTriangle.h"
#include "MVertex.h"
#include "reparamPoorTriangles.h"
#include "triangleQuality.h"

namespace reparam {

namespace {

  typedef std::pair<MVertex *, MVertex *> edgeKey;
  edgeKey key(MVertex *a, MVertex *b)
  {
    return a < b ? edgeKey(a, b) : edgeKey(b, a);
  }

  // The edges of gf on a curve: used by one of its triangles, or an edge of
  // an embedded curve
  std::set<edgeKey> curveEdges(GFace *gf)
  {
    std::map<edgeKey, int> uses;
    for(MTriangle *t : gf->triangles)
      for(int k = 0; k < 3; k++)
        uses[key(t->getVertex(k), t->getVertex((k + 1) % 3))]++;
    std::set<edgeKey> onCurve;
    for(const auto &e : uses)
      if(e.second == 1) onCurve.insert(e.first);
    for(GEdge *ge : gf->embeddedEdges())
      for(MLine *l : ge->lines)
        onCurve.insert(key(l->getVertex(0), l->getVertex(1)));
    return onCurve;
  }

} // namespace

poorTriangleCounts countPoorTriangleCauses(GFace *gf)
{
  poorTriangleCounts counts{};
  std::set<edgeKey> onCurve;
  bool edgesFound = false;
  for(MTriangle *t : gf->triangles) {
    triangleCorners c;
    for(int k = 0; k < 3; k++) c.x[k] = t->getVertex(k)->point();
    if(triangleKappa(c.x[0], c.x[1], c.x[2]) >= 0.3) continue;
    if(!edgesFound) { // only for faces with poor triangles
      onCurve = curveEdges(gf);
      edgesFound = true;
    }
    for(int k = 0; k < 3; k++) {
      GEntity *on = t->getVertex(k)->onWhat();
      c.dim[k] = on ? on->dim() : 2;
      c.edgeOnCurve[k] =
        onCurve.count(key(t->getVertex(k), t->getVertex((k + 1) % 3))) > 0;
    }
    counts[(int)poorTriangleCauseOf(c)]++;
  }
  return counts;
}
} // namespace reparam

