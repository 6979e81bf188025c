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
