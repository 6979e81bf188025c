// Session 31: the shaded net (shaded_join_scorer) judges the band and its
// edges on two-tone and gradient drawings, told from their paint, with
// JoinScorerOptions::shaded; flat drawings keep the default net in the
// band and the retrained one at its edges.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "annotated_eval.h"
#include "generated_case.h"
#include "hair25d/completion/completion.h"
#include "hair25d/completion/join_scorer.h"
#include "hair25d/generator/generator.h"
#include "invalid_options.h"
#include "same_joins.h"

namespace hair25d::completion {
namespace {

Result run(const AnnotatedCase& c, bool shaded, double shaded_threshold, double veto_below,
           double rescue_threshold, bool retrained_shaded = false) {
  Options o;
  o.inpaint_strands = false;
  o.inpaint_background = false;
  o.join_scorer.record = true;
  // The nets alone: the ensembles' rescues are join_scorer_ensemble_test.cpp's.
  o.join_scorer.ensemble = JoinScorerOptions::Ensemble::kNone;
  // Side-tangent candidates have their own bar (side_tangent_test.cpp).
  o.join_scorer.side_threshold = 1.0;
  // Angle refusals' second chances have their own net (angle_refusal_test.cpp).
  o.join_scorer.angle_refusal_threshold = 1.0;
  // So have cover refusals' (cover_refusal_test.cpp).
  o.join_scorer.cover_refusal_threshold = 1.0;
  o.join_scorer.cover_flat_threshold = 1.0;
  o.join_scorer.shaded = shaded;
  o.join_scorer.shaded_threshold = shaded_threshold;
  o.join_scorer.shaded_veto_below = veto_below;
  o.join_scorer.shaded_rescue_threshold = rescue_threshold;
  o.join_scorer.retrained_shaded = retrained_shaded;
  return complete_strands(test::input_from_case(c), o);
}

// Each candidate the nets were asked about was asked of its drawing's net:
// the band's (the shaded net on a shaded drawing, else the default one),
// the edges' (the shaded net, else the retrained one). Returns how many
// band candidates over the limit were ranked under it (rescued) and how
// many under the band were refused.
struct Counts {
  int asked = 0, rescued = 0, vetoed = 0;
};
Counts judged_by(const Result& r, const JoinScorerNet& band, const JoinScorerNet& edges) {
  const JoinScorerOptions s;
  const double limit = Options{}.max_join_cost;
  Counts n;
  for (const JoinCandidate& j : r.join_candidates) {
    // Session 37: a cut's second partner's own row (input 64 `second_cut`),
    // judged by its own net.
    if (j.probability < 0 || j.features[64] > 0.5f) continue;
    ++n.asked;
    const bool in_band = j.hand_cost >= s.band_low && j.hand_cost <= s.band_high;
    EXPECT_DOUBLE_EQ(j.probability, join_probability(in_band ? band : edges, j.features))
        << "hand cost " << j.hand_cost;
    if (in_band && j.hand_cost > limit && j.cost <= limit) ++n.rescued;
    if (j.hand_cost < s.band_low && std::isinf(j.cost)) {
      EXPECT_FALSE(j.chosen);
      ++n.vetoed;
    }
  }
  return n;
}

TEST(JoinScorerShaded, ShadedDrawingsAreJudgedByTheShadedNet) {
  for (const generator::Shading shading :
       {generator::Shading::kTwoTone, generator::Shading::kGradient}) {
    SCOPED_TRACE(static_cast<int>(shading));
    const AnnotatedCase c = test::generated_case(2004, shading);
    // Low bars: the shaded net rescues the band's candidates over the limit
    // and refuses nearly every one under it; high bars: it rescues fewer
    // and refuses none.
    const Counts low =
        judged_by(run(c, true, 0.05, 0.999, 0.05), shaded_join_scorer(), shaded_join_scorer());
    const Counts high =
        judged_by(run(c, true, 0.999, 0.0, 1.0), shaded_join_scorer(), shaded_join_scorer());
    EXPECT_GT(low.asked, 0);
    EXPECT_GT(low.rescued, high.rescued);
    EXPECT_GT(low.vetoed, 0);
    EXPECT_EQ(high.vetoed, 0);
    // Off, the committed nets judge the drawing as before.
    judged_by(run(c, false, 0.05, 0.999, 0.05), default_join_scorer(), retrained_join_scorer());
    // With retrained_shaded, the retrained net judges the band there.
    judged_by(run(c, false, 0.05, 0.999, 0.05, true), retrained_join_scorer(),
              retrained_join_scorer());
  }
}

// A flat drawing is not shaded: its joins are the same with the shaded net
// on, whatever its bars, and with retrained_shaded.
TEST(JoinScorerShaded, FlatDrawingsKeepTheirNets) {
  const AnnotatedCase c = test::generated_case(2004, generator::Shading::kFlat);
  const Result off = run(c, false, 0.9, 0.2, 0.97);
  const Result on = run(c, true, 0.05, 0.999, 0.05, true);
  judged_by(on, default_join_scorer(), retrained_join_scorer());
  test::expect_same_joins(off, on);
}

TEST(JoinScorerShaded, BadBarsAreRefused) {
  JoinScorerOptions s;
  std::string why;
  s.shaded_threshold = 1.0;
  test::expect_invalid(s, "shaded_threshold");
  s = {};
  s.shaded_veto_below = -0.1;
  test::expect_invalid(s, "shaded_veto_below");
  s = {};
  s.shaded_rescue_threshold = 0.0;
  test::expect_invalid(s, "shaded_rescue_threshold");
  s.shaded_rescue_threshold = 1.0;  // none rescued: valid
  EXPECT_TRUE(s.is_valid(&why)) << why;
}

}  // namespace
}  // namespace hair25d::completion
