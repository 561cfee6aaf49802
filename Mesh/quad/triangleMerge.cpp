// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <map>
#include "quadQuality.h"
#include "surfaceMesh.h"
#include "triangleMerge.h"

namespace reparam {

std::vector<triangleMerge>
triangleMerges(const surfaceMesh &m,
               const std::set<std::pair<int, int> > &locked, double minEta)
{
  // per edge (i < j), the triangles on it and the corner its side starts at
  std::map<std::pair<int, int>, std::vector<std::pair<int, int> > > sides;
  for(std::size_t t = 0; t < m.triangles.size(); t++)
    for(int k = 0; k < 3; k++) {
      const int a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      sides[std::make_pair(std::min(a, b), std::max(a, b))].push_back(
        std::make_pair((int)t, k));
    }
  std::vector<triangleMerge> candidates;
  for(const auto &s : sides) {
    if(s.second.size() != 2 || locked.count(s.first)) continue;
    const int t1 = s.second[0].first, k1 = s.second[0].second;
    const int t2 = s.second[1].first, k2 = s.second[1].second;
    const std::array<int, 3> &c1 = m.triangles[t1], &c2 = m.triangles[t2];
    const int a = c1[k1], b = c1[(k1 + 1) % 3];
    // the second runs b -> a along the edge
    if(c2[k2] != b || c2[(k2 + 1) % 3] != a) continue;
    const int c = c1[(k1 + 2) % 3], d = c2[(k2 + 2) % 3];
    if(c == d) continue;
    // (a, b, c) and (b, a, d) make (a, d, b, c)
    const std::array<int, 4> q = {{a, d, b, c}};
    const double eta =
      quadEta(m.points[q[0]], m.points[q[1]], m.points[q[2]], m.points[q[3]]);
    if(eta >= minEta) candidates.push_back({t1, t2, q, eta});
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const triangleMerge &x, const triangleMerge &y) {
              return x.eta > y.eta;
            });
  std::vector<bool> used(m.triangles.size(), false);
  std::vector<triangleMerge> merges;
  for(const triangleMerge &c : candidates) {
    if(used[c.first] || used[c.second]) continue;
    used[c.first] = used[c.second] = true;
    merges.push_back(c);
  }
  return merges;
}
} // namespace reparam

