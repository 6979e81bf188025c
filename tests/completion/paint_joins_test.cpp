// The colour step of strand joins (joins.cpp, `paint_step`): pieces of one
// strand are compared by how they are painted — the flat colours of cel
// paint (a base and its shadow band), or a gradient along the strand — not
// by the mean colour of windows along their cuts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include "hair25d/completion/completion.h"
#include "synthetic.h"

namespace hair25d::completion {
namespace {

// The shared synthetic drawings and helpers (synthetic.h).
using namespace test;

constexpr Rgba kBase{200, 150, 110, 255};
constexpr Rgba kBack{120, 90, 70, 255};

Rgba scaled(Rgba c, double k) {
  auto s = [k](std::uint8_t v) {
    return static_cast<std::uint8_t>(std::clamp(std::lround(v * k), 0L, 255L));
  };
  return {s(c.r), s(c.g), s(c.b), 255};
}

// Pieces 1 and 2 of a strand under band 3, over a darker back piece 4
// (test::strand_under_band): only a strand join can join 1 and 2.
Drawing strand_under_band() { return test::strand_under_band(kBack, kBase); }

// Cel paint: `base` with a shadow band (0.72 of it) down the left 15 px.
void cel(Drawing& d, int region, Rgba base) {
  repaint(d, region, [base](int x, int) { return x < 115 ? scaled(base, 0.72) : base; });
}

TEST(PaintJoins, CelPiecesOfTwoBaseColoursAreNotJoined) {
  // Both pieces with a shadow band, the lower one's base 12 % lighter (29
  // RGB): the band spreads each cut's window over both colours (RGB
  // deviation ~30), so the old step beyond the spread was 0 and they were
  // joined under a limit of 1.0 that the geometry passes; their flat colours
  // differ. The same paint on both is joined.
  Drawing same = strand_under_band();
  cel(same, 1, kBase);
  cel(same, 2, kBase);
  EXPECT_EQ(joined_with_1(same, 1.0), (std::vector<int>{1, 2}));
  Drawing other = strand_under_band();
  cel(other, 1, kBase);
  cel(other, 2, scaled(kBase, 1.12));
  EXPECT_EQ(joined_with_1(other, 1.0), (std::vector<int>{1}));
}

TEST(PaintJoins, BaseAndShadowOfOnePaintAreJoined) {
  // The upper piece shows only the shadow colour at its cut, the lower one
  // only the base: 70 RGB apart, which cost 1.2 before (not joined under a
  // limit of 1.2). The band and the back show base and shadow in the
  // drawing's one ratio (0.72), so the shadow of the lower piece's base is
  // the upper piece's colour. A lower piece of another, darker base (0.85)
  // stays apart.
  for (const double lower : {1.0, 0.85}) {
    Drawing d = strand_under_band();
    repaint(d, 1, [](int, int) { return scaled(kBase, 0.72); });
    repaint(d, 2, [lower](int, int) { return scaled(kBase, lower); });
    repaint(d, 3, [](int, int y) { return y > 140 ? scaled(kBase, 0.72) : kBase; });
    repaint(d, 4, [](int x, int) { return x > 160 ? scaled(kBack, 0.72) : kBack; });
    // A third strand elsewhere with base and shadow.
    paint(
        d, [](double x, double y) { return x > 170 && x < 210 && y > 180 && y < 260; }, kBase, 5);
    d.relations.push_back(below(4, 5));
    repaint(d, 5, [](int x, int) { return x < 185 ? scaled(kBase, 0.72) : kBase; });
    EXPECT_EQ(joined_with_1(d, 1.2),
              lower == 1.0 ? (std::vector<int>{1, 2}) : (std::vector<int>{1}))
        << lower;
  }
}

// A gradient down the strand: 0.5 levels a pixel on every channel from
// `top` at y = 70.
Rgba ramp(Rgba top, int y) {
  auto s = [y](std::uint8_t v) {
    return static_cast<std::uint8_t>(std::clamp(std::lround(v - 0.5 * (y - 70)), 0L, 255L));
  };
  return {s(top.r), s(top.g), s(top.b), 255};
}

TEST(PaintJoins, GradientContinuingUnderTheBandIsJoined) {
  // The colour falls 0.5 a channel per px all down the strand, so the cuts'
  // windows step ~40 RGB across the band: beyond their spread that cost 0.6
  // before (not joined under a limit of 1.0). The slopes of both pieces
  // predict the step. The lower piece 30 levels lighter than the slope
  // predicts (another strand) stays apart.
  for (const int offset : {0, 30}) {
    Drawing d = strand_under_band();
    repaint(d, 1, [](int, int y) { return ramp(kBase, y); });
    repaint(d, 2, [offset](int, int y) { return ramp(kBase, y - 2 * offset); });
    EXPECT_EQ(joined_with_1(d, 1.0), offset == 0 ? (std::vector<int>{1, 2}) : (std::vector<int>{1}))
        << offset;
  }
}

TEST(PaintJoins, GradientCarryingOnAcrossTheGapJoinsBeyondThePlainCost) {
  // Slopes of 0.87 RGB a pixel on both sides predict the ~40 RGB step across
  // the band: the shading visibly carries on, so the join costs 0.6 less and
  // passes a limit of 0.4 (it joins from 0.3) that the same pieces painted
  // flat, one colour, exceed (they join from 0.65).
  Drawing d = strand_under_band();
  repaint(d, 1, [](int, int y) { return ramp(kBase, y); });
  repaint(d, 2, [](int, int y) { return ramp(kBase, y); });
  EXPECT_EQ(joined_with_1(d, 0.4), (std::vector<int>{1, 2}));
  EXPECT_EQ(joined_with_1(strand_under_band(), 0.4), (std::vector<int>{1}));
}

// A gradient across the strand: 0.5 levels a pixel on every channel from
// `left` at x = 100, `lift` levels lighter.
Rgba across(Rgba left, int x, int lift) {
  auto s = [x, lift](std::uint8_t v) {
    return static_cast<std::uint8_t>(std::clamp(std::lround(v + lift - 0.5 * (x - 100)), 0L, 255L));
  };
  return {s(left.r), s(left.g), s(left.b), 255};
}

TEST(PaintJoins, PiecesOffTheGradientAreNotJoined) {
  // Both pieces shaded across the strand (0.87 RGB a pixel), so their slopes
  // predict no change across the band: the lower piece 4 levels lighter (7
  // RGB, another strand's paint) cost only 0.23 more and was joined under a
  // limit of 1.0; now it stays apart, as does a lower piece shaded down the
  // strand (slope 0.87) 9 levels (16 RGB) off the ~45 RGB its slope
  // predicts, joined under 1.4 before. One paint is joined both ways.
  for (const int lift : {0, 4}) {
    Drawing d = strand_under_band();
    repaint(d, 1, [](int x, int) { return across(kBase, x, 0); });
    repaint(d, 2, [lift](int x, int) { return across(kBase, x, lift); });
    EXPECT_EQ(joined_with_1(d, 1.0), lift == 0 ? (std::vector<int>{1, 2}) : (std::vector<int>{1}))
        << lift;
  }
  for (const int offset : {0, 9}) {
    Drawing d = strand_under_band();
    repaint(d, 1, [](int, int y) { return ramp(kBase, y); });
    repaint(d, 2, [offset](int, int y) { return ramp(kBase, y - 2 * offset); });
    EXPECT_EQ(joined_with_1(d, 1.4), offset == 0 ? (std::vector<int>{1, 2}) : (std::vector<int>{1}))
        << offset;
  }
}

// A wide piece cut in two by a strand lying over it: left (1) and right (2)
// of strand 3, both over region 4 (front hair: no mass or path join), so a
// bank or strand join must join them.
Drawing wide_piece_under_strand(Rgba right) {
  Drawing d = blank(260, 300);
  paint(
      d, [](double x, double y) { return x > 10 && x < 250 && y > 20 && y < 280; }, kBack, 4);
  paint(
      d, [](double x, double y) { return x > 20 && x < 110 && y > 100 && y < 200; }, kBase, 1);
  paint(
      d, [](double x, double y) { return x >= 110 && x < 240 && y > 100 && y < 200; }, right, 2);
  paint(
      d, [](double x, double y) { return x > 95 && x < 145 && y > 40 && y < 260; }, kBase, 3);
  d.relations = {below(4, 1), below(4, 2), below(4, 3), below(1, 3), below(2, 3)};
  return d;
}

TEST(PaintJoins, BankJoinComparesThePaint) {
  // The right piece 25 % lighter (68 RGB, under max_colour_distance): the
  // bank join cost 0.8 and was made; the paint step now counts (+3.4).
  EXPECT_EQ(joined_with_1(wide_piece_under_strand(kBase), 2.4), (std::vector<int>{1, 2}));
  EXPECT_EQ(joined_with_1(wide_piece_under_strand(scaled(kBase, 1.25)), 2.4),
            (std::vector<int>{1}));
}

// Whether completing `d` offered the scorer a join of pieces 1 and 2 (the
// scorer on, its candidates recorded): the candidate, its hand cost and the
// scorer's probability, or none.
std::optional<JoinCandidate> candidate_1_2(const Drawing& d) {
  Options o;
  o.inpaint_background = false;
  o.face_joins = false;
  o.join_scorer.record = true;
  const Result r = complete_strands(test::input_of(d, Vec2(125, 10)), o);
  for (const JoinCandidate& c : r.join_candidates)
    if (std::min(c.region_a, c.region_b) == 1 && std::max(c.region_a, c.region_b) == 2) return c;
  return std::nullopt;
}

TEST(PaintJoins, OffTheGradientByUnevenWindowsIsLeftToTheScorer) {
  // The upper piece falls 0.5 levels a pixel down the strand, the lower one
  // is one colour (its window's slope 0, under a quarter of the other's),
  // 40 levels darker than the upper one's slope predicts: off the gradient.
  // A window that measured no slope may have missed the strand's rate, so
  // the candidate is not refused but priced just over the limit and left to
  // the scorer (asked: a probability), which alone may join it; with the
  // scorer off it stays apart, as before.
  Drawing uneven = strand_under_band();
  repaint(uneven, 1, [](int, int y) { return ramp(kBase, y); });
  repaint(uneven, 2, [](int, int) { return ramp(kBase, 210); });
  const std::optional<JoinCandidate> c = candidate_1_2(uneven);
  ASSERT_TRUE(c.has_value()) << "uneven windows: refused, not left to the scorer";
  EXPECT_GT(c->hand_cost, Options{}.max_join_cost);
  EXPECT_GE(c->probability, 0.0);
  Options off;
  off.inpaint_background = false;
  off.face_joins = false;
  off.join_scorer.enabled = false;
  EXPECT_EQ(test::regions_with(complete_strands(test::input_of(uneven, Vec2(125, 10)), off), 1),
            (std::vector<int>{1}));
  // Both pieces falling 0.5 a pixel, the lower one 30 levels lighter than
  // the slopes predict: even windows measured the rate, so the step is
  // another strand's and the candidate is refused before the scorer.
  Drawing even = strand_under_band();
  repaint(even, 1, [](int, int y) { return ramp(kBase, y); });
  repaint(even, 2, [](int, int y) { return ramp(kBase, y - 60); });
  EXPECT_FALSE(candidate_1_2(even).has_value());
}

}  // namespace
}  // namespace hair25d::completion
