// Topological order with cycle breaking: acyclic, weakest links dropped,
// independent of how regions are numbered.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "hair25d/core/error.h"
#include "hair25d/layering/depth_order.h"

namespace hair25d::layering {
namespace {

RegionRelation rel(int a, int b, Relation r, double score) {
  RegionRelation x;
  x.a = a;
  x.b = b;
  x.relation = r;
  x.score = score;
  return x;
}

// Every relation of the result holds in the depth map.
void expect_consistent(const DepthOrder& o) {
  for (const RegionRelation& r : o.relations) {
    const int da = o.depth.at(r.a), db = o.depth.at(r.b);
    if (r.relation == Relation::kAbove) {
      EXPECT_GT(da, db) << r.a << " above " << r.b;
    }
    if (r.relation == Relation::kBelow) {
      EXPECT_LT(da, db) << r.a << " below " << r.b;
    }
    if (r.relation == Relation::kEqual) {
      EXPECT_EQ(da, db) << r.a << " equal " << r.b;
    }
  }
}

TEST(OrderRegions, ChainGivesIncreasingDepth) {
  const DepthOrder o = order_regions(
      {1, 2, 3}, {rel(1, 2, Relation::kBelow, 1.0), rel(3, 2, Relation::kAbove, 1.0)});
  EXPECT_EQ(o.depth.at(1), 0);
  EXPECT_EQ(o.depth.at(2), 1);
  EXPECT_EQ(o.depth.at(3), 2);
  EXPECT_TRUE(o.overridden.empty());
}

TEST(OrderRegions, CycleDropsItsWeakestRelation) {
  // 1 < 2 < 3 < 1, the last one weakest.
  const DepthOrder o =
      order_regions({1, 2, 3}, {rel(1, 2, Relation::kBelow, 3.0), rel(2, 3, Relation::kBelow, 2.0),
                                rel(3, 1, Relation::kBelow, -0.5)});
  ASSERT_EQ(o.overridden.size(), 1u);
  EXPECT_EQ(o.overridden[0], std::make_pair(3, 1));
  EXPECT_TRUE(o.relations[2].overridden);
  EXPECT_EQ(o.relations[2].relation, Relation::kAbove);  // flipped to agree
  expect_consistent(o);
}

TEST(OrderRegions, UserFixedRelationWinsOverStrongerOnes) {
  RegionRelation fixed = rel(3, 1, Relation::kBelow, 0.0);
  fixed.user_fixed = true;
  const DepthOrder o = order_regions(
      {1, 2, 3}, {rel(1, 2, Relation::kBelow, 3.0), rel(2, 3, Relation::kBelow, 2.0), fixed});
  EXPECT_FALSE(o.relations[2].overridden);
  EXPECT_LT(o.depth.at(3), o.depth.at(1));
  expect_consistent(o);
}

TEST(OrderRegions, EqualRegionsShareADepth) {
  const DepthOrder o = order_regions(
      {4, 5, 6}, {rel(4, 5, Relation::kEqual, 0.0), rel(6, 4, Relation::kAbove, 1.0)});
  EXPECT_EQ(o.depth.at(4), o.depth.at(5));
  EXPECT_GT(o.depth.at(6), o.depth.at(5));
}

TEST(OrderRegions, EqualDoesNotUndoAnOrderAlreadyPlaced) {
  // 1 < 2 < 3 by strong relations; a claim that 1 = 3 contradicts them.
  const DepthOrder o =
      order_regions({1, 2, 3}, {rel(1, 3, Relation::kEqual, 0.0), rel(1, 2, Relation::kBelow, 1.0),
                                rel(2, 3, Relation::kBelow, 1.0)});
  ASSERT_EQ(o.overridden.size(), 1u);
  EXPECT_EQ(o.overridden[0], std::make_pair(1, 3));
  EXPECT_EQ(o.relations[0].relation, Relation::kBelow);
  expect_consistent(o);
}

TEST(OrderRegions, RandomRelationsGiveAnAcyclicOrderIndependentOfNumbering) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> score(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const int n = 3 + trial % 9;
    std::vector<int> ids(n);
    for (int i = 0; i < n; ++i) ids[i] = i + 1;
    std::vector<RegionRelation> rels;
    for (int a = 1; a <= n; ++a)
      for (int b = a + 1; b <= n; ++b)
        if (rng() % 3 == 0) {
          const double s = score(rng);
          rels.push_back(rel(a, b, s > 0 ? Relation::kAbove : Relation::kBelow, s));
        }
    const DepthOrder o = order_regions(ids, rels);
    expect_consistent(o);

    // The same relations with ids renumbered by a random permutation.
    std::vector<int> perm = ids;
    std::shuffle(perm.begin(), perm.end(), rng);
    for (int& p : perm) p = p * 7 + 3;  // and not 1..n any more
    std::vector<RegionRelation> moved = rels;
    for (RegionRelation& r : moved) {
      r.a = perm[r.a - 1];
      r.b = perm[r.b - 1];
    }
    std::reverse(moved.begin(), moved.end());  // and listed in another order
    std::vector<int> moved_ids = perm;
    std::sort(moved_ids.begin(), moved_ids.end());
    const DepthOrder p = order_regions(moved_ids, moved);
    for (int id : ids) EXPECT_EQ(o.depth.at(id), p.depth.at(perm[id - 1])) << "trial " << trial;
  }
}

TEST(OrderRegions, RejectsBadInput) {
  EXPECT_THROW(order_regions({1, 2}, {rel(1, 3, Relation::kAbove, 1)}), Error);
  EXPECT_THROW(order_regions({1, 2}, {rel(2, 2, Relation::kAbove, 1)}), Error);
}

}  // namespace
}  // namespace hair25d::layering
