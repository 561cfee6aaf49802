// Reparam - the median box tree behind the closest-triangle and (u, v)
// searches (Mesh/core/boxTree.h)

#include <algorithm>
#include <random>
#include <gtest/gtest.h>
#include "boxTree.h"

using namespace reparam;

namespace {

  struct box2 {
    double lo[2], hi[2];
  };

  // depth of node i below the root, its items checked against its box
  int check(const boxTree<2> &tree, const std::vector<box2> &boxes, int i,
            int leafSize, std::vector<int> &seen)
  {
    const boxTree<2>::node &n = tree.nodes[i];
    if(n.left < 0) {
      EXPECT_LE(n.count, leafSize);
      EXPECT_GT(n.count, 0);
      for(int j = n.first; j < n.first + n.count; j++) {
        const box2 &b = boxes[tree.order[j]];
        seen[tree.order[j]]++;
        for(int k = 0; k < 2; k++) {
          EXPECT_LE(n.lo[k], b.lo[k]);
          EXPECT_GE(n.hi[k], b.hi[k]);
        }
      }
      return 0;
    }
    EXPECT_EQ(n.count, 0);
    for(int c : {n.left, n.right})
      for(int k = 0; k < 2; k++) {
        EXPECT_LE(n.lo[k], tree.nodes[c].lo[k]);
        EXPECT_GE(n.hi[k], tree.nodes[c].hi[k]);
      }
    return 1 + std::max(check(tree, boxes, n.left, leafSize, seen),
                        check(tree, boxes, n.right, leafSize, seen));
  }

} // namespace

TEST(boxTree, balancedBoxesHoldingTheirItemsOnce)
{
  // 1000 small boxes along a long thin band: the splits follow its length
  std::mt19937 random(5);
  std::uniform_real_distribution<double> x(0., 100.), y(0., 1.), s(0., 0.1);
  std::vector<box2> boxes(1000);
  for(box2 &b : boxes) {
    b.lo[0] = x(random);
    b.lo[1] = y(random);
    b.hi[0] = b.lo[0] + s(random);
    b.hi[1] = b.lo[1] + s(random);
  }
  boxTree<2> tree;
  tree.build(
    (int)boxes.size(), 4,
    [&](int i, double *lo, double *hi) {
      std::copy(boxes[i].lo, boxes[i].lo + 2, lo);
      std::copy(boxes[i].hi, boxes[i].hi + 2, hi);
    },
    [&](int i, int k) { return 0.5 * (boxes[i].lo[k] + boxes[i].hi[k]); });
  ASSERT_EQ(tree.order.size(), boxes.size());
  std::vector<int> seen(boxes.size(), 0);
  const int depth = check(tree, boxes, 0, 4, seen);
  for(int n : seen) EXPECT_EQ(n, 1);
  // median halves: 1000 -> 500 -> ... -> 3 or 4 in 8 levels
  EXPECT_EQ(depth, 8);
  // the root's first split is across the band's length: its children meet
  // near x = 50
  const boxTree<2>::node &root = tree.nodes[0];
  EXPECT_NEAR(tree.nodes[root.left].hi[0], 50., 5.);
  EXPECT_NEAR(tree.nodes[root.right].lo[0], 50., 5.);
  // nothing to build from nothing
  boxTree<2> empty;
  empty.build(
    0, 4, [](int, double *, double *) {}, [](int, int) { return 0.; });
  EXPECT_TRUE(empty.nodes.empty());
  EXPECT_TRUE(empty.order.empty());
}

TEST(boxTree, eachItemAskedOnceAndTheSameTreeEachTime)
{
  // the build asks each item's box and centroid once, whatever the depth,
  // and builds the same tree from the same items
  std::mt19937 random(11);
  std::uniform_real_distribution<double> x(0., 10.);
  std::vector<box2> boxes(777);
  for(box2 &b : boxes)
    for(int k = 0; k < 2; k++) {
      b.lo[k] = x(random);
      b.hi[k] = b.lo[k] + 0.01 * x(random);
    }
  std::vector<int> boxCalls(boxes.size(), 0), centroidCalls(boxes.size(), 0);
  auto build = [&](boxTree<2> &tree) {
    tree.build((int)boxes.size(), 3,
               [&](int i, double *lo, double *hi) {
                 boxCalls[i]++;
                 std::copy(boxes[i].lo, boxes[i].lo + 2, lo);
                 std::copy(boxes[i].hi, boxes[i].hi + 2, hi);
               },
               [&](int i, int k) {
                 centroidCalls[i]++;
                 return 0.5 * (boxes[i].lo[k] + boxes[i].hi[k]);
               });
  };
  boxTree<2> a, b;
  build(a);
  for(std::size_t i = 0; i < boxes.size(); i++) {
    EXPECT_EQ(boxCalls[i], 1);
    EXPECT_EQ(centroidCalls[i], 2); // one per coordinate
  }
  build(b);
  EXPECT_EQ(a.order, b.order);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  std::vector<int> seen(boxes.size(), 0);
  check(a, boxes, 0, 3, seen);
  for(int n : seen) EXPECT_EQ(n, 1);
}
