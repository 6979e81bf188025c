// Session 39 (JoinScorerOptions::field_cross_max): on gradient drawings a
// candidate its net refuses joins last when each piece's own colour field
// predicts the other piece's paint at its cut (inputs 75-76,
// RegionFields::cross_miss).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <utility>

#include "annotated_eval.h"
#include "generated_case.h"
#include "hair25d/completion/completion.h"
#include "hair25d/completion/join_scorer.h"
#include "hair25d/generator/generator.h"
#include "invalid_options.h"
#include "joins_only.h"
#include "strand_of.h"
#include "trace_of.h"

namespace hair25d::completion {
namespace {

constexpr int kFieldCrossMax = 75;     // join_feature_name: "field_cross_max"
constexpr int kFieldCrossLarger = 76;  // "field_cross_larger"

Options on(double max, double larger, double low) {
  Options o = test::joins_only();
  o.trace_joins = true;
  o.join_scorer.field_cross_max = max;
  o.join_scorer.field_cross_larger_max = larger;
  o.join_scorer.field_cross_low = low;
  return o;
}

std::set<std::pair<int, int>> chosen(const AnnotatedCase& c, const Options& o) {
  return test::traced_pairs(complete_strands(test::input_from_case(c), o), JoinStage::kChosen);
}

TEST(FieldCross, InputsAreNamed) {
  EXPECT_STREQ(join_feature_name(kFieldCrossMax), "field_cross_max");
  EXPECT_STREQ(join_feature_name(kFieldCrossLarger), "field_cross_larger");
}

TEST(FieldCross, BadValuesAreRefused) {
  JoinScorerOptions s;
  s.field_cross_max = -1;
  test::expect_invalid(s, "field_cross_max");
  s.field_cross_max = 61;
  test::expect_invalid(s, "field_cross_max");
  s.field_cross_max = std::numeric_limits<double>::quiet_NaN();
  test::expect_invalid(s, "field_cross_max");
  s = {};
  s.field_cross_larger_max = -0.5;
  test::expect_invalid(s, "field_cross_larger_max");
  s = {};
  s.field_cross_low = 1.5;
  test::expect_invalid(s, "field_cross_low");
  Options o;
  o.join_scorer.field_cross_max = -1;
  test::expect_invalid(o, "field_cross_max");
}

// Recorded with the scorer on: gradient candidates carry the measure (the
// worse way round at least the larger piece's), two-tone ones (cel paint)
// and flat ones never do.
TEST(FieldCross, MeasuredOnGradientDrawingsOnly) {
  Options o = test::joins_only();
  o.join_scorer.record = true;
  int measured = 0;
  const AnnotatedCase g = test::generated_case(2005, generator::Shading::kGradient);
  for (const JoinCandidate& j : complete_strands(test::input_from_case(g), o).join_candidates) {
    if (j.features[kFieldCrossMax] < 0) {
      EXPECT_EQ(j.features[kFieldCrossLarger], -1.0f);
      continue;
    }
    ++measured;
    EXPECT_GE(j.features[kFieldCrossMax], j.features[kFieldCrossLarger] - 1e-6f);
    EXPECT_GE(j.features[kFieldCrossLarger], 0.0f);
    EXPECT_LE(j.features[kFieldCrossMax], 2.0f);
  }
  EXPECT_GT(measured, 0);
  for (const generator::Shading shading :
       {generator::Shading::kTwoTone, generator::Shading::kFlat}) {
    const AnnotatedCase c = test::generated_case(2005, shading);
    for (const JoinCandidate& j : complete_strands(test::input_from_case(c), o).join_candidates) {
      EXPECT_EQ(j.features[kFieldCrossMax], -1.0f);
      EXPECT_EQ(j.features[kFieldCrossLarger], -1.0f);
    }
  }
}

// Off (0) the joins are those of a scorer without the rule, whatever the
// other two values; on two-tone and flat drawings even a rule any measured
// candidate passes changes nothing.
TEST(FieldCross, NotOffNorOffGradient) {
  const AnnotatedCase g = test::generated_case(2005, generator::Shading::kGradient);
  EXPECT_EQ(chosen(g, on(0, 0, 0.3)), chosen(g, on(0, 60, 0)));
  Options plain = test::joins_only();
  plain.trace_joins = true;
  for (const generator::Shading shading :
       {generator::Shading::kTwoTone, generator::Shading::kFlat}) {
    const AnnotatedCase c = test::generated_case(2005, shading);
    EXPECT_EQ(chosen(c, on(60, 60, 0)), chosen(c, plain));
  }
}

// On by default at 3 / 1.5 / 0.5: dev gradient 2010 and 2013 gain pairs
// over the rule turned off, and every pair gained is of one annotated
// strand (fails with the rule off by default, or when it joins pieces of
// two strands there).
TEST(FieldCross, RightJoinsByDefault) {
  Options plain = test::joins_only();
  plain.trace_joins = true;
  for (const std::uint64_t seed : {2010u, 2013u}) {
    const AnnotatedCase c = test::generated_case(seed, generator::Shading::kGradient);
    const auto by_default = chosen(c, plain);
    EXPECT_EQ(by_default, chosen(c, on(3, 1.5, 0.5)));
    std::map<int, int> truth;
    for (const AnnotatedRegion& reg : c.region_list) truth[reg.id] = reg.strand;
    const auto off = chosen(c, on(0, 0, 0.5));
    int gained = 0;
    for (const auto& [a, b] : by_default) {
      if (off.count({a, b})) continue;
      ++gained;
      EXPECT_EQ(truth.at(a), truth.at(b)) << "seed " << seed << " joined " << a << "-" << b;
    }
    EXPECT_GT(gained, 0) << "seed " << seed;
  }
}

// With a rule any measured candidate passes, gradient drawings gain joins
// of pairs their nets refused (fails without the rule).
TEST(FieldCross, JoinsWhatTheNetsRefuse) {
  int gained = 0;
  for (const std::uint64_t seed : {2000u, 2001u, 2002u, 2003u}) {
    const AnnotatedCase c = test::generated_case(seed, generator::Shading::kGradient);
    const auto off = chosen(c, on(0, 0, 0)), all = chosen(c, on(60, 60, 0));
    for (const auto& pair : all) gained += !off.count(pair);
  }
  EXPECT_GT(gained, 0);
}

}  // namespace
}  // namespace hair25d::completion
