// Session 36 (JoinScorerOptions::cover_refusal_threshold): a strand-join
// candidate refused only because its patch lies under min_join_coverage is
// kept as a second chance and judged by a net trained on such candidates
// alone (`cover_join_scorer`), with inputs saying what lies where the patch
// is uncovered (cover_retry.h).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "annotated_eval.h"
#include "feature_index.h"
#include "generated_case.h"
#include "hair25d/completion/completion.h"
#include "hair25d/completion/join_scorer.h"
#include "hair25d/generator/generator.h"
#include "invalid_options.h"
#include "joins_only.h"
#include "trace_of.h"

namespace hair25d::completion {
namespace {

constexpr int kCoverRetried = 54;  // join_feature_name: "cover_retried"
constexpr int kRetried = 44;       // "retried" (session 35)

Result run(const AnnotatedCase& c, double threshold, bool all_shadings = false) {
  Options o = test::joins_only();
  o.trace_joins = true;
  o.join_scorer.cover_refusal_threshold = threshold;
  o.join_scorer.cover_refusal_all_shadings = all_shadings;
  return complete_strands(test::input_from_case(c), o);
}

// With a bar any candidate passes, two-tone drawings gain joins
// of pairs the cover refused, each with a patch under min_join_coverage.
TEST(CoverRefusals, JoinedOnlyWhenOn) {
  std::size_t gained = 0;
  for (const std::uint64_t seed : {2000u, 2001u, 2002u, 2003u}) {
    const AnnotatedCase c = test::generated_case(seed, generator::Shading::kTwoTone);
    gained += test::cover_gains(run(c, 1.0), run(c, 1e-6)).size();
  }
  EXPECT_GT(gained, 0u);
}

// Recorded (the net's training data) as rows of their own: `cover_retried`
// set, the cover under min_join_coverage, the uncovered shares summing to
// what the cover leaves (the same raster, off screentone), never chosen;
// every other row has the second chance's inputs at 0 (the nets trained
// before them see what they were trained on).
TEST(CoverRefusals, RecordedAsRowsOfTheirOwn) {
  Options o = test::joins_only();
  o.join_scorer.enabled = false;
  o.join_scorer.record = true;
  const AnnotatedCase c = test::generated_case(2002, generator::Shading::kTwoTone);
  const Result r = complete_strands(test::input_from_case(c), o);
  const int uncovered = test::feature_index("uncovered");  // 1 − the cover
  int retried = 0;
  for (const JoinCandidate& j : r.join_candidates) {
    if (j.features[kCoverRetried] > 0.5f) {
      ++retried;
      EXPECT_GT(j.features[uncovered], 1.0 - o.min_join_coverage - 1e-6);
      double missed = 0;
      for (int k = 55; k <= 60; ++k) {
        EXPECT_GE(j.features[k], 0.0f) << k;
        missed += j.features[k];
      }
      EXPECT_NEAR(missed, j.features[uncovered], 1e-4);
      EXPECT_GE(j.features[61], 1.0f - j.features[uncovered] - 1e-5f);  // the best shape's cover
      EXPECT_GE(j.features[63], 0.0f);
      EXPECT_LE(j.features[63], 1.0f);
      EXPECT_GT(j.features[62], 0.0f);
      for (int k = kRetried; k < kCoverRetried; ++k) EXPECT_EQ(j.features[k], 0.0f) << k;
      EXPECT_FALSE(j.chosen);
      continue;
    }
    // Inputs 75-76 (session 39) are every shaded candidate's.
    for (int k = kCoverRetried; k < 75; ++k) EXPECT_EQ(j.features[k], 0.0f) << k;
  }
  EXPECT_GT(retried, 0);
}

// Dev two-tone 2036 (+10 right pairs at 0.9 with the annotation's
// relations): at the bar of session 36 the net joins pairs the cover
// refused, each of one strand in the annotation, with p over the bar.
TEST(CoverRefusals, RightJoinsAtTheBar) {
  const AnnotatedCase c = test::generated_case(2036, generator::Shading::kTwoTone);
  std::map<int, int> strand;
  for (const AnnotatedRegion& r : c.region_list) strand[r.id] = r.strand;
  const std::vector<JoinTrace> gained = test::cover_gains(run(c, 1.0), run(c, 0.9));
  for (const JoinTrace& t : gained) {
    EXPECT_GE(t.probability, 0.9);
    EXPECT_EQ(strand.at(t.region_a), strand.at(t.region_b)) << t.region_a << "-" << t.region_b;
  }
  EXPECT_FALSE(gained.empty());
}

// The default options join at the bar of session 36: the same joins as
// the bar set to 0.9, and more than with the second chances off.
TEST(CoverRefusals, JoinedAtTheDefaultBar) {
  const AnnotatedCase c = test::generated_case(2036, generator::Shading::kTwoTone);
  Options o = test::joins_only();
  o.trace_joins = true;
  const Result by_default = complete_strands(test::input_from_case(c), o);
  const auto chosen = test::traced_pairs(by_default, JoinStage::kChosen);
  EXPECT_EQ(chosen, test::traced_pairs(run(c, 0.9), JoinStage::kChosen));
  EXPECT_GT(chosen.size(), test::traced_pairs(run(c, 1.0), JoinStage::kChosen).size());
}

// On screentone drawings (no shaded paint) only with
// cover_refusal_all_shadings: without it no pair the cover refused is
// joined, with it some are at a bar any candidate passes.
TEST(CoverRefusals, ScreentoneOnlyWithAllShadings) {
  int without = 0, with = 0;
  for (const std::uint64_t seed : {2000u, 2001u, 2002u, 2003u}) {
    const AnnotatedCase c = test::generated_case(seed, generator::Shading::kScreentone);
    const Result off = run(c, 1.0);
    const auto refused = test::traced_pairs(off, JoinStage::kCover),
               before = test::traced_pairs(off, JoinStage::kChosen);
    auto gained = [&](const Result& r) {
      int n = 0;
      for (const auto& pair : test::traced_pairs(r, JoinStage::kChosen))
        n += !before.count(pair) && refused.count(pair);
      return n;
    };
    without += gained(run(c, 1e-6));
    with += gained(run(c, 1e-6, true));
  }
  EXPECT_EQ(without, 0);
  EXPECT_GT(with, 0);
}

TEST(CoverRefusals, BadThresholdIsRefused) {
  Options o;
  for (double t : {0.0, 1.5, -0.2, std::nan("")}) {
    o.join_scorer.cover_refusal_threshold = t;
    test::expect_invalid(o, "cover_refusal_threshold");
  }
}

TEST(CoverRefusals, CoverRetriedIsInput54) {
  EXPECT_STREQ(join_feature_name(kCoverRetried), "cover_retried");
  EXPECT_STREQ(join_feature_name(63), "miss_at_cuts");
}

}  // namespace
}  // namespace hair25d::completion
