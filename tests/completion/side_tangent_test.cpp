// Session 31 (JoinScorerOptions::side_threshold): an edge pair refused by
// the 70° angle whose angles fit once an unreliable edge takes its side
// tangent (the middle line of the two side outlines leaving the cut) is a
// candidate the band's net alone may join, off screentone drawings only.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "annotated_eval.h"
#include "generated_case.h"
#include "hair25d/completion/completion.h"
#include "hair25d/completion/join_scorer.h"
#include "hair25d/generator/generator.h"
#include "invalid_options.h"
#include "joins_only.h"

namespace hair25d::completion {
namespace {

Result run(const AnnotatedCase& c, double side_threshold) {
  Options o = test::joins_only();
  o.trace_joins = true;
  o.join_scorer.side_threshold = side_threshold;
  return complete_strands(test::input_from_case(c), o);
}

std::set<std::pair<int, int>> chosen(const Result& r) {
  std::set<std::pair<int, int>> out;
  for (const JoinTrace& t : r.join_trace)
    if (t.stage == JoinStage::kChosen) out.insert({t.region_a, t.region_b});
  return out;
}

// Off (1), nothing changes; with a bar any candidate passes, a flat drawing
// gains joins of pairs whose own tangents were refused by the angle, and
// every pair main chose is still chosen or its edge was taken by one of them.
TEST(SideTangents, AngleRefusedPairsJoinOnlyWhenOn) {
  int gained = 0;
  for (const std::uint64_t seed : {2000u, 2001u, 2002u, 2003u, 2004u}) {
    const AnnotatedCase c = test::generated_case(seed, generator::Shading::kFlat);
    const Result off = run(c, 1.0), on = run(c, 0.01);
    EXPECT_GE(on.joins, off.joins) << seed;
    std::set<std::pair<int, int>> angle_refused;
    for (const JoinTrace& t : off.join_trace)
      if (t.stage == JoinStage::kAngle) angle_refused.insert({t.region_a, t.region_b});
    for (const auto& pair : chosen(on))
      if (!chosen(off).count(pair) && angle_refused.count(pair)) ++gained;
  }
  EXPECT_GT(gained, 0);
}

// Not on screentone drawings: the same strands with any bar.
TEST(SideTangents, NoneOnScreentone) {
  const AnnotatedCase c = test::generated_case(2000, generator::Shading::kScreentone);
  const Result off = run(c, 1.0), on = run(c, 0.01);
  EXPECT_EQ(on.joins, off.joins);
  EXPECT_EQ(chosen(on), chosen(off));
}

TEST(SideTangents, BadThresholdIsRefused) {
  Options o;
  for (double t : {0.0, 1.5, -0.2}) {
    o.join_scorer.side_threshold = t;
    test::expect_invalid(o, "side_threshold");
  }
}

}  // namespace
}  // namespace hair25d::completion
