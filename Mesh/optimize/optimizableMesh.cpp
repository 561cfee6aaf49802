// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include "optimizableMesh.h"
#include "triangleQuality.h"

namespace reparam {

std::vector<int> removeDeadParts(optimizableMesh &m,
                                 const std::vector<bool> &deadPoint,
                                 const std::vector<bool> &deadTriangle)
{
  std::vector<int> newIndex(m.points.size(), -1);
  std::size_t n = 0;
  for(std::size_t i = 0; i < m.points.size(); i++) {
    if(deadPoint[i]) continue;
    newIndex[i] = (int)n;
    m.points[n] = m.points[i];
    m.movable[n] = m.movable[i];
    m.landing[n] = m.landing[i];
    m.inputNode[n] = m.inputNode[i];
    m.size[n] = m.size[i];
    m.origin[n] = m.origin[i];
    n++;
  }
  for(auto *v : {&m.landing, &m.inputNode, &m.origin}) v->resize(n);
  m.points.resize(n);
  m.movable.resize(n);
  m.size.resize(n);
  std::set<std::pair<int, int> > locked;
  for(const auto &e : m.lockedEdges)
    if(newIndex[e.first] >= 0 && newIndex[e.second] >= 0)
      locked.insert(std::make_pair(newIndex[e.first], newIndex[e.second]));
  m.lockedEdges = locked;
  std::size_t k = 0;
  const bool against = m.against.size() == m.triangles.size();
  for(std::size_t t = 0; t < m.triangles.size(); t++) {
    if(deadTriangle[t]) continue;
    for(int &v : m.triangles[t]) v = newIndex[v];
    m.triangles[k] = m.triangles[t];
    m.triangleOrigin[k] = m.triangleOrigin[t];
    if(against) m.against[k] = m.against[t];
    k++;
  }
  m.triangles.resize(k);
  m.triangleOrigin.resize(k);
  if(against) m.against.resize(k);
  return newIndex;
}

double worstKappa(const optimizableMesh &m)
{
  double worst = 1.;
  for(const std::array<int, 3> &t : m.triangles)
    worst = std::min(
      worst, triangleKappa(m.points[t[0]], m.points[t[1]], m.points[t[2]]));
  return worst;
}

} // namespace reparam
