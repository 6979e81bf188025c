// Joins of strand pieces whose own outline says too little: a nub — a
// strand's rounded root peeking out from under an occluder — is joined by the
// other piece's tangents (joins.cpp); a window — a piece of a wide region
// seen between two strands lying over it — across the banks of either strand
// (bank_crossings.cpp). And one the outline says too much for: two pieces of
// flat paint in different colours are two strands (joins.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "hair25d/completion/completion.h"
#include "synthetic.h"

namespace hair25d::completion {
namespace {

// The shared synthetic drawings and helpers (synthetic.h).
using namespace test;

constexpr Rgba kBack{120, 90, 70, 255};
constexpr Rgba kStrand{200, 150, 110, 255};
constexpr Rgba kBang{150, 110, 80, 255};

// A vertical strand (x 100..140) over a wide lowest region 4, its rounded
// root (half an ellipse `top` px tall, ending at y 140) peeking out above a
// band 3 (y 118..162) lying over it as the nub 1; below the band the long
// piece 2 (y 140..230). `lower_dx` shifts the lower piece sideways.
Drawing nub_over_band(double top, double lower_dx = 0.0) {
  Drawing d = blank(250, 300);
  paint(
      d, [](double x, double y) { return x > 20 && x < 230 && y > 20 && y < 280; }, kBack, 4);
  paint(
      d,
      [top](double x, double y) {
        const double u = (x - 120) / 20, v = (y - 140) / top;
        return y < 140 && u * u + v * v < 1;
      },
      kStrand, 1);
  paint(
      d,
      [lower_dx](double x, double y) {
        return x > 100 + lower_dx && x < 140 + lower_dx && y >= 140 && y < 230;
      },
      kStrand, 2);
  paint(
      d, [](double x, double y) { return x > 40 && x < 210 && y > 118 && y < 162; }, kStrand, 3);
  d.relations = {below(4, 1), below(4, 2), below(4, 3), below(1, 3), below(2, 3)};
  return d;
}

// `veto`: JoinScorerOptions::veto_below as by default, else 0 (no
// candidate under the cost limit refused by the retrained net).
std::vector<int> joined_with_1(const Drawing& d, bool veto = true) {
  Options o;
  if (!veto) o.join_scorer.veto_below = 0.0;
  o.inpaint_background = false;
  o.face_joins = false;
  o.path_joins = false;
  return test::regions_with(complete_strands(test::input_of(d, Vec2(125, 10)), o), 1);
}

TEST(StrandJoins, NubIsJoinedByTheOtherPiecesTangents) {
  // The nub shows 12-15 px of its root above the band, ~28 px wide: its
  // outline beside the cut turns round the root, so its tangents lie over
  // 70° off the join and it made no strand join. The lower piece points
  // straight at its cut. A lower piece 40 px to the right, whose tangents lie
  // ~42° off the chords to the nub's cut (more than the 30° a one-sided join
  // allows), stays apart.
  for (double top : {30.0, 33.0}) {
    EXPECT_EQ(joined_with_1(nub_over_band(top)), (std::vector<int>{1, 2})) << top;
    EXPECT_EQ(joined_with_1(nub_over_band(top, 40)), (std::vector<int>{1})) << top;
  }
}

// Pieces of one wide region (the cap) in a strip cut by two bangs 2 (x
// 100..140) and 3 (x 170..210) lying over it, over a lowest region 6: the
// left piece 1 (x 15..100, y 24..`bottom` + 8), between the bangs the
// window 4 (x 140..170, y 30..`bottom`), the right piece 5 (x 210..285);
// without the second bang, 4 is the end of a strip lying under bang 2 only.
Drawing cap_between_bangs(double bottom, bool second_bang) {
  Drawing d = blank(300, 220);
  paint(
      d, [](double x, double y) { return x > 5 && x < 295 && y > 5 && y < 215; }, kBack, 6);
  paint(
      d, [bottom](double x, double y) { return x > 15 && x < 100 && y > 24 && y < bottom + 8; },
      kStrand, 1);
  paint(
      d, [bottom](double x, double y) { return x > 140 && x < 170 && y > 30 && y < bottom; },
      kStrand, 4);
  paint(
      d, [bottom](double x, double y) { return x > 210 && x < 285 && y > 24 && y < bottom + 8; },
      kStrand, 5);
  paint(
      d, [](double x, double y) { return x > 100 && x < 140 && y > 10 && y < 200; }, kBang, 2);
  d.relations = {below(1, 2), below(4, 2), below(6, 1), below(6, 2), below(6, 4), below(6, 5)};
  if (second_bang) {
    paint(
        d, [](double x, double y) { return x > 170 && x < 210 && y > 10 && y < 200; }, kBang, 3);
    d.relations.push_back(below(4, 3));
    d.relations.push_back(below(5, 3));
    d.relations.push_back(below(6, 3));
  }
  return d;
}

// Bank joins only: strand joins ruled out (tangents within 0.5°, cut widths
// within 1 %: the pieces' cuts differ by 14 px).
std::vector<int> bank_joined_with_4(const Drawing& d) {
  Options o;
  o.inpaint_background = false;
  o.face_joins = false;
  o.path_joins = false;
  o.max_join_angle_deg = 0.5;
  o.min_width_ratio = 0.99;
  return test::regions_with(complete_strands(test::input_of(d, Vec2(150, 0)), o), 4);
}

TEST(StrandJoins, WindowBetweenTwoStrandsIsBankJoined) {
  // The window reaches 30 px behind its cuts, less than the 1.5 crossed
  // widths (~60 px) the banks ask of a piece, so it was joined to neither
  // side; but every ray run inwards across it ends under bang 3: it is seen
  // between two strands, not a strand end. The same piece without bang 3
  // (its far side shows) stays apart.
  for (double bottom : {90.0, 150.0}) {
    EXPECT_EQ(bank_joined_with_4(cap_between_bangs(bottom, true)), (std::vector<int>{1, 4, 5}))
        << bottom;
    EXPECT_EQ(bank_joined_with_4(cap_between_bangs(bottom, false)), (std::vector<int>{4}))
        << bottom;
  }
}

// A straight vertical strand (x 100..140) over a wide lowest region 4, cut
// by a band 3 (y 118..162) lying over it: the upper piece 1 (y 40..140) in
// kStrand, the lower piece 2 (y 140..230) in `lower`, both flat paint.
Drawing strand_under_band(Rgba lower) {
  Drawing d = blank(250, 300);
  paint(
      d, [](double x, double y) { return x > 20 && x < 230 && y > 20 && y < 280; }, kBack, 4);
  paint(
      d, [](double x, double y) { return x > 100 && x < 140 && y > 40 && y < 140; }, kStrand, 1);
  paint(
      d, [](double x, double y) { return x > 100 && x < 140 && y >= 140 && y < 230; }, lower, 2);
  paint(
      d, [](double x, double y) { return x > 40 && x < 210 && y > 118 && y < 162; }, kBang, 3);
  d.relations = {below(4, 1), below(4, 2), below(4, 3), below(1, 3), below(2, 3)};
  return d;
}

TEST(StrandJoins, PiecesOfTwoFlatPaintsAreNotJoined) {
  // The pieces line up exactly (tangents 0° off, the same width, a 44 px
  // gap under the band), so their outline makes a cheap join; but flat
  // paint 8.8 RGB apart is another strand's. Paint 1 RGB off is one strand.
  EXPECT_EQ(joined_with_1(strand_under_band(Rgba{206, 155, 114, 255})), (std::vector<int>{1}));
  EXPECT_EQ(joined_with_1(strand_under_band(Rgba{201, 150, 110, 255})), (std::vector<int>{1, 2}));
  EXPECT_EQ(joined_with_1(strand_under_band(kStrand)), (std::vector<int>{1, 2}));
}

// An arched strand (radius 150 ± 14 round (150, 260), the half above y 260)
// over a wide lowest region 4, its top hidden by a band 3 (x 75..225, y
// 80..170) lying over it: the left piece 1 and the right piece 2 in kStrand,
// their cuts ~150 px apart, the hidden arc turning 60°. Three strips 5, 6, 7
// lying on region 4 inside the arch, unrelated to the strand, in `others`,
// and two more, 8 and 9, in other paints.
Drawing arch_under_band(Rgba others) {
  Drawing d = blank(300, 300);
  paint(
      d, [](double x, double y) { return x > 5 && x < 295 && y > 5 && y < 295; }, kBack, 4);
  auto arch = [](double x, double y) {
    const double r = std::hypot(x - 150, y - 260);
    return y < 260 && r > 136 && r < 164;
  };
  paint(
      d, [arch](double x, double y) { return arch(x, y) && x < 150; }, kStrand, 1);
  paint(
      d, [arch](double x, double y) { return arch(x, y) && x >= 150; }, kStrand, 2);
  paint(
      d, [](double x, double y) { return x > 75 && x < 225 && y > 80 && y < 170; }, kBang, 3);
  // Two more regions of other paints: rarity needs eight flat-painted regions.
  paint(
      d, [](double x, double y) { return x > 40 && x < 70 && y > 200 && y < 250; },
      Rgba{90, 140, 200, 255}, 8);
  paint(
      d, [](double x, double y) { return x > 230 && x < 260 && y > 200 && y < 250; },
      Rgba{120, 200, 120, 255}, 9);
  for (int k = 0; k < 3; ++k)
    paint(
        d,
        [k](double x, double y) {
          return x > 105 + 35 * k && x < 125 + 35 * k && y > 200 && y < 250;
        },
        others, 5 + k);
  d.relations = {below(4, 1), below(4, 2), below(4, 3), below(1, 3), below(2, 3),
                 below(4, 5), below(4, 6), below(4, 7), below(4, 8), below(4, 9)};
  return d;
}

TEST(StrandJoins, PiecesOfOneRarePaintAreJoinedAcrossALongBendingGap) {
  // The hidden arc turns 60° over a gap of five strand widths: the outline
  // alone prices the join at ~3.5 (angles 1.5, gap 1.5, bulge 0.5), over the
  // limit of 2.4. The two pieces are one flat paint that no other of the
  // drawing's nine regions shares, so they are one strand.
  // When three other regions share that paint (strands of one hair colour),
  // the paint says nothing and the pieces stay apart. The hand cost's rule
  // alone: the retrained net's veto (session 29), trained on the generator's
  // drawings, refuses this nine-region drawing's right join (p < 0.2; a
  // known cost of the veto, docs/completion-record.md).
  EXPECT_EQ(joined_with_1(arch_under_band(Rgba{170, 130, 150, 255}), false),
            (std::vector<int>{1, 2}));
  EXPECT_EQ(joined_with_1(arch_under_band(kStrand), false), (std::vector<int>{1}));
}

// A vertical strand (x 100..140) over a wide lowest region 4, crossed at y
// 136..142 by `ink` — the tip of another strand thinner than its outline,
// drawn as ink only — into the upper piece 1 (y 60..136) and the lower
// piece 2 (y 142..230, in `lower`). No region lies between the pieces, so
// neither lies under anything there.
Drawing strand_cut_by_ink(Rgba lower) {
  Drawing d = blank(250, 300);
  paint(
      d, [](double x, double y) { return x > 20 && x < 230 && y > 20 && y < 280; }, kBack, 4);
  paint(
      d, [](double x, double y) { return x > 100 && x < 140 && y > 60 && y < 136; }, kStrand, 1);
  paint(
      d, [](double x, double y) { return x > 100 && x < 140 && y >= 142 && y < 230; }, lower, 2);
  for (int y = 136; y < 142; ++y)
    for (int x = 80; x < 160; ++x) {
      d.image.at(x, y) = Rgba{20, 15, 10, 255};
      d.regions.at(x, y) = 0;
    }
  d.relations = {below(4, 1), below(4, 2)};
  return d;
}

// Two strands side by side (x 100..128 and 136..164, y 60..230) over a wide
// lowest region 4, a band of ink 8 px wide between them all along.
Drawing strands_beside_ink() {
  Drawing d = blank(250, 300);
  paint(
      d, [](double x, double y) { return x > 20 && x < 230 && y > 20 && y < 280; }, kBack, 4);
  paint(
      d, [](double x, double y) { return x > 100 && x < 128 && y > 60 && y < 230; }, kStrand, 1);
  paint(
      d, [](double x, double y) { return x > 136 && x < 164 && y > 60 && y < 230; }, kStrand, 2);
  for (int y = 60; y < 230; ++y)
    for (int x = 128; x < 136; ++x) {
      d.image.at(x, y) = Rgba{20, 15, 10, 255};
      d.regions.at(x, y) = 0;
    }
  d.relations = {below(4, 1), below(4, 2)};
  return d;
}

TEST(StrandJoins, StrandCutByInkOnlyIsJoined) {
  // The pieces face each other across 10 px of ink (their own outlines and
  // the crossing tip) and no occluder: one strand, its sides running on.
  EXPECT_EQ(joined_with_1(strand_cut_by_ink(kStrand)), (std::vector<int>{1, 2}));
  // Another flat paint below the ink is another strand.
  EXPECT_EQ(joined_with_1(strand_cut_by_ink(Rgba{206, 155, 114, 255})), (std::vector<int>{1}));
  // Two strands side by side, ink between them all along: no cut across a
  // strand, whatever the paint.
  EXPECT_EQ(joined_with_1(strands_beside_ink()), (std::vector<int>{1}));
}

}  // namespace
}  // namespace hair25d::completion
