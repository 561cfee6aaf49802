// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "quadConnectivity.h"
#include "surfaceMesh.h"

namespace reparam {

void quadConnectivity::build(const surfaceMesh &m,
                             const std::vector<bool> *removed)
{
  neighbours.assign(m.points.size(), std::set<int>());
  quadsAt.assign(m.points.size(), std::set<int>());
  onTriangle.assign(m.points.size(), false);
  for(const std::array<int, 3> &t : m.triangles)
    for(int k = 0; k < 3; k++) {
      onTriangle[t[k]] = true;
      neighbours[t[k]].insert(t[(k + 1) % 3]);
      neighbours[t[(k + 1) % 3]].insert(t[k]);
    }
  for(std::size_t i = 0; i < m.quadrangles.size(); i++) {
    if(removed && (*removed)[i]) continue;
    const std::array<int, 4> &q = m.quadrangles[i];
    for(int k = 0; k < 4; k++) {
      quadsAt[q[k]].insert((int)i);
      neighbours[q[k]].insert(q[(k + 1) % 4]);
      neighbours[q[(k + 1) % 4]].insert(q[k]);
    }
  }
}
} // namespace reparam

