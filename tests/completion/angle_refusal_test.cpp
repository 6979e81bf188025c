// Session 35 (JoinScorerOptions::angle_refusal_threshold): an edge pair
// refused by the 70° angle that no side tangent brings within it is tried
// with other tangents (angle_retry.h) and judged by a net trained on such
// candidates alone (`angle_join_scorer`), on every shading.
#include <gtest/gtest.h>

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

constexpr int kRetried = 44;  // join_feature_name: "retried"

Result run(const AnnotatedCase& c, double threshold) {
  Options o = test::joins_only();
  o.trace_joins = true;
  o.join_scorer.angle_refusal_threshold = threshold;
  // Cover refusals' second chances have their own net
  // (cover_refusal_test.cpp); on two-tone 2002 it joins 2-19 too.
  o.join_scorer.cover_refusal_threshold = 1.0;
  return complete_strands(test::input_from_case(c), o);
}

// Off (1) no second chance is made; with a bar any candidate passes,
// screentone drawings (where no side tangent is tried) gain joins of pairs
// the angle refused.
TEST(AngleRefusals, JoinedOnlyWhenOn) {
  int gained = 0;
  for (const std::uint64_t seed : {2000u, 2001u, 2002u, 2003u}) {
    const AnnotatedCase c = test::generated_case(seed, generator::Shading::kScreentone);
    const Result off = run(c, 1.0), on = run(c, 0.01);
    const auto refused = test::traced_pairs(off, JoinStage::kAngle),
               before = test::traced_pairs(off, JoinStage::kChosen);
    for (const auto& pair : test::traced_pairs(on, JoinStage::kChosen))
      if (!before.count(pair) && refused.count(pair)) ++gained;
  }
  EXPECT_GT(gained, 0);
}

// Recorded (the net's training data) as rows of their own: `retried` set,
// within the angle limit with the tangents tried, over it with their own;
// every other row has the second chance's inputs at 0 (the nets trained
// before them see what they were trained on).
TEST(AngleRefusals, RecordedAsRowsOfTheirOwn) {
  Options o = test::joins_only();
  o.join_scorer.enabled = false;
  o.join_scorer.record = true;
  const AnnotatedCase c = test::generated_case(2002, generator::Shading::kTwoTone);
  const Result r = complete_strands(test::input_from_case(c), o);
  int retried = 0;
  for (const JoinCandidate& j : r.join_candidates) {
    if (j.features[kRetried] > 0.5f) {
      ++retried;
      EXPECT_LE(j.features[1], 1.0f + 1e-5f);  // worst angle tried
      EXPECT_GT(j.features[45], 1.0f);         // worst angle of its own
      EXPECT_FALSE(j.chosen);
      continue;
    }
    // Inputs 54-63 are the cover refusals' second chances (session 36).
    for (int k = kRetried; k < 54; ++k) EXPECT_EQ(j.features[k], 0.0f) << k;
  }
  EXPECT_GT(retried, 0);
}

// Dev two-tone 2002: pieces 2 and 19, one strand in the annotation, are
// refused by the angle with their own tangents; at the default bar the
// angle net's second chance joins them (p 0.91).
TEST(AngleRefusals, JoinedAtTheDefaultBar) {
  const AnnotatedCase c = test::generated_case(2002, generator::Shading::kTwoTone);
  const Result off = run(c, 1.0);
  EXPECT_EQ(test::trace_of(off, 2, 19, JoinStage::kChosen), nullptr);
  EXPECT_NE(test::trace_of(off, 2, 19, JoinStage::kAngle), nullptr);
  std::map<int, int> s = test::strand_of(off);
  EXPECT_NE(s.at(2), s.at(19));

  const double bar = JoinScorerOptions{}.angle_refusal_threshold;
  ASSERT_LT(bar, 1.0);
  const Result on = run(c, bar);
  const JoinTrace* chosen = test::trace_of(on, 2, 19, JoinStage::kChosen);
  ASSERT_NE(chosen, nullptr);
  EXPECT_GE(chosen->probability, bar);
  s = test::strand_of(on);
  EXPECT_EQ(s.at(2), s.at(19));
}

TEST(AngleRefusals, BadThresholdIsRefused) {
  Options o;
  for (double t : {0.0, 1.5, -0.2}) {
    o.join_scorer.angle_refusal_threshold = t;
    test::expect_invalid(o, "angle_refusal_threshold");
  }
}

TEST(AngleRefusals, RetriedIsInput44) { EXPECT_STREQ(join_feature_name(kRetried), "retried"); }

}  // namespace
}  // namespace hair25d::completion
