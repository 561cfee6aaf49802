// Reparam - optimal discrete parametrizations for Gmsh compound surfaces
//
// A tree of axis-aligned boxes over items (triangles, in the (u, v) plane or
// in space), for the searches that must skip most of them: each box halved
// at the median of its items' centroids along the longest side of their
// box, `leafSize` items or fewer a leaf. Balanced, so that a search's stack
// holds at most two boxes per level.

#ifndef BOX_TREE_H
#define BOX_TREE_H

#include <algorithm>
#include <vector>

namespace reparam {

template <int D> struct boxTree {
  struct node {
    double lo[D], hi[D];
    int left = -1, right = -1; // children (inner nodes)
    int first = 0, count = 0; // items order[first, first + count) (leaves)
  };
  std::vector<node> nodes; // the root first
  std::vector<int> order; // the items, each leaf's together

  // items 0 .. n - 1; box(i, lo, hi) gives item i's box, centroid(i, k) the
  // k-th coordinate of its centroid (each asked once per item)
  template <class Box, class Centroid>
  void build(int n, int leafSize, const Box &box, const Centroid &centroid)
  {
    nodes.clear();
    order.resize(n);
    for(int i = 0; i < n; i++) order[i] = i;
    if(!n) return;
    // every level reads every item's box and centroid: computed once
    // (asked of the item at each level, they were most of the build)
    std::vector<double> boxes(2 * D * (std::size_t)n),
      centroids(D * (std::size_t)n);
    for(int i = 0; i < n; i++) {
      box(i, &boxes[2 * D * i], &boxes[2 * D * i + D]);
      for(int k = 0; k < D; k++) centroids[D * i + k] = centroid(i, k);
    }
    nodes.reserve(2 * n / leafSize + 2);
    split(0, n, leafSize, boxes, centroids);
  }

private:
  // boxes: each item's low corner then high corner; centroids: D each
  int split(int first, int count, int leafSize,
            const std::vector<double> &boxes,
            const std::vector<double> &centroids)
  {
    const int index = (int)nodes.size();
    nodes.push_back(node());
    double lo[D], hi[D], clo[D], chi[D];
    std::fill(lo, lo + D, 1e300);
    std::fill(clo, clo + D, 1e300);
    std::fill(hi, hi + D, -1e300);
    std::fill(chi, chi + D, -1e300);
    for(int i = first; i < first + count; i++) {
      const double *l = &boxes[2 * D * order[i]], *h = l + D;
      const double *c = &centroids[D * order[i]];
      for(int k = 0; k < D; k++) {
        lo[k] = std::min(lo[k], l[k]);
        hi[k] = std::max(hi[k], h[k]);
        clo[k] = std::min(clo[k], c[k]);
        chi[k] = std::max(chi[k], c[k]);
      }
    }
    std::copy(lo, lo + D, nodes[index].lo);
    std::copy(hi, hi + D, nodes[index].hi);
    if(count <= leafSize) {
      nodes[index].first = first;
      nodes[index].count = count;
      return index;
    }
    int axis = 0;
    for(int k = 1; k < D; k++)
      if(chi[k] - clo[k] > chi[axis] - clo[axis]) axis = k;
    const int half = count / 2;
    std::nth_element(order.begin() + first, order.begin() + first + half,
                     order.begin() + first + count, [&](int a, int b) {
                       return centroids[D * a + axis] < centroids[D * b + axis];
                     });
    const int left = split(first, half, leafSize, boxes, centroids);
    const int right =
      split(first + half, count - half, leafSize, boxes, centroids);
    nodes[index].left = left;
    nodes[index].right = right;
    return index;
  }
};

} // namespace reparam

#endif
