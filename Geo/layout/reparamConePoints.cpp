// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <array>
#include <cmath>
#include <set>
#include "GFace.h"
#include "GModel.h"
#include "GmshMessage.h"
#include "MVertex.h"
#include "conePoints.h"
#include "creaseChains.h"
#include "edgeByCoordinates.h"
#include "discreteVertex.h"
#include "reparamConePoints.h"
#include "reparamState.h"

namespace reparam {

void reparamRecordMergedCreases(const std::vector<std::array<SPoint3, 2> > &edges,
                                double size)
{
  std::set<edgeByCoordinates> &mergedCreases = lastLayout().mergedCreases;
  mergedCreases.clear();
  for(const auto &e : edges) mergedCreases.insert(byCoordinates(e[0], e[1]));
  lastLayout().noiseSize = size;
}

bool reparamIsMergedCrease(const SPoint3 &a, const SPoint3 &b)
{
  return lastLayout().mergedCreases.count(byCoordinates(a, b)) > 0;
}

double reparamLayoutNoiseSize() { return lastLayout().noiseSize; }

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
  std::vector<int> tips = conePoints(points, triangles, M_PI);
  const std::set<edgeByCoordinates> &mergedCreases = lastLayout().mergedCreases;
  const double layoutSize = lastLayout().noiseSize;
  std::vector<int> corners;
  if(!mergedCreases.empty())
    corners = creaseCorners(points, triangles, [&](int a, int b) {
      return mergedCreases.count(byCoordinates(points[a], points[b])) > 0;
    });
  tips.insert(tips.end(), corners.begin(), corners.end());
  // a node closer than half the layout's size to gf's curves or to another
  // kept one would only make small triangles: the mesh passes near it
  std::vector<SPoint3> taken;
  for(std::size_t i = 0; i < points.size() && i < nodes.size(); i++) {
    GEntity *on = nodes[i]->onWhat();
    if(on && on->dim() < 2) taken.push_back(points[i]);
  }
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
    bool near = false;
    for(const SPoint3 &q : taken) near = near || p.distance(q) < 0.5 * layoutSize;
    if(near) continue;
    taken.push_back(p);
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
} // namespace reparam

