// JoinScorerOptions::retrained_shaded_threshold (session 34): the
// retrained net's bar for the band on two-tone and gradient drawings.
#include <gtest/gtest.h>

#include <map>

#include "annotated_eval.h"
#include "generated_case.h"
#include "hair25d/completion/completion.h"
#include "hair25d/core/error.h"
#include "invalid_options.h"
#include "joins_only.h"
#include "strand_of.h"
#include "trace_of.h"

namespace hair25d::completion {
namespace {

Result run(const AnnotatedCase& c, double bar) {
  Options o = test::joins_only();
  o.trace_joins = true;
  o.join_scorer.retrained_shaded_threshold = bar;
  return complete_strands(test::input_from_case(c), o);
}

// Dev two-tone 2077: back hair 1 and piece 20, one strand in the
// annotation, meet across the strands over them in a band candidate the
// retrained net gives p 0.87: refused at 0.9, joined at the default bar.
TEST(RetrainedShadedBar, BackHairJoinsUnderTheOldBar) {
  const AnnotatedCase c = test::generated_case(2077, generator::Shading::kTwoTone);
  const Result high = run(c, 0.9);
  const JoinTrace* refused = test::trace_of(high, 1, 20, JoinStage::kBandRefused);
  ASSERT_NE(refused, nullptr);
  EXPECT_GE(refused->probability, JoinScorerOptions{}.retrained_shaded_threshold);
  EXPECT_LT(refused->probability, 0.9);
  std::map<int, int> s = test::strand_of(high);
  EXPECT_NE(s.at(1), s.at(20));

  const Result low = run(c, JoinScorerOptions{}.retrained_shaded_threshold);
  EXPECT_NE(test::trace_of(low, 1, 20, JoinStage::kChosen), nullptr);
  s = test::strand_of(low);
  EXPECT_EQ(s.at(1), s.at(20));
}

// The bar is the shaded drawings' only: a flat drawing's joins do not
// move with it.
TEST(RetrainedShadedBar, FlatDrawingsKeepTheirBar) {
  const AnnotatedCase c = test::generated_case(2077, generator::Shading::kFlat);
  EXPECT_EQ(test::strand_of(run(c, 0.5)), test::strand_of(run(c, 0.95)));
}

TEST(RetrainedShadedBar, BadBarIsRefused) {
  const AnnotatedCase c = test::generated_case(2077, generator::Shading::kTwoTone);
  Options o;
  o.join_scorer.retrained_shaded_threshold = 0.0;
  test::expect_invalid(o, "retrained_shaded_threshold = 0");
  EXPECT_THROW(complete_strands(test::input_from_case(c), o), Error);
  o.join_scorer.retrained_shaded_threshold = 1.0;
  test::expect_invalid(o, "retrained_shaded_threshold = 1");
}

}  // namespace
}  // namespace hair25d::completion
