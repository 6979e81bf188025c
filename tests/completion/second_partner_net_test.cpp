// Session 37 (JoinScorerOptions::second_partner_threshold): a candidate the
// greedy matching refuses because an earlier join took the atoms of one of
// its edges is judged by a net trained on such candidates alone
// (`second_partner_join_scorer`), with inputs saying how sure the scorer
// was of it and of the first join and how the two partners lie along the
// cut (second_partner.h).
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <utility>

#include "annotated_eval.h"
#include "feature_index.h"
#include "generated_case.h"
#include "hair25d/completion/completion.h"
#include "hair25d/completion/join_scorer.h"
#include "hair25d/core/error.h"
#include "hair25d/generator/generator.h"
#include "invalid_options.h"
#include "joins_only.h"
#include "strand_of.h"
#include "trace_of.h"

namespace hair25d::completion {
namespace {

constexpr int kSecondCut = 64;     // join_feature_name: "second_cut"
constexpr int kCoverRetried = 54;  // "cover_retried" (session 36)

Result run(const AnnotatedCase& c, double threshold, bool all_shadings = false) {
  Options o = test::joins_only();
  o.trace_joins = true;
  o.join_scorer.second_partner_threshold = threshold;
  o.join_scorer.second_partner_all_shadings = all_shadings;
  return complete_strands(test::input_from_case(c), o);
}

// Recorded with the scorer on (the model's matching) as rows of their own:
// `second_cut` set, the inputs in their ranges, the pair also recorded as
// an ordinary row before it (the scorer's judgement of it); every other row
// has inputs 64 on at 0. With the scorer off (hand costs alone: not the
// model's matching) there are none.
TEST(SecondPartnerNet, RecordedAsRowsOfTheirOwn) {
  Options o = test::joins_only();
  o.join_scorer.record = true;
  o.join_scorer.second_partner_threshold = 1.0;
  int seconds = 0;
  for (const std::uint64_t seed : {4000u, 4001u, 4002u, 4005u}) {
    const AnnotatedCase c = test::generated_case(seed, generator::Shading::kGradient);
    const Result r = complete_strands(test::input_from_case(c), o);
    std::set<std::pair<int, int>> ordinary;
    for (const JoinCandidate& j : r.join_candidates) {
      if (j.features[kSecondCut] < 0.5f) {
        // Inputs 75-76 (session 39) are every gradient candidate's.
        for (int k = kSecondCut; k < 75; ++k) EXPECT_EQ(j.features[k], 0.0f) << k;
        ordinary.insert({j.region_a, j.region_b});
        continue;
      }
      ++seconds;
      EXPECT_TRUE(ordinary.count({j.region_a, j.region_b})) << j.region_a << "-" << j.region_b;
      EXPECT_FALSE(j.chosen);  // the net is off
      EXPECT_GE(j.features[test::feature_index("faced_gap")], 0.0f);
      EXPECT_GE(j.features[test::feature_index("faced_overlap")], 0.0f);
      EXPECT_LE(j.features[test::feature_index("faced_overlap")], 1.0f);
      EXPECT_GT(j.features[test::feature_index("cut_width_share")], 0.0f);
      EXPECT_GE(j.features[test::feature_index("partners_side")], -1.0f - 1e-5f);
      EXPECT_LE(j.features[test::feature_index("partners_side")], 1.0f + 1e-5f);
      EXPECT_GE(j.features[test::feature_index("first_partners")], 1.0f);
    }
  }
  EXPECT_GT(seconds, 0);
  o.join_scorer.enabled = false;
  const Result off = complete_strands(
      test::input_from_case(test::generated_case(4005, generator::Shading::kGradient)), o);
  for (const JoinCandidate& j : off.join_candidates) EXPECT_EQ(j.features[kSecondCut], 0.0f);
}

// On flat drawings, whatever the bar, no pair moves unless
// second_partner_all_shadings.
TEST(SecondPartnerNet, NotOnFlatDrawings) {
  const AnnotatedCase flat = test::generated_case(4005, generator::Shading::kFlat);
  const Options o = test::joins_only();
  const Result plain = complete_strands(test::input_from_case(flat), o);
  EXPECT_EQ(test::strand_of(run(flat, 1.0)), test::strand_of(plain));
  EXPECT_EQ(test::strand_of(run(flat, 1e-6)), test::strand_of(plain));
}

// At a bar every candidate passes, shaded drawings gain joins of pairs the
// matching refused as "atom taken" with the net off (dev two-tone drawings
// that gained pairs at 0.9).
TEST(SecondPartnerNet, JoinedOnlyWhenOn) {
  int gained = 0;
  for (const std::uint64_t seed : {3023u, 3051u, 3076u}) {
    const AnnotatedCase c = test::generated_case(seed, generator::Shading::kTwoTone);
    const Result off = run(c, 1.0), on = run(c, 1e-6);
    const auto taken = test::traced_pairs(off, JoinStage::kAtomTaken),
               before = test::traced_pairs(off, JoinStage::kChosen);
    for (const auto& pair : test::traced_pairs(on, JoinStage::kChosen))
      if (!before.count(pair) && taken.count(pair)) ++gained;
  }
  EXPECT_GT(gained, 0);
}

// The default options join at the bar of session 37.
TEST(SecondPartnerNet, OnByDefault) {
  EXPECT_EQ(JoinScorerOptions{}.second_partner_threshold, 0.9);
  EXPECT_TRUE(JoinScorerOptions{}.second_partner_last);
}

// Dev two-tone 3080 (+12 right pairs at 0.9 with the annotation's
// relations): 15-25 is refused as "atom taken" with the net off (its cut
// taken by an earlier join) and 1 and 30 (one strand in the annotation)
// stay apart; at the bar of session 37 the net joins 15-25, which brings
// 1 and 30 together, and every pair it adds is of one strand. Fails with
// an untrained net (p 0.5 everywhere).
TEST(SecondPartnerNet, RightJoinsAtTheBar) {
  const AnnotatedCase c = test::generated_case(3080, generator::Shading::kTwoTone);
  std::map<int, int> truth;
  for (const AnnotatedRegion& r : c.region_list) truth[r.id] = r.strand;
  ASSERT_EQ(truth.at(1), truth.at(30));
  const Result off = run(c, 1.0);
  EXPECT_NE(test::trace_of(off, 15, 25, JoinStage::kAtomTaken), nullptr);
  EXPECT_EQ(test::trace_of(off, 15, 25, JoinStage::kChosen), nullptr);
  const std::map<int, int> before = test::strand_of(off);
  EXPECT_NE(before.at(1), before.at(30));
  const Result on = run(c, 0.9);
  EXPECT_NE(test::trace_of(on, 15, 25, JoinStage::kChosen), nullptr);
  const std::map<int, int> s = test::strand_of(on);
  EXPECT_EQ(s.at(1), s.at(30));
  int added = 0;
  for (const auto& [a, sa] : s)
    for (const auto& [b, sb] : s)
      if (a < b && sa == sb && before.at(a) != before.at(b)) {
        ++added;
        EXPECT_EQ(truth.at(a), truth.at(b)) << a << "-" << b;
      }
  EXPECT_GT(added, 0);
}

TEST(SecondPartnerNet, BadThresholdIsRefused) {
  for (const double t : {0.0, -0.5, 1.5}) {
    Options o;
    o.join_scorer.second_partner_threshold = t;
    test::expect_invalid(o, "second_partner_threshold");
    EXPECT_THROW(
        complete_strands(
            test::input_from_case(test::generated_case(4005, generator::Shading::kGradient)), o),
        Error);
  }
}

TEST(SecondPartnerNet, SecondCutIsInput64) {
  EXPECT_STREQ(join_feature_name(kSecondCut), "second_cut");
  EXPECT_STREQ(join_feature_name(74), "first_partners");
  EXPECT_STREQ(join_feature_name(kCoverRetried), "cover_retried");
}

}  // namespace
}  // namespace hair25d::completion
