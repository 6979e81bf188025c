// Firm same-depth relations in the drawing order (depth_order.h): an "equal"
// flagged firm is placed before the above/below relations, so orders through
// other regions do not override it; unflagged, it is overridden as before.
#include <gtest/gtest.h>

#include "hair25d/core/error.h"
#include "hair25d/layering/depth_order.h"

namespace hair25d::layering {
namespace {

RegionRelation rel(int a, int b, Relation r, double score) {
  RegionRelation out;
  out.a = a;
  out.b = b;
  out.relation = r;
  out.score = score;
  return out;
}

const RegionRelation* find(const DepthOrder& o, int a, int b) {
  for (const RegionRelation& r : o.relations)
    if (r.a == a && r.b == b) return &r;
  return nullptr;
}

// 7 above 4 (strong), 4 above 9 (weaker), 7 = 9: the two orders imply 7
// above 9, which overrides the plain "equal"; a firm one holds, and the
// weaker order that contradicts it is overridden instead.
const std::vector<RegionRelation> kRelations = {rel(7, 4, Relation::kAbove, 3.0),
                                                rel(4, 9, Relation::kAbove, 2.0),
                                                rel(7, 9, Relation::kEqual, 0.0)};

TEST(FirmEqual, PlainEqualIsOverriddenByOrders) {
  const DepthOrder o = order_regions({4, 7, 9}, kRelations);
  ASSERT_NE(find(o, 7, 9), nullptr);
  EXPECT_TRUE(find(o, 7, 9)->overridden);
  EXPECT_EQ(find(o, 7, 9)->relation, Relation::kAbove);
  EXPECT_GT(o.depth.at(7), o.depth.at(9));
  // The same with flags that mark nothing firm.
  const DepthOrder none = order_regions({4, 7, 9}, kRelations, {0, 0, 0});
  EXPECT_TRUE(find(none, 7, 9)->overridden);
}

TEST(FirmEqual, FirmEqualHoldsAndTheWeakerOrderGives) {
  const DepthOrder o = order_regions({4, 7, 9}, kRelations, {0, 0, 1});
  ASSERT_NE(find(o, 7, 9), nullptr);
  EXPECT_FALSE(find(o, 7, 9)->overridden);
  EXPECT_EQ(find(o, 7, 9)->relation, Relation::kEqual);
  EXPECT_EQ(o.depth.at(7), o.depth.at(9));
  EXPECT_FALSE(find(o, 7, 4)->overridden);
  EXPECT_GT(o.depth.at(7), o.depth.at(4));
  ASSERT_NE(find(o, 4, 9), nullptr);
  EXPECT_TRUE(find(o, 4, 9)->overridden);
  EXPECT_EQ(find(o, 4, 9)->relation, Relation::kBelow);
  ASSERT_EQ(o.overridden.size(), 1u);
  EXPECT_EQ(o.overridden[0], std::make_pair(4, 9));
}

TEST(FirmEqual, FlagsOnOrdersChangeNothing) {
  const DepthOrder plain = order_regions({4, 7, 9}, kRelations);
  const DepthOrder flagged = order_regions({4, 7, 9}, kRelations, {1, 1, 0});
  EXPECT_EQ(plain.depth, flagged.depth);
  EXPECT_EQ(plain.overridden, flagged.overridden);
}

// User-fixed relations still come first; the firm equal comes next.
TEST(FirmEqual, UserFixedOrderStillWins) {
  std::vector<RegionRelation> rs = kRelations;
  rs[1].user_fixed = true;  // 4 above 9, fixed by the user
  const DepthOrder o = order_regions({4, 7, 9}, rs, {0, 0, 1});
  // Fixed first: 4 above 9; then 7 = 9; 7 above 4 would close a cycle.
  EXPECT_FALSE(find(o, 4, 9)->overridden);
  EXPECT_GT(o.depth.at(4), o.depth.at(9));
  EXPECT_FALSE(find(o, 7, 9)->overridden);
  EXPECT_TRUE(find(o, 7, 4)->overridden);
}

TEST(FirmEqual, FlagsOfAnotherLengthAreRefused) {
  EXPECT_THROW(order_regions({4, 7, 9}, kRelations, {1}), Error);
  try {
    order_regions({4, 7, 9}, kRelations, {0, 0, 0, 1});
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("firm flags = 4 for 3 relations"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace hair25d::layering
