// Session 37 (JoinScorerOptions::cover_flat_threshold,
// cover_screentone_threshold): cover refusals' second chances on flat and
// screentone drawings, judged by `cover_plain_join_scorer` (trained on
// those two shadings' second chances alone) at each shading's own bar;
// two-tone and gradient drawings keep session 36's net and bar.
#include <gtest/gtest.h>

#include <cmath>
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
#include "trace_of.h"

namespace hair25d::completion {
namespace {

std::set<std::pair<int, int>> chosen(const AnnotatedCase& c, double flat, double screentone,
                                     bool all_shadings = false) {
  Options o = test::joins_only();
  o.trace_joins = true;
  o.join_scorer.cover_flat_threshold = flat;
  o.join_scorer.cover_screentone_threshold = screentone;
  o.join_scorer.cover_refusal_all_shadings = all_shadings;
  return test::traced_pairs(complete_strands(test::input_from_case(c), o), JoinStage::kChosen);
}

// Pairs the cover refused with both bars off that a bar any candidate
// passes joins: `flat` and `screentone` set that bar (else 1).
int gained(const AnnotatedCase& c, bool flat, bool screentone) {
  Options o = test::joins_only();
  o.trace_joins = true;
  o.join_scorer.cover_flat_threshold = 1.0;
  o.join_scorer.cover_screentone_threshold = 1.0;
  const Result off = complete_strands(test::input_from_case(c), o);
  const auto refused = test::traced_pairs(off, JoinStage::kCover),
             before = test::traced_pairs(off, JoinStage::kChosen);
  int n = 0;
  for (const auto& pair : chosen(c, flat ? 1e-6 : 1.0, screentone ? 1e-6 : 1.0))
    n += !before.count(pair) && refused.count(pair);
  return n;
}

// Each bar acts on its own shading only.
TEST(CoverPlain, EachBarOnItsOwnShading) {
  int flat_by_flat = 0, flat_by_screentone = 0, tone_by_tone = 0, tone_by_flat = 0;
  for (const std::uint64_t seed : {2000u, 2001u, 2002u, 2003u}) {
    const AnnotatedCase flat = test::generated_case(seed, generator::Shading::kFlat);
    const AnnotatedCase tone = test::generated_case(seed, generator::Shading::kScreentone);
    flat_by_flat += gained(flat, true, false);
    flat_by_screentone += gained(flat, false, true);
    tone_by_tone += gained(tone, false, true);
    tone_by_flat += gained(tone, true, false);
  }
  EXPECT_GT(flat_by_flat, 0);
  EXPECT_EQ(flat_by_screentone, 0);
  EXPECT_GT(tone_by_tone, 0);
  EXPECT_EQ(tone_by_flat, 0);
}

// Dev flat 2057 (+5 right pairs at 0.95 with the annotation's relations):
// at the default flat bar the net joins pairs the cover refused, each of
// one strand in the annotation, with p over the bar. An untrained net or
// the bar not read on flat drawings fails it.
TEST(CoverPlain, RightFlatJoinsAtTheBar) {
  const AnnotatedCase c = test::generated_case(2057, generator::Shading::kFlat);
  std::map<int, int> strand;
  for (const AnnotatedRegion& r : c.region_list) strand[r.id] = r.strand;
  Options o = test::joins_only();
  o.trace_joins = true;
  o.join_scorer.cover_flat_threshold = 1.0;
  const Result off = complete_strands(test::input_from_case(c), o);
  const double bar = JoinScorerOptions{}.cover_flat_threshold;
  o.join_scorer.cover_flat_threshold = bar;
  const Result on = complete_strands(test::input_from_case(c), o);
  const std::vector<JoinTrace> gained = test::cover_gains(off, on);
  for (const JoinTrace& t : gained) {
    EXPECT_GE(t.probability, bar);
    EXPECT_EQ(strand.at(t.region_a), strand.at(t.region_b)) << t.region_a << "-" << t.region_b;
  }
  EXPECT_FALSE(gained.empty());
}

// Two-tone and gradient drawings are session 36's whatever the two bars.
TEST(CoverPlain, ShadedDrawingsUnchanged) {
  for (const generator::Shading s : {generator::Shading::kTwoTone, generator::Shading::kGradient})
    for (const std::uint64_t seed : {2036u, 2002u}) {
      const AnnotatedCase c = test::generated_case(seed, s);
      EXPECT_EQ(chosen(c, 1.0, 1.0), chosen(c, 1e-6, 1e-6)) << seed;
    }
}

// cover_refusal_all_shadings keeps session 36's net and bar on flat
// drawings: the flat bar then changes nothing.
TEST(CoverPlain, AllShadingsKeepsSession36Net) {
  const AnnotatedCase c = test::generated_case(2001, generator::Shading::kFlat);
  EXPECT_EQ(chosen(c, 1.0, 1.0, true), chosen(c, 1e-6, 1e-6, true));
}

TEST(CoverPlain, BadThresholdsAreRefused) {
  for (double t : {0.0, 1.5, -0.2, std::nan("")}) {
    Options o;
    o.join_scorer.cover_flat_threshold = t;
    test::expect_invalid(o, "cover_flat_threshold");
    o = Options{};
    o.join_scorer.cover_screentone_threshold = t;
    test::expect_invalid(o, "cover_screentone_threshold");
  }
}

}  // namespace
}  // namespace hair25d::completion
