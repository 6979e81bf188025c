// Session 24's joins for gradient drawings: one linear colour field painting
// two pieces (RegionFields::step) is the gradient's rare paint, for strand
// joins (joins.cpp, kOneFieldBonus) and for the path joins of pieces that no
// third region shares a field with (mass_paths.cpp, kMaxRareFieldStep).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "hair25d/completion/completion.h"
#include "synthetic.h"

namespace hair25d::completion {
namespace {

// The shared synthetic drawings and helpers (synthetic.h).
using namespace test;

// A linear field: `base` plus `sx`, `sy` levels a pixel on every channel.
struct Field {
  Rgba base;
  double sx = 0.0, sy = 0.0;
  Rgba at(int x, int y) const {
    const auto c = [&](std::uint8_t v) {
      return static_cast<std::uint8_t>(std::clamp(std::lround(v + sx * x + sy * y), 0L, 255L));
    };
    return {c(base.r), c(base.g), c(base.b), 255};
  }
};

// The strand's gradient down its length (0.4 levels a px), its back's
// across (0.3 a px, another colour), the band's along it.
const Field kStrand{{230, 190, 200, 255}, 0.0, -0.4};
const Field kBack{{90, 70, 110, 255}, 0.3, 0.0};
const Field kBand{{60, 140, 90, 255}, 0.25, 0.1};

void repaint_field(Drawing& d, int region, const Field& f) {
  repaint(d, region, [&f](int x, int y) { return f.at(x, y); });
}

// Pieces 1 and 2 of a strand under band 3, over back 4, offset sideways so
// that their cuts do not face each other; strip 5 painted by `strip`, and
// strips 6..9 each in a gradient of its own colour, on the back (rarity
// needs regions to compare with). No region is of flat paint: not a cel
// drawing.
Drawing strand_pieces_under_band(const Field& strip) {
  Drawing d = blank(300, 300);
  paint(
      d, [](double x, double y) { return x > 20 && x < 280 && y > 20 && y < 280; }, kBack.base, 4);
  paint(
      d, [](double x, double y) { return x > 100 && x < 140 && y > 30 && y < 140; }, kStrand.base,
      1);
  paint(
      d, [](double x, double y) { return x > 120 && x < 160 && y >= 140 && y < 250; }, kStrand.base,
      2);
  paint(
      d, [](double x, double y) { return x > 40 && x < 260 && y > 118 && y < 162; }, kBand.base, 3);
  paint(
      d, [](double x, double y) { return x > 220 && x < 250 && y > 170 && y < 260; }, strip.base,
      5);
  d.relations = {below(4, 1), below(4, 2), below(4, 3), below(1, 3), below(2, 3), below(4, 5)};
  repaint_field(d, 4, kBack);
  repaint_field(d, 1, kStrand);
  repaint_field(d, 2, kStrand);
  repaint_field(d, 3, kBand);
  repaint_field(d, 5, strip);
  for (int k = 0; k < 4; ++k) {
    const double x0 = 30 + 16 * k;
    const Field own{
        {static_cast<std::uint8_t>(140 + 25 * k), 110, static_cast<std::uint8_t>(60 + 30 * k), 255},
        0.0,
        0.4 + 0.1 * k};
    paint(
        d, [x0](double x, double y) { return x > x0 && x < x0 + 12 && y > 180 && y < 260; },
        own.base, 6 + k);
    repaint_field(d, 6 + k, own);
    d.relations.push_back(below(4, 6 + k));
  }
  return d;
}

TEST(GradientJoins, StrandPiecesOfOneRareFieldAreJoinedUnderTheBandLyingOnBoth) {
  // Only region-level joins can join (test::run_region_joins rules strand
  // joins out), and the pieces lie above the back, so no back-hair path
  // join takes them: one field that no third region shares joins them under
  // the band. Strip 5 painted by the same field shares it: nothing is said.
  const Field other{{200, 120, 160, 255}, 0.0, 0.45};
  EXPECT_EQ(test::regions_with(test::run_region_joins(strand_pieces_under_band(other)), 1),
            (std::vector<int>{1, 2}));
  EXPECT_EQ(test::regions_with(test::run_region_joins(strand_pieces_under_band(kStrand)), 1),
            (std::vector<int>{1}));
}

// Pieces 1 and 2 of a vertical strand cut by band 3 over back 4
// (test::strand_under_band), 1 in `upper`'s field and 2 in `lower`'s.
std::vector<int> strand_joined_with_1(const Field& upper, const Field& lower,
                                      double max_join_cost) {
  Drawing d = test::strand_under_band(kBack.base, kStrand.base);
  repaint_field(d, 1, upper);
  repaint_field(d, 2, lower);
  repaint_field(d, 3, kBand);
  repaint_field(d, 4, kBack);
  return test::joined_with_1(d, max_join_cost);
}

TEST(GradientJoins, StrandPiecesOfOneFieldJoinBelowTheShadingBonusAlone) {
  // One field paints both pieces: the join costs kOneFieldBonus less than
  // the shading carrying on alone says, and passes a limit that the lower
  // piece shaded half as steeply (the colours meeting at the band's middle,
  // row 140, so the windows' step stays within what the slopes explain,
  // while the joint field misses the pieces) does not; under a looser limit
  // both are joined.
  Field shallower = kStrand;
  shallower.sy = 0.5 * kStrand.sy;
  const auto at_140 = [](std::uint8_t v) { return static_cast<std::uint8_t>(v - 28); };
  shallower.base = {at_140(kStrand.base.r), at_140(kStrand.base.g), at_140(kStrand.base.b), 255};
  EXPECT_EQ(strand_joined_with_1(kStrand, kStrand, 0.1), (std::vector<int>{1, 2}));
  EXPECT_EQ(strand_joined_with_1(kStrand, shallower, 0.1), (std::vector<int>{1}));
  EXPECT_EQ(strand_joined_with_1(kStrand, shallower, 1.5), (std::vector<int>{1, 2}));
}

}  // namespace
}  // namespace hair25d::completion
