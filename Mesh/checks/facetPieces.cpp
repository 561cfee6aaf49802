// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include <algorithm>
#include <cstdint>
#include <utility>
#include "facetPieces.h"
#include "unionFind.h"

namespace reparam {

std::vector<int> facetPieceRoots(const std::vector<std::array<int, 3> > &facets,
                                 const std::vector<bool> *skip,
                                 std::vector<char> *closed)
{
  // edges as sorted keys, not a map: inputs of millions of facets
  std::vector<std::pair<std::uint64_t, int> > edges;
  edges.reserve(3 * facets.size());
  for(std::size_t i = 0; i < facets.size(); i++) {
    const std::array<int, 3> &f = facets[i];
    if(f[0] == f[1] || f[1] == f[2] || f[2] == f[0]) continue;
    if(skip && (*skip)[i]) continue;
    for(int k = 0; k < 3; k++) {
      const std::uint64_t a = (std::uint32_t)f[k],
                          b = (std::uint32_t)f[(k + 1) % 3];
      edges.push_back({std::min(a, b) << 32 | std::max(a, b), (int)i});
    }
  }
  std::sort(edges.begin(), edges.end());
  unionFind pieces(facets.size());
  for(std::size_t i = 1; i < edges.size(); i++)
    if(edges[i].first == edges[i - 1].first)
      pieces.join(edges[i].second, edges[i - 1].second);
  std::vector<int> root(facets.size());
  for(std::size_t i = 0; i < facets.size(); i++) root[i] = pieces.find((int)i);
  if(closed) {
    closed->assign(facets.size(), 1);
    for(std::size_t i = 0; i < edges.size();) {
      std::size_t j = i;
      while(j < edges.size() && edges[j].first == edges[i].first) j++;
      if(j - i != 2) (*closed)[root[edges[i].second]] = 0;
      i = j;
    }
  }
  return root;
}

} // namespace reparam
