// The join scorer's ensembles (join_scorer.h, sessions 25-26): the mean of
// their nets, their generated files, and the rescues they add: the
// screentone nets' on screentone drawings, the paint nets' on the others.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "annotated_eval.h"
#include "generated_case.h"
#include "hair25d/completion/completion.h"
#include "hair25d/completion/join_scorer.h"
#include "hair25d/core/error.h"
#include "hair25d/generator/generator.h"
#include "weights_file.h"

namespace hair25d::completion {
namespace {

// A net whose probability is logistic(b2) whatever the input.
JoinScorerNet constant_net(float b2) {
  JoinScorerNet net;
  net.b2 = b2;
  return net;
}

TEST(JoinScorerEnsemble, ProbabilityIsTheMeanOfTheNets) {
  const JoinFeatures f{};
  const std::vector<JoinScorerNet> two{constant_net(0.0f), constant_net(std::log(3.0f))};
  EXPECT_NEAR(join_probability(two[0], f), 0.5, 1e-6);
  EXPECT_NEAR(join_probability(two[1], f), 0.75, 1e-6);
  EXPECT_NEAR(join_probability(std::span<const JoinScorerNet>(two), f), 0.625, 1e-6);
  EXPECT_NEAR(join_probability(std::span<const JoinScorerNet>(two).first(1), f), 0.5, 1e-6);
  EXPECT_THROW(join_probability(std::span<const JoinScorerNet>{}, f), Error);
}

// The committed file is the ensemble printed again, byte for byte below its
// comment; its nets are of different training seeds.
TEST(JoinScorerEnsemble, WeightsFileIsTheEnsemblePrinted) {
  const std::span<const JoinScorerNet> nets = ensemble_join_scorers();
  ASSERT_GE(nets.size(), 2u);
  for (std::size_t i = 1; i < nets.size(); ++i) EXPECT_NE(nets[i].w1[0][0], nets[0].w1[0][0]);
  const std::string printed = test::generated_part(join_scorer_ensemble_source(nets, "x"));
  EXPECT_FALSE(printed.empty());
  EXPECT_EQ(test::generated_part(test::committed_source("join_scorer_ensemble_weights.cpp")),
            printed);
  EXPECT_NE(join_scorer_ensemble_source({}, "x").find("return {};"), std::string::npos);
}

TEST(JoinScorerEnsemble, PaintWeightsFileIsTheEnsemblePrinted) {
  const std::span<const JoinScorerNet> nets = paint_ensemble_join_scorers();
  ASSERT_GE(nets.size(), 2u);
  for (std::size_t i = 1; i < nets.size(); ++i) EXPECT_NE(nets[i].w1[0][0], nets[0].w1[0][0]);
  // Other nets than the screentone ones (trained on other drawings).
  EXPECT_NE(nets[0].w1[0][0], ensemble_join_scorers()[0].w1[0][0]);
  const std::string printed =
      test::generated_part(join_scorer_ensemble_source(nets, "x", "paint_ensemble_join_scorers"));
  EXPECT_EQ(test::generated_part(test::committed_source("join_scorer_paint_ensemble_weights.cpp")),
            printed);
}

// With the default net's threshold out of reach (0.99) and the ensembles'
// low (screentone 0.05, paint 0.06, cel 0.07), a band candidate over the
// limit is rescued exactly when the mean of the drawing's ensemble reaches
// its threshold, ranked by it, and only on the drawings
// JoinScorerOptions::ensemble names: kScreentone the screentone ones (the
// others keep every hand cost), kEach those with the screentone nets and the
// others with the paint nets (at the cel threshold on a two-tone drawing),
// which judge only pieces compared as flat paint.
TEST(JoinScorerEnsemble, RescuesOnTheDrawingsItIsAskedFor) {
  using Ensemble = JoinScorerOptions::Ensemble;
  const JoinScorerOptions s;
  const double limit = Options{}.max_join_cost;
  int flat_paint = 0;
  while (std::string(join_feature_name(flat_paint)) != "flat_paint") ++flat_paint;
  for (const generator::Shading shading :
       {generator::Shading::kScreentone, generator::Shading::kFlat, generator::Shading::kTwoTone,
        generator::Shading::kGradient}) {
    const bool screentone = shading == generator::Shading::kScreentone;
    SCOPED_TRACE(static_cast<int>(shading));
    const AnnotatedCase c = test::generated_case(2004, shading);
    for (const auto ensemble : {Ensemble::kScreentone, Ensemble::kNone, Ensemble::kEach}) {
      SCOPED_TRACE(static_cast<int>(ensemble));
      Options o;
      o.inpaint_strands = false;
      o.inpaint_background = false;
      o.join_scorer.record = true;
      o.join_scorer.threshold = o.join_scorer.screentone_threshold = 0.99;
      o.join_scorer.ensemble = ensemble;
      // Side-tangent candidates have their own bar (side_tangent_test.cpp),
      // and so has the second opinion (join_scorer_second_test.cpp).
      o.join_scorer.side_threshold = 1.0;
      o.join_scorer.second_threshold = 1.0;
      // Angle refusals' second chances have their own net (angle_refusal_test.cpp).
      o.join_scorer.angle_refusal_threshold = 1.0;
      // So have cover refusals' (cover_refusal_test.cpp).
      o.join_scorer.cover_refusal_threshold = 1.0;
      o.join_scorer.cover_flat_threshold = 1.0;
      // So has the gradient pieces' fields' rule (field_cross_test.cpp).
      o.join_scorer.field_cross_max = 0.0;
      // The default net judges the band of every drawing without screentone.
      o.join_scorer.retrained_shaded = false;
      o.join_scorer.ensemble_threshold = 0.05;
      o.join_scorer.paint_ensemble_threshold = 0.06;
      o.join_scorer.cel_ensemble_threshold = 0.07;
      const Result r = complete_strands(test::input_from_case(c), o);
      const bool on =
          ensemble == Ensemble::kEach || (screentone && ensemble == Ensemble::kScreentone);
      const std::span<const JoinScorerNet> nets =
          screentone ? ensemble_join_scorers() : paint_ensemble_join_scorers();
      // A two-tone drawing's pieces share a cel shadow: the cel threshold.
      const double t = screentone ? 0.05 : shading == generator::Shading::kTwoTone ? 0.07 : 0.06;
      int rescued = 0, not_asked = 0;
      for (const JoinCandidate& j : r.join_candidates) {
        // The default net's own rescues (p >= 0.99) are not the ensemble's.
        if (j.hand_cost < s.band_low || j.hand_cost > s.band_high || j.probability < 0 ||
            j.probability >= 0.99)
          continue;
        const double q = join_probability(nets, j.features);
        const bool asked = screentone || j.features[flat_paint] > 0.5f;
        if (on && asked && q >= t) {
          EXPECT_DOUBLE_EQ(j.cost,
                           std::min(j.hand_cost, limit + (t - q) * (s.band_high - s.band_low)));
          rescued += j.hand_cost > limit;
        } else {
          EXPECT_EQ(j.cost, j.hand_cost);
          not_asked += on && !asked && q >= t && j.hand_cost > limit;
        }
      }
      // The gradient's pieces are compared by their fits: the paint nets
      // would rescue some of them, and are not asked.
      const bool gradient = shading == generator::Shading::kGradient;
      if (on)
        EXPECT_GT(gradient ? not_asked : rescued, 0);
      else
        EXPECT_EQ(rescued, 0);
    }
  }
}

}  // namespace
}  // namespace hair25d::completion
