// Session 32 (JoinScorerOptions::second_low, second_threshold): a band
// candidate the default net refuses on a flat drawing is joined when the
// retrained net, trained on other rows, is sure of it; never on screentone,
// two-tone or gradient drawings, whose band other nets judge.
#include <gtest/gtest.h>

#include <string>

#include "annotated_eval.h"
#include "generated_case.h"
#include "hair25d/completion/completion.h"
#include "hair25d/completion/join_scorer.h"
#include "hair25d/generator/generator.h"
#include "invalid_options.h"
#include "same_joins.h"

namespace hair25d::completion {
namespace {

Result run(const AnnotatedCase& c, double second_low, double second_threshold) {
  Options o;
  o.inpaint_strands = false;
  o.inpaint_background = false;
  o.join_scorer.record = true;
  // The nets alone: no ensemble rescues, no side-tangent candidates.
  o.join_scorer.ensemble = JoinScorerOptions::Ensemble::kNone;
  o.join_scorer.side_threshold = 1.0;
  o.join_scorer.second_low = second_low;
  o.join_scorer.second_threshold = second_threshold;
  return complete_strands(test::input_from_case(c), o);
}

// Band candidates over the limit that the band's net refused (p under its
// `threshold`) but that were ranked under the limit: with the ensembles off
// only the second opinion does that. Each must have p >= second_low and the
// second net's p >= second_threshold.
int second_rescues(const Result& r, double threshold, const JoinScorerNet& second,
                   double second_low, double second_threshold) {
  const JoinScorerOptions s;
  const double limit = Options{}.max_join_cost;
  int n = 0;
  for (const JoinCandidate& j : r.join_candidates) {
    if (j.hand_cost <= limit || j.hand_cost > s.band_high || j.probability < 0) continue;
    if (j.probability >= threshold || j.cost > limit) continue;
    ++n;
    EXPECT_GE(j.probability, second_low);
    EXPECT_GE(join_probability(second, j.features), second_threshold);
  }
  return n;
}

TEST(JoinScorerSecond, RefusalsAreRescuedOnlyByTheSecondNet) {
  const double threshold = JoinScorerOptions{}.threshold;  // the default net's bar
  const JoinScorerNet& second = retrained_join_scorer();
  for (const int seed : {2004, 2005}) {
    SCOPED_TRACE(seed);
    const AnnotatedCase c = test::generated_case(seed, generator::Shading::kFlat);
    // Off: nothing under the band's bar is joined from over the limit.
    EXPECT_EQ(second_rescues(run(c, 0.5, 1.0), threshold, second, 0.0, 0.0), 0);
    // A lax second bar rescues refusals, each one the retrained net trusts;
    // a strict one fewer.
    const int lax = second_rescues(run(c, 0.0, 0.05), threshold, second, 0.0, 0.05);
    const int strict = second_rescues(run(c, 0.0, 0.95), threshold, second, 0.0, 0.95);
    EXPECT_GT(lax, 0);
    EXPECT_LT(strict, lax);
    // second_low: refusals the default net finds unlikely stay refused.
    second_rescues(run(c, 0.5, 0.05), threshold, second, 0.5, 0.05);
  }
}

// Screentone, two-tone and gradient drawings keep their joins with the
// option on.
TEST(JoinScorerSecond, NoneOnScreentoneOrShadedDrawings) {
  for (const generator::Shading shading :
       {generator::Shading::kScreentone, generator::Shading::kTwoTone,
        generator::Shading::kGradient}) {
    SCOPED_TRACE(static_cast<int>(shading));
    const AnnotatedCase c = test::generated_case(2004, shading);
    const Result off = run(c, 0.5, 1.0);
    const Result on = run(c, 0.0, 0.05);
    test::expect_same_joins(off, on);
  }
}

TEST(JoinScorerSecond, BadBarsAreRefused) {
  JoinScorerOptions s;
  std::string why;
  s.second_threshold = 0.0;
  test::expect_invalid(s, "second_threshold");
  s.second_threshold = 1.5;
  test::expect_invalid(s, "second_threshold = 1.5");
  s = {};
  s.second_low = -0.1;
  test::expect_invalid(s, "second_low");
  s = {};
  s.second_threshold = 1.0;  // off: valid
  EXPECT_TRUE(s.is_valid(&why)) << why;
}

}  // namespace
}  // namespace hair25d::completion
