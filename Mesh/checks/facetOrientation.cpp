// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cstdint>
#include "facetOrientation.h"
#include "facetPieces.h"

namespace reparam {

namespace {

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

  // Per facet, the first facet with the same nodes (itself when no other
  // comes before it with them; -1 when degenerate)
  std::vector<int>
  firstWithSameNodes(const std::vector<std::array<int, 3> > &facets)
  {
    std::vector<std::pair<std::array<int, 3>, int> > sorted;
    sorted.reserve(facets.size());
    for(std::size_t i = 0; i < facets.size(); i++) {
      if(degenerate(facets[i])) continue;
      std::array<int, 3> key = facets[i];
      std::sort(key.begin(), key.end());
      sorted.push_back({key, (int)i});
    }
    std::sort(sorted.begin(), sorted.end());
    std::vector<int> first(facets.size(), -1);
    for(std::size_t i = 0; i < sorted.size(); i++)
      first[sorted[i].second] = i && sorted[i].first == sorted[i - 1].first ?
                                  first[sorted[i - 1].second] :
                                  sorted[i].second;
    return first;
  }

  // The second of a set of facets with the same nodes is dropped, and a
  // piece made of such sets only (a pillow: no volume, every edge used
  // twice by the same nodes) whole: with one facet of each set kept it
  // would be left open
  void dropDuplicates(const std::vector<std::array<int, 3> > &facets,
                      facetRepair &r)
  {
    const std::vector<int> first = firstWithSameNodes(facets);
    std::vector<int> repeats(facets.size(), 0);
    for(std::size_t i = 0; i < facets.size(); i++)
      if(first[i] >= 0) repeats[first[i]]++;
    const std::vector<int> root = facetPieceRoots(facets);
    std::vector<char> onlyRepeated(facets.size(), 1);
    for(std::size_t i = 0; i < facets.size(); i++)
      if(first[i] >= 0 && repeats[first[i]] < 2) onlyRepeated[root[i]] = 0;
    for(std::size_t i = 0; i < facets.size(); i++) {
      if(first[i] < 0) continue;
      const bool pillow = onlyRepeated[root[i]];
      if(!pillow && first[i] == (int)i) continue;
      r.drop[i] = true;
      r.dropped++;
      if(pillow && root[i] == (int)i) r.droppedPieces.push_back((int)i);
    }
  }

  // Per kept facet and edge k (corners k, k + 1): the other facet of that
  // edge when exactly two kept facets use it, else -1
  std::vector<std::array<int, 3> >
  neighbours(const std::vector<std::array<int, 3> > &facets,
             const facetRepair &r)
  {
    std::vector<std::pair<std::uint64_t, int> > edges; // (edge, 3 facet + k)
    edges.reserve(3 * facets.size());
    for(std::size_t i = 0; i < facets.size(); i++) {
      if(r.drop[i] || degenerate(facets[i])) continue;
      for(int k = 0; k < 3; k++) {
        const std::uint64_t a = (std::uint32_t)facets[i][k],
                            b = (std::uint32_t)facets[i][(k + 1) % 3];
        edges.push_back(
          {std::min(a, b) << 32 | std::max(a, b), (int)(3 * i + k)});
      }
    }
    std::sort(edges.begin(), edges.end());
    std::vector<std::array<int, 3> > next(facets.size(), {{-1, -1, -1}});
    for(std::size_t i = 0; i < edges.size();) {
      std::size_t j = i;
      while(j < edges.size() && edges[j].first == edges[i].first) j++;
      if(j - i == 2) {
        const int s = edges[i].second, t = edges[i + 1].second;
        next[s / 3][s % 3] = t / 3;
        next[t / 3][t % 3] = s / 3;
      }
      i = j;
    }
    return next;
  }

} // namespace

facetRepair orientFacets(const std::vector<std::array<int, 3> > &facets)
{
  facetRepair r;
  r.reverse.assign(facets.size(), false);
  r.drop.assign(facets.size(), false);
  dropDuplicates(facets, r);
  const std::vector<std::array<int, 3> > next = neighbours(facets, r);
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
        const int g = next[f][k];
        if(g < 0 || seen[g]) continue;
        int a = facets[f][k], b = facets[f][(k + 1) % 3];
        if(flip[f]) std::swap(a, b); // as f will run once turned
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
} // namespace reparam
