// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// Disjoint sets of the items 0 .. n - 1, joined pair by pair: the connected
// components of triangles through their edges, of faces through their
// curves. Path halving, no ranks: join(a, b) hangs a's root under b's, so
// each set's root (which callers may number or order sets by) depends only
// on the joins made, in their order.

#ifndef UNION_FIND_H
#define UNION_FIND_H

#include <numeric>
#include <vector>

namespace reparam {

class unionFind {
public:
  explicit unionFind(std::size_t n) : _parent(n)
  {
    std::iota(_parent.begin(), _parent.end(), 0);
  }
  // The root of i's set
  int find(int i)
  {
    while(_parent[i] != i) i = _parent[i] = _parent[_parent[i]];
    return i;
  }
  // One set of a's and b's, rooted at b's root
  void join(int a, int b)
  {
    const int rootOfB = find(b);
    _parent[find(a)] = rootOfB;
  }
  std::size_t size() const { return _parent.size(); }

private:
  std::vector<int> _parent;
};

} // namespace reparam

#endif
