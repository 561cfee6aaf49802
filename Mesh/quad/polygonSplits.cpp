// Reparam - optimal discrete parametrizations for Gmsh compound surfaces

#include "polygonSplits.h"

namespace reparam {

namespace {

  // The corners of p from i to j, both included (i <= j)
  std::vector<int> part(const std::vector<int> &p, std::size_t i, std::size_t j)
  {
    return std::vector<int>(p.begin() + i, p.begin() + j + 1);
  }

  // Every combination of one split of each sub-polygon (those of two
  // corners, a side, have none and take one empty split)
  std::vector<polygonSplit>
  combine(const std::vector<std::vector<int> > &pieces,
          const polygonSplit &element)
  {
    std::vector<polygonSplit> all(1, element);
    for(const std::vector<int> &piece : pieces) {
      if(piece.size() < 3) continue;
      std::vector<polygonSplit> next;
      for(const polygonSplit &a : all)
        for(const polygonSplit &b : polygonSplits(piece)) {
          polygonSplit c = a;
          c.triangles.insert(c.triangles.end(), b.triangles.begin(),
                             b.triangles.end());
          c.quadrangles.insert(c.quadrangles.end(), b.quadrangles.begin(),
                               b.quadrangles.end());
          next.push_back(c);
        }
      all.swap(next);
    }
    return all;
  }

} // namespace

std::vector<polygonSplit> polygonSplits(const std::vector<int> &p)
{
  const std::size_t n = p.size();
  std::vector<polygonSplit> splits;
  if(n < 3 || n > 8) return splits;
  // the element on side (p[0], p[1]): a triangle (0, 1, k) or a
  // quadrangle (0, 1, j, k), the rest of the polygon on its other sides
  for(std::size_t k = 2; k < n; k++) {
    polygonSplit t;
    t.triangles.push_back({{p[0], p[1], p[k]}});
    std::vector<int> last = part(p, k, n - 1);
    last.push_back(p[0]);
    for(const polygonSplit &s : combine({part(p, 1, k), last}, t))
      splits.push_back(s);
    for(std::size_t j = 2; j < k; j++) {
      polygonSplit q;
      q.quadrangles.push_back({{p[0], p[1], p[j], p[k]}});
      for(const polygonSplit &s :
          combine({part(p, 1, j), part(p, j, k), last}, q))
        splits.push_back(s);
    }
  }
  return splits;
}
} // namespace reparam

