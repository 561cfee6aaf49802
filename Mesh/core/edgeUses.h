// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// How many triangles use each undirected edge of a triangulation: 1 on its
// boundary, 2 inside, more where it is not manifold. Kept in a std::map, so
// that the edges are visited in the same order (smaller node, then larger)
// every run and sums over them are bit-identical.

#ifndef EDGE_USES_H
#define EDGE_USES_H

#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>

namespace reparam {

// The undirected edge (a, b) as (smaller node, larger node)
inline std::pair<int, int> undirectedEdge(int a, int b)
{
  return std::make_pair(std::min(a, b), std::max(a, b));
}

class edgeUses {
public:
  typedef std::map<std::pair<int, int>, int> counts;

  void add(int a, int b) { _uses[undirectedEdge(a, b)]++; }
  // its edges (a, b), (b, c), (c, a)
  void addTriangle(int a, int b, int c)
  {
    add(a, b);
    add(b, c);
    add(c, a);
  }
  // 0 for an edge of no triangle
  int of(int a, int b) const
  {
    auto it = _uses.find(undirectedEdge(a, b));
    return it == _uses.end() ? 0 : it->second;
  }
  std::size_t size() const { return _uses.size(); }
  // ((smaller, larger), uses), ordered by the smaller node, then the larger
  counts::const_iterator begin() const { return _uses.begin(); }
  counts::const_iterator end() const { return _uses.end(); }

private:
  counts _uses;
};

inline edgeUses edgeUsesOf(const std::vector<std::array<int, 3> > &triangles)
{
  edgeUses uses;
  for(const std::array<int, 3> &t : triangles)
    uses.addTriangle(t[0], t[1], t[2]);
  return uses;
}

// Of triangles given as three nodes each, one after the other
inline edgeUses edgeUsesOf(const std::vector<int> &triangleNodes)
{
  edgeUses uses;
  for(std::size_t i = 0; i + 2 < triangleNodes.size(); i += 3)
    uses.addTriangle(triangleNodes[i], triangleNodes[i + 1],
                     triangleNodes[i + 2]);
  return uses;
}

// The edges of exactly one of the triangles (three nodes each, one after the
// other), in the order edgeUses visits them: what edgeUsesOf(...) finds with
// one use, by a sort of a flat array rather than a tree of nodes (the
// layout asks it of every part, of up to a million triangles)
inline std::vector<std::pair<int, int> >
edgesUsedOnce(const std::vector<int> &triangleNodes)
{
  std::vector<std::pair<int, int> > all;
  all.reserve(triangleNodes.size());
  for(std::size_t i = 0; i + 2 < triangleNodes.size(); i += 3)
    for(int k = 0; k < 3; k++)
      all.push_back(
        undirectedEdge(triangleNodes[i + k], triangleNodes[i + (k + 1) % 3]));
  std::sort(all.begin(), all.end());
  std::vector<std::pair<int, int> > once;
  for(std::size_t i = 0; i < all.size();) {
    std::size_t j = i + 1;
    while(j < all.size() && all[j] == all[i]) j++;
    if(j == i + 1) once.push_back(all[i]);
    i = j;
  }
  return once;
}

} // namespace reparam

#endif
