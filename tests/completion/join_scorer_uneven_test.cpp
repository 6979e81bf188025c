// The uneven gradient net (join_scorer.h, session 26): its generated file,
// and the candidates off the gradient by uneven windows that it adds to the
// default net's, over the band too.
#include <gtest/gtest.h>

#include <algorithm>

#include "annotated_eval.h"
#include "hair25d/completion/completion.h"
#include "hair25d/completion/join_scorer.h"
#include "hair25d/generator/generator.h"
#include "weights_file.h"

namespace hair25d::completion {
namespace {

TEST(JoinScorerUneven, WeightsFileIsTheNetsPrinted) {
  ASSERT_FALSE(uneven_join_scorers().empty());
  const std::string printed = test::generated_part(
      join_scorer_ensemble_source(uneven_join_scorers(), "x", "uneven_join_scorers"));
  EXPECT_FALSE(printed.empty());
  EXPECT_EQ(test::generated_part(test::committed_source("join_scorer_uneven_weights.cpp")),
            printed);
}

// The uneven gradient candidates, told by their inputs (join_paint.h:
// off the gradient, step_excess > 1, by uneven slopes, slope_ratio < 0.25).
bool uneven(const JoinCandidate& j) { return j.features[44] > 1.0f && j.features[45] < 0.25f; }

Result complete(const AnnotatedCase& c, double threshold, double band_high) {
  Options o;
  o.inpaint_strands = false;
  o.inpaint_background = false;
  o.join_scorer.record = true;
  o.join_scorer.uneven_threshold = threshold;
  o.join_scorer.uneven_band_high = band_high;
  return complete_strands(test::input_from_case(c), o);
}

// Generated gradient drawing 2015 (800 x 640, 20 strands) has uneven
// candidates in the band and over it. With the uneven net's threshold low
// (0.05) every one that the default net refuses (p < 0.2, or not asked
// over the band) joins exactly when the uneven net's probability u reaches
// it, ranked by u; with the threshold 1 none does. Over the band such
// candidates are seen only up to uneven_band_high.
TEST(JoinScorerUneven, AddsWhatTheDefaultNetRefuses) {
  generator::Options g;
  g.width = 800;
  g.height = 640;
  g.strand_count = 20;
  g.seed = 2015;
  g.shading = generator::Shading::kGradient;
  g.strand_masks = false;
  const AnnotatedCase c = generator::generate_case(g);
  const JoinScorerOptions s;
  const double limit = Options{}.max_join_cost, band = s.band_high - s.band_low;
  for (const double threshold : {0.05, 1.0}) {
    SCOPED_TRACE(threshold);
    int added = 0, over_band = 0;
    for (const JoinCandidate& j : complete(c, threshold, 6.0).join_candidates) {
      if (!uneven(j)) continue;
      over_band += j.hand_cost > s.band_high;
      if (j.probability >= 0.2) {
        EXPECT_LE(j.cost, limit);
        continue;
      }
      EXPECT_EQ(j.probability<0, j.hand_cost> s.band_high);
      const double u = join_probability(uneven_join_scorers(), j.features);
      if (threshold < 1 && u >= threshold) {
        EXPECT_DOUBLE_EQ(j.cost, limit + (threshold - u) * band);
        ++added;
      } else {
        EXPECT_EQ(j.cost, j.hand_cost);
      }
    }
    EXPECT_GT(over_band, 0);
    if (threshold < 1)
      EXPECT_GT(added, 0);
    else
      EXPECT_EQ(added, 0);
  }
  for (const JoinCandidate& j : complete(c, 0.05, s.band_high).join_candidates)
    EXPECT_LE(j.hand_cost, s.band_high);
}

}  // namespace
}  // namespace hair25d::completion
