// An open pair (equal only for want of a drawn line) that the same-depth
// model says lies at two depths is ordered (Options::open_order_log_odds).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include "hair25d/core/annotation.h"
#include "hair25d/core/error.h"
#include "hair25d/layering/layering.h"
#include "layering/relation_lookup.h"

namespace hair25d::layering {
namespace {

using test::relation_of;

AnnotatedCase case1() {
  return read_annotated_case(std::filesystem::path(HAIR25D_TEST_DATA_DIR) / "annotated" / "case1");
}

// The mean same-depth log-odds over a pair's open hair boundaries.
double open_same_log_odds(const Result& r, int a, int b) {
  double length = 0.0, sum = 0.0;
  for (const BoundaryReport& rep : r.boundaries) {
    const bool pair = (rep.left == a && rep.right == b) || (rep.left == b && rep.right == a);
    if (!pair || rep.occluding) continue;
    length += rep.length;
    sum += rep.equal * rep.length;
  }
  return length > 0 ? sum / length : std::numeric_limits<double>::quiet_NaN();
}

// Case 1's region 17, a sliver of a strand lying over regions 10 and 9,
// whose outline against them reads under the line threshold: the
// annotation has it above both. Its open boundaries read about -11
// same-depth log-odds, far from a cusp inside one strand; ordered by their
// order log-odds it is above, where before it was "equal" and the
// completion joined it into their strand.
TEST(OpenOrder, SliverWithoutALineIsOrderedAbove) {
  const AnnotatedCase c = case1();
  const Result r = layer_regions(c.image, c.regions);
  EXPECT_LT(open_same_log_odds(r, 17, 10), -6.0);
  EXPECT_EQ(relation_of(r, 17, 10), Relation::kAbove);
  EXPECT_EQ(relation_of(r, 17, 9), Relation::kAbove);
}

// -infinity turns the rule off: the open pairs are equal, as before.
TEST(OpenOrder, MinusInfinityKeepsOpenPairsEqual) {
  const AnnotatedCase c = case1();
  Options o;
  o.open_order_log_odds = -std::numeric_limits<double>::infinity();
  std::string why;
  EXPECT_TRUE(o.is_valid(&why)) << why;
  const Result r = layer_regions(c.image, c.regions, o);
  EXPECT_EQ(relation_of(r, 17, 10), Relation::kEqual);
}

// The mean same-depth log-odds over a pair's occluding hair boundaries.
double occluding_same_log_odds(const Result& r, int a, int b) {
  double length = 0.0, sum = 0.0;
  for (const BoundaryReport& rep : r.boundaries) {
    const bool pair = (rep.left == a && rep.right == b) || (rep.left == b && rep.right == a);
    if (!pair || !rep.occluding) continue;
    length += rep.length;
    sum += rep.equal * rep.length;
  }
  return length > 0 ? sum / length : std::numeric_limits<double>::quiet_NaN();
}

const RegionRelation* find(const Result& r, int a, int b) {
  for (const RegionRelation& x : r.relations)
    if ((x.a == a && x.b == b) || (x.a == b && x.b == a)) return &x;
  return nullptr;
}

// Each measured `equal` carries the log-odds it was decided on
// (RegionRelation::equal_evidence, which completion weighs; its score is
// 0); orders and the user's relations carry none. With the open rule off,
// case 1's sliver 17 is an open equal of 10, its evidence its open
// boundaries' mean; the pairs the same-depth model calls one depth carry
// their occluding boundaries' mean, over 0.
TEST(OpenOrder, EqualsCarryTheirEvidence) {
  const AnnotatedCase c = case1();
  Options o;
  o.open_order_log_odds = -std::numeric_limits<double>::infinity();
  const Result r = layer_regions(c.image, c.regions, o);
  const RegionRelation* sliver = find(r, 17, 10);
  ASSERT_NE(sliver, nullptr);
  ASSERT_TRUE(sliver->equal_evidence);
  EXPECT_TRUE(sliver->equal_evidence->open);
  EXPECT_NEAR(sliver->equal_evidence->log_odds, open_same_log_odds(r, 17, 10), 1e-9);
  EXPECT_GT(sliver->equal_evidence->open_fraction, 0.5);
  // Case 3 has pairs the same-depth model calls one depth (13 and 14).
  const AnnotatedCase c3 =
      read_annotated_case(std::filesystem::path(HAIR25D_TEST_DATA_DIR) / "annotated" / "case3");
  const Result case3 = layer_regions(c3.image, c3.regions);
  int same_depth = 0;
  for (const Result* result : {&r, &case3})
    for (const RegionRelation& x : result->relations) {
      if (!x.equal_evidence) continue;
      EXPECT_EQ(x.score, 0.0) << x.a << " / " << x.b;
      if (x.equal_evidence->open) continue;
      ++same_depth;
      EXPECT_GT(x.equal_evidence->log_odds, 0.0) << x.a << " / " << x.b;
      EXPECT_NEAR(x.equal_evidence->log_odds, occluding_same_log_odds(*result, x.a, x.b), 1e-9);
    }
  EXPECT_GT(same_depth, 0);
  // Measured orders carry none, nor does the user's word on the sliver.
  const Result ordered = layer_regions(c.image, c.regions);
  const RegionRelation* above = find(ordered, 17, 10);
  ASSERT_NE(above, nullptr);
  EXPECT_NE(above->relation, Relation::kEqual);
  EXPECT_FALSE(above->equal_evidence);
  o.fixed = {{17, 10, Relation::kEqual, 0.0, true}};
  const Result with_user = layer_regions(c.image, c.regions, o);
  const RegionRelation* fixed = find(with_user, 17, 10);
  ASSERT_NE(fixed, nullptr);
  EXPECT_TRUE(fixed->user_fixed);
  EXPECT_FALSE(fixed->equal_evidence);
}

TEST(OpenOrder, RejectsNanAndPlusInfinity) {
  for (double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    Options o;
    o.open_order_log_odds = bad;
    std::string why;
    EXPECT_FALSE(o.is_valid(&why));
    EXPECT_NE(why.find("open_order_log_odds"), std::string::npos);
  }
}

}  // namespace
}  // namespace hair25d::layering
