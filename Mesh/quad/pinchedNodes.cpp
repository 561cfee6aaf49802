// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <set>
#include "pinchedNodes.h"
#include "surfaceMesh.h"

namespace reparam {

namespace {

  // Element e's corners (3 or 4)
  std::vector<int> cornersOf(const surfaceMesh &m, int e)
  {
    const int t = (int)m.triangles.size();
    if(e < t) return {m.triangles[e].begin(), m.triangles[e].end()};
    const std::array<int, 4> &q = m.quadrangles[e - t];
    return {q.begin(), q.end()};
  }

  // The corners before and after v in the element's order, or false
  bool neighboursIn(const std::vector<int> &c, int v, int &before, int &after)
  {
    const int n = (int)c.size();
    for(int k = 0; k < n; k++)
      if(c[k] == v) {
        before = c[(k + n - 1) % n];
        after = c[(k + 1) % n];
        return true;
      }
    return false;
  }

} // namespace

std::vector<pinchedNode> pinchedNodes(const surfaceMesh &m,
                                      const std::vector<bool> &removable)
{
  std::vector<std::vector<int> > elementsAt(m.points.size());
  for(int e = 0; e < (int)m.numElements(); e++)
    for(int v : cornersOf(m, e)) elementsAt[v].push_back(e);
  std::vector<pinchedNode> pinched;
  std::set<int> taken;
  for(int v = 0; v < (int)m.points.size(); v++) {
    if(!removable[v] || elementsAt[v].size() != 2) continue;
    const int e0 = elementsAt[v][0], e1 = elementsAt[v][1];
    if(taken.count(e0) || taken.count(e1)) continue;
    const std::vector<int> c0 = cornersOf(m, e0), c1 = cornersOf(m, e1);
    int a0, b0, a1, b1;
    if(!neighboursIn(c0, v, a0, b0) || !neighboursIn(c1, v, a1, b1) ||
       std::set<int>({a0, b0}) != std::set<int>({a1, b1}) || a0 == b0)
      continue;
    pinchedNode p;
    p.node = v;
    p.elements = {{e0, e1}};
    for(int k = 0; k < 2; k++) {
      const std::vector<int> &c = k ? c1 : c0;
      if(c.size() != 4) continue;
      int at = 0;
      while(c[at] != v) at++;
      p.triangles.push_back(
        {{c[(at + 1) % 4], c[(at + 2) % 4], c[(at + 3) % 4]}});
      p.from.push_back(k);
    }
    taken.insert(e0);
    taken.insert(e1);
    pinched.push_back(p);
  }
  return pinched;
}
} // namespace reparam

