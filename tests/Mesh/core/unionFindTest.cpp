// Reparam - disjoint sets joined pair by pair

#include <gtest/gtest.h>
#include "unionFind.h"

using namespace reparam;

TEST(unionFind, eachItemAloneFirst)
{
  unionFind sets(4);
  EXPECT_EQ(sets.size(), 4u);
  for(int i = 0; i < 4; i++) EXPECT_EQ(sets.find(i), i);
}

TEST(unionFind, joinRootsAtTheSecondItemsRoot)
{
  unionFind sets(6);
  sets.join(0, 1);
  EXPECT_EQ(sets.find(0), 1);
  sets.join(2, 3);
  sets.join(1, 3);
  // {0, 1, 2, 3} rooted at 3, {4}, {5}
  for(int i = 0; i < 4; i++) EXPECT_EQ(sets.find(i), 3);
  EXPECT_EQ(sets.find(4), 4);
  sets.join(5, 0);
  EXPECT_EQ(sets.find(5), 3);
  EXPECT_EQ(sets.find(4), 4);
}

TEST(unionFind, aChainHasOneRoot)
{
  const int n = 1000;
  unionFind sets(n);
  for(int i = 0; i + 1 < n; i++) sets.join(i, i + 1);
  for(int i = 0; i < n; i++) ASSERT_EQ(sets.find(i), n - 1);
  // joining within a set changes nothing
  sets.join(n - 1, 0);
  EXPECT_EQ(sets.find(0), n - 1);
}
