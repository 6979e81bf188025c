// The net for the strand-join candidates over the angle limit
// (JoinScorerOptions::max_angle_deg, wide_join_scorer; retrained in
// session 29 on the wide candidates of dev seeds 4000-5399 of both
// relations): on drawings it never saw it orders those candidates by
// whether their two pieces are one strand far better than the hand cost,
// and what it accepts at wide_threshold is right.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>
#include <vector>

#include "annotated_eval.h"
#include "feature_index.h"
#include "generated_case.h"
#include "hair25d/completion/completion.h"
#include "hair25d/completion/join_scorer.h"
#include "hair25d/generator/generator.h"

namespace hair25d::completion {
namespace {

// Area under the ROC curve of `score` (higher = one strand), ties half.
double auc(const std::vector<double>& score, const std::vector<int>& label) {
  std::vector<int> idx(score.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::sort(idx.begin(), idx.end(), [&](int a, int b) { return score[a] < score[b]; });
  double rank_sum = 0, pos = 0;
  for (std::size_t i = 0; i < idx.size();) {
    std::size_t j = i;
    while (j < idx.size() && score[idx[j]] == score[idx[i]]) ++j;
    for (std::size_t k = i; k < j; ++k)
      if (label[idx[k]]) rank_sum += 0.5 * (i + j - 1) + 1, ++pos;
    i = j;
  }
  const double neg = static_cast<double>(score.size()) - pos;
  return pos > 0 && neg > 0 ? (rank_sum - pos * (pos + 1) / 2) / (pos * neg) : 0.5;
}

// Seeds 5000 and 5001 in the four shadings (train_join_scorer's held-out ev5000 set):
// every wide candidate (worst tangent angle over max_join_angle_deg) as the
// training data records it, the scorer off so that nothing is rescued.
TEST(JoinScorerWide, NetSeparatesCandidatesOverTheAngleLimit) {
  const int worst = test::feature_index("worst_angle");
  std::vector<double> net, hand;
  std::vector<int> label;
  for (const std::uint64_t seed : {5000u, 5001u})
    for (const generator::Shading shading :
         {generator::Shading::kFlat, generator::Shading::kTwoTone, generator::Shading::kGradient,
          generator::Shading::kScreentone}) {
      const AnnotatedCase c = test::generated_case(seed, shading);
      std::map<int, int> strand;
      for (const AnnotatedRegion& reg : c.region_list) strand[reg.id] = reg.strand;
      Options o;
      o.inpaint_strands = false;
      o.inpaint_background = false;
      o.join_scorer.enabled = false;
      o.join_scorer.record = true;
      o.join_scorer.band_high = 5.0;
      o.join_scorer.max_angle_deg = 120.0;
      const Result r = complete_strands(test::input_from_case(c), o);
      for (const JoinCandidate& j : r.join_candidates) {
        if (!(j.features[worst] > 1.0f)) continue;
        EXPECT_LE(j.hand_cost, o.join_scorer.wide_band_high);
        net.push_back(join_probability(wide_join_scorer(), j.features));
        hand.push_back(-j.hand_cost);
        label.push_back(strand.at(j.region_a) == strand.at(j.region_b));
      }
    }
  const int right = std::accumulate(label.begin(), label.end(), 0);
  const double by_net = auc(net, label), by_hand = auc(hand, label);
  int taken_right = 0, taken_wrong = 0;
  const double t = JoinScorerOptions{}.wide_threshold;
  for (std::size_t i = 0; i < label.size(); ++i)
    if (net[i] >= t) ++(label[i] ? taken_right : taken_wrong);
  std::printf("%zu wide candidates (%d one strand): AUC hand %.3f, net %.3f; p >= %.2f %d / %d\n",
              label.size(), right, by_hand, by_net, t, taken_right, taken_wrong);
  ASSERT_GE(right, 20);
  ASSERT_GE(static_cast<int>(label.size()) - right, 10);
  // Session 29's net: 81 candidates (65 one strand), AUC hand cost 0.733,
  // net 0.946, 30 right / 0 wrong at p >= 0.95; session 18's (trained on
  // 5275 candidates) gave AUC 0.897 and 17 right / 2 wrong.
  EXPECT_GT(by_net, 0.93);
  EXPECT_GT(by_net, by_hand + 0.15);
  EXPECT_EQ(taken_wrong, 0);
  EXPECT_GE(taken_right, 25);
}

// The strands' regions, in order.
std::vector<std::vector<int>> strands_of(const Result& r) {
  std::vector<std::vector<int>> out;
  for (const CompletedStrand& s : r.strands) out.push_back(s.regions);
  return out;
}

// Wide candidates join only off screentone (session 29): with a threshold
// any of them passes, the screentone drawing's strands are those of the
// wide candidates off, while the flat drawing gains joins; recorded, the
// screentone drawing's wide candidates are scored but never joined.
TEST(JoinScorerWide, NoWideJoinsOnScreentone) {
  auto run = [](const AnnotatedCase& c, double max_angle, bool record) {
    Options o;
    o.inpaint_strands = false;
    o.inpaint_background = false;
    o.join_scorer.max_angle_deg = max_angle;
    o.join_scorer.wide_threshold = 0.01;
    o.join_scorer.record = record;
    return complete_strands(test::input_from_case(c), o);
  };
  const AnnotatedCase flat = test::generated_case(5000, generator::Shading::kFlat);
  EXPECT_GT(run(flat, 120.0, false).joins, run(flat, 0.0, false).joins);
  const AnnotatedCase screentone = test::generated_case(5000, generator::Shading::kScreentone);
  const Result off = run(screentone, 0.0, false), on = run(screentone, 120.0, false);
  EXPECT_EQ(on.joins, off.joins);
  EXPECT_EQ(strands_of(on), strands_of(off));
  const Result recorded = run(screentone, 120.0, true);
  const int worst = test::feature_index("worst_angle");
  int wide = 0;
  for (const JoinCandidate& j : recorded.join_candidates) {
    if (!(j.features[worst] > 1.0f)) continue;
    ++wide;
    EXPECT_GE(j.probability, 0.0);  // asked
    EXPECT_TRUE(std::isinf(j.cost));
    EXPECT_FALSE(j.chosen);
  }
  EXPECT_GT(wide, 0);
}

}  // namespace
}  // namespace hair25d::completion
