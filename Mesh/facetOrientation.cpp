// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <map>
#include <set>
#include "facetOrientation.h"

namespace {

  typedef std::pair<int, int> edgeKey;

  edgeKey keyOf(int a, int b) { return a < b ? edgeKey(a, b) : edgeKey(b, a); }

  bool degenerate(const std::array<int, 3> &f)
  {
    return f[0] == f[1] || f[1] == f[2] || f[2] == f[0];
  }

  // Whether f uses the edge from a to b in that direction
  bool runs(const std::array<int, 3> &f, int a, int b)
  {
    for(int k = 0; k < 3; k++)
      if(f[k] == a && f[(k + 1) % 3] == b) return true;
    return false;
  }

  // The second of a set of facets with the same nodes is dropped
  void dropDuplicates(const std::vector<std::array<int, 3> > &facets,
                      facetRepair &r)
  {
    std::set<std::array<int, 3> > seen;
    for(std::size_t i = 0; i < facets.size(); i++) {
      std::array<int, 3> sorted = facets[i];
      std::sort(sorted.begin(), sorted.end());
      if(degenerate(facets[i]) || seen.insert(sorted).second) continue;
      r.drop[i] = true;
      r.dropped++;
    }
  }

} // namespace

facetRepair orientFacets(const std::vector<std::array<int, 3> > &facets)
{
  facetRepair r;
  r.reverse.assign(facets.size(), false);
  r.drop.assign(facets.size(), false);
  dropDuplicates(facets, r);
  std::map<edgeKey, std::vector<int> > around;
  for(std::size_t i = 0; i < facets.size(); i++) {
    if(r.drop[i] || degenerate(facets[i])) continue;
    for(int k = 0; k < 3; k++)
      around[keyOf(facets[i][k], facets[i][(k + 1) % 3])].push_back((int)i);
  }
  std::vector<bool> seen(facets.size(), false);
  std::vector<int> flip(facets.size(), 0);
  for(std::size_t start = 0; start < facets.size(); start++) {
    if(seen[start] || r.drop[start] || degenerate(facets[start])) continue;
    // one connected piece, each facet's turn relative to the first
    std::vector<int> piece = {(int)start};
    seen[start] = true;
    for(std::size_t n = 0; n < piece.size(); n++) {
      const int f = piece[n];
      for(int k = 0; k < 3; k++) {
        int a = facets[f][k], b = facets[f][(k + 1) % 3];
        if(flip[f]) std::swap(a, b); // as f will run once turned
        const std::vector<int> &on = around[keyOf(a, b)];
        if(on.size() != 2) continue; // a border or non-manifold edge
        const int g = on[0] == f ? on[1] : on[0];
        if(seen[g]) continue;
        seen[g] = true;
        flip[g] = runs(facets[g], a, b); // same direction: turn it
        piece.push_back(g);
      }
    }
    std::size_t turned = 0;
    for(int f : piece) turned += flip[f];
    const bool keepFirst = 2 * turned <= piece.size();
    for(int f : piece)
      if((flip[f] != 0) == keepFirst) {
        r.reverse[f] = true;
        r.reversed++;
      }
  }
  return r;
}
