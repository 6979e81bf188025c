// The paint of back-hair pieces joined region to region (mass and path
// joins, bank_crossings.cpp and mass_paths.cpp): a gradient over the whole
// back hair continues under the strands lying on it, so the colour step the
// windows at the cuts measure is no reason to keep the pieces apart when
// one linear field paints both (RegionFields, join_paint.h).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "hair25d/completion/completion.h"
#include "synthetic.h"

namespace hair25d::completion {
namespace {

// The shared synthetic drawings and helpers (synthetic.h).
using namespace test;

// The back hair's gradient: lighter to the right and down (0.46 RGB a px
// along x), plus `offset` a channel.
Rgba gradient(int x, int y, int offset) {
  const auto c = [&](double base, double sx, double sy) {
    return static_cast<std::uint8_t>(std::lround(base + sx * x + sy * y + offset));
  };
  return Rgba{c(60, 0.35, 0.1), c(40, 0.25, 0.08), c(30, 0.15, 0.05), 255};
}

// Back hair (regions 1 left, 2 right) behind a fan of three overlapping
// vertical strands 3 < 4 < 5 across x 112..205 (test::back_hair_under_fan).
Drawing back_hair_under_fan() { return test::back_hair_under_fan(kBack, kBack, kFan); }

// Back hair (1) and a sliver of it (2, 4 px wide between its outlines)
// under strand 3 lying on both, painted over `d`.
void paint_back_sliver_and_strand(Drawing& d) {
  paint(
      d, [](double x, double y) { return x > 20 && x < 150 && y > 40 && y < 170; }, kBack, 1);
  paint(
      d, [](double x, double y) { return x > 150 && x < 200 && y > 40 && y < 170; }, kBack, 2);
  paint(
      d, [](double x, double y) { return x > 135 && x < 177 && y > 10 && y < 200; }, kFan, 3);
}

// The same over a tail 5 hanging from under the back hair 1, with a side
// lock 6 lying on 1 and on the tail.
Drawing back_tail_and_lock() {
  Drawing d = blank(300, 270);
  paint(
      d, [](double x, double y) { return x > 40 && x < 80 && y > 150 && y < 255; }, kBack, 5);
  paint_back_sliver_and_strand(d);
  paint(
      d, [](double x, double y) { return x > 70 && x < 105 && y > 20 && y < 250; }, kFan, 6);
  return d;
}

// The same with strand 4 lying on the sliver only.
Drawing back_hair_and_sliver() {
  Drawing d = blank(300, 210);
  paint_back_sliver_and_strand(d);
  paint(
      d, [](double x, double y) { return x > 185 && x < 230 && y > 15 && y < 195; }, kFan, 4);
  d.relations = {below(1, 3), below(2, 3), below(2, 4)};
  return d;
}

// `d` with pieces 1 and 2 in the back hair's gradient, 2 lifted by
// `offset` a channel.
Drawing in_gradient(Drawing d, int offset) {
  repaint(d, 1, [](int x, int y) { return gradient(x, y, 0); });
  repaint(d, 2, [offset](int x, int y) { return gradient(x, y, offset); });
  return d;
}

// Only the region-level joins can join.
Result run(const Drawing& d) { return test::run_region_joins(d); }

TEST(MassPaint, BackHairInOneGradientIsJoinedAcrossTheFan) {
  // The windows 6 px inside the two cuts, ~87 px apart, step ~39 RGB (over
  // the 10 RGB limit: the old rule kept them apart); one linear field
  // paints both pieces.
  const Result r = run(in_gradient(back_hair_under_fan(), 0));
  EXPECT_EQ(test::regions_with(r, 1), (std::vector<int>{1, 2}));
  for (int id : {3, 4, 5}) EXPECT_EQ(test::regions_with(r, id), (std::vector<int>{id}));
  // The right piece 14 levels a channel lighter than the left one's
  // gradient carried on: a lock of another paint.
  EXPECT_EQ(test::regions_with(run(in_gradient(back_hair_under_fan(), 14)), 1),
            (std::vector<int>{1}));
  // Without a gradient the field says nothing the colour step does not: two
  // flat pieces 24 levels a channel apart stay apart.
  Drawing flat = back_hair_under_fan();
  repaint(flat, 2, [](int, int) { return Rgba{144, 104, 74, 255}; });
  EXPECT_EQ(test::regions_with(run(flat), 1), (std::vector<int>{1}));
}

TEST(MassPaint, PiecesOfTwoGradientsAreNotJoinedThoughTheWindowsStepLittle) {
  // The right piece carries the left one's colour at the cut on, but twice
  // as steep (0.9 RGB a px along x): the windows beside the cuts step ~2
  // RGB (under the 10 RGB limit; the old rule joined them), while no one
  // field paints both (it misses by ~21 RGB): two locks' gradients.
  Drawing d = in_gradient(back_hair_under_fan(), 0);
  repaint(d, 2, [](int x, int y) { return gradient(114 + 2 * (x - 212), y, 0); });
  EXPECT_EQ(test::regions_with(run(d), 1), (std::vector<int>{1}));
}

TEST(PathPaint, GradientSliverIsJoinedUnderTheStrandLyingOnBoth) {
  // The windows at the paths' ends, ~44 px apart across strand 3, step ~20
  // RGB (over the 0.8 RGB limit); the sliver has only 1-px-inside pixels.
  const Result r = run(in_gradient(back_hair_and_sliver(), 0));
  EXPECT_EQ(test::regions_with(r, 1), (std::vector<int>{1, 2}));
  EXPECT_EQ(test::regions_with(r, 3), (std::vector<int>{3}));
  EXPECT_EQ(test::regions_with(run(in_gradient(back_hair_and_sliver(), 14)), 1),
            (std::vector<int>{1}));
  // Both pieces flat, the sliver 10 levels a channel lighter: no piece shows
  // a gradient of its own.
  Drawing flat = back_hair_and_sliver();
  repaint(flat, 2, [](int, int) { return Rgba{130, 90, 60, 255}; });
  EXPECT_EQ(test::regions_with(run(flat), 1), (std::vector<int>{1}));
}

// The back hair's cel shadow: 0.72 of its base (the generator's band).
constexpr Rgba kBand{86, 58, 36, 255};

// Back hair (1, left, y 60..170) in its base above row `level` and its
// band below, and a piece of it (2, right, rows y0..y1) in `right`, behind
// the fan of three strands 3 < 4 < 5 across x 112..205.
Drawing cel_back_under_fan(int level, double y0, double y1, Rgba right) {
  Drawing d = blank(340, 230);
  paint(
      d, [](double x, double y) { return x > 20 && x < 120 && y > 60 && y < 170; }, kBack, 1);
  repaint(d, 1, [level](int, int y) { return y < level ? kBack : kBand; });
  paint(
      d, [&](double x, double y) { return x > 195 && x < 320 && y > y0 && y < y1; }, right, 2);
  paint(
      d, [](double x, double y) { return x > 112 && x < 145 && y > 10 && y < 220; }, kFan, 3);
  paint(
      d, [](double x, double y) { return x > 140 && x < 172 && y > 5 && y < 215; }, kFan, 4);
  paint(
      d, [](double x, double y) { return x > 168 && x < 205 && y > 15 && y < 225; }, kFan, 5);
  d.relations = {below(1, 3), below(2, 5), below(3, 4), below(4, 5)};
  return d;
}

TEST(MassPaint, BackPieceSeenInItsShadowBandIsJoinedToTheBackShowingBoth) {
  // The band's level lies under the fan at row 120: the left piece shows
  // base and band, the right one (rows 66..168) only the band. Most rays
  // leave the left piece in its base, so the windows step ~42 RGB (the old
  // rules kept them apart); the right piece's paint is the left one's band
  // and reaches below the band's top.
  const Result r = run(cel_back_under_fan(120, 66, 168, kBand));
  EXPECT_EQ(test::regions_with(r, 1), (std::vector<int>{1, 2}));
  for (int id : {3, 4, 5}) EXPECT_EQ(test::regions_with(r, id), (std::vector<int>{id}));
  // The band's colour wholly above the band (rows 66..110, the band from
  // 150): a strand's band seen beside the back's base, not the back.
  EXPECT_EQ(test::regions_with(run(cel_back_under_fan(150, 66, 110, kBand)), 1),
            (std::vector<int>{1}));
  // A band 8 % lighter than the back's: another lock's paint.
  EXPECT_EQ(test::regions_with(run(cel_back_under_fan(120, 66, 168, Rgba{93, 63, 39, 255})), 1),
            (std::vector<int>{1}));
}

TEST(MassPaint, PiecesOfOtherFlatColoursAreNotJoinedThoughTheWindowsStepLittle) {
  // The right piece 5 / 5 / 4 levels off the back's paint: its windows step
  // ~8 RGB, within the mass joins' 10 (the old rules joined it), but on a
  // cel drawing two flat paints that far apart are two locks (the
  // generator varies each strand's colour by up to 8 %).
  Drawing d = back_hair_under_fan();
  repaint(d, 2, [](int, int) { return Rgba{125, 85, 54, 255}; });
  EXPECT_EQ(test::regions_with(run(d), 1), (std::vector<int>{1}));
  // The same paint is joined.
  EXPECT_EQ(test::regions_with(run(back_hair_under_fan()), 1), (std::vector<int>{1, 2}));
}

TEST(MassPaint, PiecesOfNearlyOneFlatPaintAreNotJoined) {
  // The right piece one level a channel off the back's paint (1.7 RGB):
  // between the cel judgement's `same` (1) and `other` (3) limits, where
  // the old rules joined it. On a cel drawing pieces of one strand share
  // one paint; two strands of nearly one colour (an "under" strand lying on
  // the face beside another, generated seed 2073) do not.
  Drawing d = back_hair_under_fan();
  repaint(d, 2, [](int, int) { return Rgba{121, 81, 51, 255}; });
  EXPECT_EQ(test::regions_with(run(d), 1), (std::vector<int>{1}));
  // One channel one level off (1 RGB) is still one paint.
  repaint(d, 2, [](int, int) { return Rgba{121, 80, 50, 255}; });
  EXPECT_EQ(test::regions_with(run(d), 1), (std::vector<int>{1, 2}));
}

TEST(PathJoins, BackHairLyingOnAHangingTailIsAPiece) {
  // Back hair 1 and its sliver 2 under strand 3 lying on both; a tail 5
  // hangs from under 1, and a side lock 6 lies on 1 and on the tail. 1 lies
  // above a region, so it was front hair and no path piece (6 lying on the
  // back keeps tailed_hair from taking 5 as a tail): the tail, covered by
  // two regions, hangs from under it.
  Drawing d = back_tail_and_lock();
  d.relations = {below(1, 3), below(2, 3), below(5, 1), below(5, 6), below(1, 6)};
  const Result r = run(d);
  EXPECT_EQ(test::regions_with(r, 1), (std::vector<int>{1, 2}));
  EXPECT_EQ(test::regions_with(r, 5), (std::vector<int>{5}));
  EXPECT_EQ(test::regions_with(r, 6), (std::vector<int>{6}));
}

TEST(PathJoins, BackHairRestingOnATailThreeRegionsCoverIsAPiece) {
  // As above, with a second lock 7 lying on the back and the tail: the tail
  // is covered by three regions (two-tone seed 103: a tail under two back
  // pieces and a bang), so it hung from under nothing and back 1 stayed
  // front hair, no path piece. Back 1 touches the tail along a few per cent
  // of its outline (it rests on the tail's top end), so the tail hangs from
  // under it.
  Drawing d = back_tail_and_lock();
  paint(
      d, [](double x, double y) { return x > 30 && x < 50 && y > 90 && y < 262; }, kFan, 7);
  d.relations = {below(1, 3), below(2, 3), below(5, 1), below(5, 6),
                 below(1, 6), below(5, 7), below(1, 7)};
  const Result r = run(d);
  EXPECT_EQ(test::regions_with(r, 1), (std::vector<int>{1, 2}));
  EXPECT_EQ(test::regions_with(r, 5), (std::vector<int>{5}));
  EXPECT_EQ(test::regions_with(r, 6), (std::vector<int>{6}));
  EXPECT_EQ(test::regions_with(r, 7), (std::vector<int>{7}));
}

// The top of the back hair 1 (a 30 px arc, `top`) with the cap 2 lying on
// its lower part, and the back's lower part 3 (`lower`) below a gap of
// paper; a strand 4 lies on the cap and on 3, a side lock 8 on 1 and the
// cap. No region lying above both 1 and 3 touches 1, so the path joins
// under common occluders find no path. Strands 5, 6 and 7 (`strands`) hang right of
// the back, lying on nothing.
Drawing back_top_under_the_cap(Rgba top, Rgba lower, Rgba strands) {
  const Rgba cap{170, 120, 90, 255}, strand{90, 140, 70, 255};
  Drawing d = blank(370, 300);
  paint(
      d, [](double x, double y) { return x > 40 && x < 300 && y > 20 && y < 62; }, top, 1);
  paint(
      d, [](double x, double y) { return x > 60 && x < 280 && y > 45 && y < 110; }, cap, 2);
  paint(
      d, [](double x, double y) { return x > 40 && x < 300 && y > 132 && y < 260; }, lower, 3);
  paint(
      d, [](double x, double y) { return x > 150 && x < 185 && y > 70 && y < 200; }, strand, 4);
  for (int k = 0; k < 3; ++k)
    paint(
        d,
        [k](double x, double y) {
          return x > 304 + 18 * k && x < 318 + 18 * k && y > 40 && y < 280;
        },
        strands, 5 + k);
  paint(
      d, [](double x, double y) { return x > 45 && x < 72 && y > 10 && y < 100; }, strand, 8);
  d.relations = {below(1, 2), below(2, 4), below(3, 4), below(1, 8), below(2, 8)};
  return d;
}

TEST(PathJoins, BackHairRoundTheCapIsJoinedToItsLowerPartInItsOwnPaint) {
  // Paths from 1 run through the cap (above 1) and the strand (above 3):
  // regions lying above either piece. Joined in one paint; not when the
  // lower part is painted otherwise, nor when other regions (the three
  // strands beside it) share the paint: then it is no back hair's own.
  const Rgba kLower{150, 100, 70, 255};
  EXPECT_EQ(test::regions_with(run(back_top_under_the_cap(kBack, kBack, kFan)), 1),
            (std::vector<int>{1, 3}));
  EXPECT_EQ(test::regions_with(run(back_top_under_the_cap(kBack, kLower, kFan)), 1),
            (std::vector<int>{1}));
  EXPECT_EQ(test::regions_with(run(back_top_under_the_cap(kBack, kBack, kBack)), 1),
            (std::vector<int>{1}));
}

}  // namespace
}  // namespace hair25d::completion
