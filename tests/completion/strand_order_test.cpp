// The strand order kept acyclic when groups of regions merge
// (completion/src/strand_order.h): a strand has one depth, so no join may
// make a group lie above itself through other groups.
#include "strand_order.h"

#include <gtest/gtest.h>

#include "synthetic.h"

namespace hair25d::completion {
namespace {

using detail::StrandGroups;

// Regions A = 1, X1 = 2, X2 = 3, B = 4: X1 and X2 are one strand (an equal
// pair), X1 lies above A and B above X2. A and B are never ordered directly,
// nor through a chain of regions, only through the strand X.
StrandGroups a_below_x_below_b(StrandOrderGuard guard, bool firm) {
  StrandGroups g;
  g.set_guard(guard);
  for (int id : {1, 2, 3, 4}) g.find(id);
  g.unite(2, 3);
  if (firm) {
    g.add_firm_order(1, 2);
    g.add_firm_order(3, 4);
  } else {
    g.add_weak_order(1, 2);
    g.add_weak_order(3, 4);
  }
  return g;
}

TEST(StrandOrder, JoinAboveAndBelowAThirdStrandIsRefused) {
  StrandGroups guarded = a_below_x_below_b(StrandOrderGuard::kFirm, true);
  EXPECT_FALSE(guarded.try_join(1, 4));
  EXPECT_NE(guarded.find(1), guarded.find(4));
  ASSERT_EQ(guarded.guard_refusals().size(), 1u);
  EXPECT_EQ(guarded.guard_refusals()[0], std::make_pair(1, 4));
  // Either way round.
  EXPECT_FALSE(guarded.try_join(4, 1));
  // Without the guard only direct chains of regions count: the join is made.
  StrandGroups plain = a_below_x_below_b(StrandOrderGuard::kOff, true);
  EXPECT_TRUE(plain.try_join(1, 4));
  EXPECT_EQ(plain.find(1), plain.find(4));
  EXPECT_TRUE(plain.guard_refusals().empty());
}

TEST(StrandOrder, PiecesUnderOneOccluderAreJoined) {
  // X above both A and B (a strand cut by an occluder): no chain from one
  // piece to the other, the join is made.
  StrandGroups g;
  g.set_guard(StrandOrderGuard::kFirm);
  g.add_firm_order(1, 2);
  g.add_firm_order(4, 3);
  g.unite(2, 3);
  EXPECT_TRUE(g.try_join(1, 4));
  EXPECT_EQ(g.find(1), g.find(4));
}

TEST(StrandOrder, DirectChainsOfRegionsAreRefusedWithoutTheGuard) {
  // 1 below 2 below 3: 1 and 3 are refused through region 2 alone.
  StrandGroups g;
  g.add_firm_order(1, 2);
  g.add_firm_order(2, 3);
  EXPECT_FALSE(g.try_join(1, 3));
  EXPECT_FALSE(g.try_join(1, 2));
  EXPECT_TRUE(g.guard_refusals().empty());  // not the guard's refusals
  EXPECT_TRUE(g.try_join(1, 4));
}

TEST(StrandOrder, WeakOrdersCountOnlyWithTheGuardForAll) {
  StrandGroups firm = a_below_x_below_b(StrandOrderGuard::kFirm, false);
  EXPECT_TRUE(firm.try_join(1, 4));
  StrandGroups all = a_below_x_below_b(StrandOrderGuard::kAll, false);
  EXPECT_FALSE(all.try_join(1, 4));
  // A weak order directly between the two never keeps them apart.
  StrandGroups direct;
  direct.set_guard(StrandOrderGuard::kAll);
  direct.add_weak_order(1, 4);
  EXPECT_TRUE(direct.try_join(1, 4));
}

// test::strand_under_band with its band split in two regions of one strand
// (3, x 40..170, and 5, x 170..210, an equal pair): the band lies above the
// upper piece 1, and the lower piece 2 is said to lie above 5. Joining 1 and
// 2 would put the band's strand above the joined strand and below it.
test::Drawing strand_over_split_band() {
  const Rgba back{120, 80, 50, 255}, strand{200, 150, 110, 255};
  test::Drawing d = test::blank(250, 300);
  test::paint(
      d, [](double x, double y) { return x > 20 && x < 230 && y > 20 && y < 280; }, back, 4);
  test::paint(
      d, [](double x, double y) { return x > 100 && x < 140 && y > 70 && y < 140; }, strand, 1);
  test::paint(
      d, [](double x, double y) { return x > 100 && x < 140 && y >= 140 && y < 210; }, strand, 2);
  test::paint(
      d, [](double x, double y) { return x > 40 && x < 170 && y > 118 && y < 162; }, strand, 3);
  test::paint(
      d, [](double x, double y) { return x >= 170 && x < 210 && y > 118 && y < 162; }, strand, 5);
  using test::below;
  d.relations = {below(4, 1), below(4, 2), below(4, 3), below(4, 5),
                 below(1, 3), below(2, 3), below(5, 2), {3, 5, Relation::kEqual, 1.0, true, false}};
  return d;
}

std::vector<int> joined_with_1(StrandOrderGuard guard) {
  const test::Drawing d = strand_over_split_band();
  Options o;
  o.inpaint_background = false;
  o.face_joins = false;
  o.strand_order = guard;
  const Result r = complete_strands(test::input_of(d, Vec2(125, 10)), o);
  if (guard != StrandOrderGuard::kOff) {
    EXPECT_EQ(r.order_refusals.size(), 1u);
    for (const Result::OrderRefusal& o : r.order_refusals) {
      EXPECT_EQ(std::min(o.region_a, o.region_b), 1);
      EXPECT_EQ(std::max(o.region_a, o.region_b), 2);
      EXPECT_EQ(o.join, "strand");
    }
  } else {
    EXPECT_TRUE(r.order_refusals.empty());
  }
  return test::regions_with(r, 1);
}

TEST(StrandOrder, CompletionRefusesAJoinThatPutsAStrandAboveItself) {
  EXPECT_EQ(joined_with_1(StrandOrderGuard::kOff), (std::vector<int>{1, 2}));
  EXPECT_EQ(joined_with_1(StrandOrderGuard::kFirm), (std::vector<int>{1}));
}

}  // namespace
}  // namespace hair25d::completion
