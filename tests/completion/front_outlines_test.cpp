// Session 21: outlines of shapes lying on the hair stay in the background
// (wikipe-tan's puzzle-piece clip over her twin tail), the hair's own
// outline still goes. Read from the T-junctions at the ends of the line the
// shape and the hair share.
#include <gtest/gtest.h>

#include <cmath>

#include "hair25d/completion/completion.h"
#include "synthetic.h"

namespace hair25d::completion {
namespace {

constexpr int kW = 260, kH = 200;
constexpr Rgba kClip{180, 180, 180, 255};
constexpr Rgba kHair{90, 140, 190, 255};
// The clip: a disc over the strand's left side.
constexpr double kCx = 95, kCy = 95, kR = 42;
// The strand: a band running off the sheet at the top and the bottom.
constexpr double kLeft = 100, kRight = 160;

bool in_clip(double x, double y) { return std::hypot(x - kCx, y - kCy) < kR; }
bool in_strand(double x, double y) { return x > kLeft && x < kRight && y > -10 && y < kH + 10; }

int luma(const Rgba& c) { return (299 * c.r + 587 * c.g + 114 * c.b) / 1000; }

// The head centre inside the strand, far from the clip: no face (the clip
// would pass for one and be filled as skin).
Result run(const test::Drawing& d) {
  Options o;
  o.inpaint_strands = false;
  return complete_strands(test::input_of(d, Vec2(130, 185)), o);
}

// `clip_on_top`: the clip is drawn over the strand (its outline runs on
// past the strand's sides, which end on it), else the strand over the clip.
test::Drawing drawing(const Rgba& sheet, bool clip_on_top) {
  test::Drawing d{Image(kW, kH, sheet), LabelMap(kW, kH, 0), {}};
  if (clip_on_top) {
    test::paint(d, in_strand, kHair, 1);
    test::paint_skin(d, in_clip, kClip);
  } else {
    test::paint_skin(d, in_clip, kClip);
    test::paint(d, in_strand, kHair, 1);
  }
  return d;
}

// The clip lies over the strand: its outline along the strand is its own and
// stays in the background, so its grey stays inside it. Before, the outline
// assignment gave that line to the strand, the hole took it, and the clip's
// grey flooded the strand's place.
TEST(FrontOutlines, OutlineOfAShapeLyingOnTheHairStays) {
  for (const Rgba sheet : {Rgba{0, 0, 0, 0}, Rgba{235, 240, 230, 255}}) {
    const test::Drawing d = drawing(sheet, true);
    const Result r = run(d);
    int line = 0, line_dark = 0, beside = 0, grey = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const double e = std::hypot(x + 0.5 - kCx, y + 0.5 - kCy) - kR;
        // The clip's outline (3 px inside its edge) where it lies on the strand.
        if (e > -2.5 && e < -0.5 && x > kLeft + 4)
          ++line, line_dark += luma(r.background.at(x, y)) < 100;
        // The strand's place outside the clip, away from its outline.
        if (e > 6 && in_strand(x + 0.5, y + 0.5) && x > kLeft + 3 && x < kRight - 3 && y > 20 &&
            y < kH - 20) {
          ++beside;
          const Rgba& c = r.background.at(x, y);
          grey += c.a > 128 && std::abs(c.r - kClip.r) < 20 && std::abs(c.b - kClip.b) < 20;
        }
      }
    ASSERT_GT(line, 80) << "sheet alpha " << int(sheet.a);
    EXPECT_GE(line_dark, line * 9 / 10)
        << "the clip's outline went with the hair, sheet alpha " << int(sheet.a);
    ASSERT_GT(beside, 3000);
    EXPECT_LE(grey, beside / 50) << "the clip's grey flooded the strand's place, sheet alpha "
                                 << int(sheet.a);
  }
}

// The strand lies over the clip: the clip's outline ends on the strand's
// sides, which run on smoothly; the strand's outline over the clip is the
// strand's and goes with it (the clip's grey fills in behind).
TEST(FrontOutlines, HairsOwnOutlineEndingOnAShapeStillGoes) {
  for (const Rgba sheet : {Rgba{0, 0, 0, 0}, Rgba{235, 240, 230, 255}}) {
    const test::Drawing d = drawing(sheet, false);
    const Result r = run(d);
    int side = 0, side_dark = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        // The strand's left outline where it lies on the clip, away from
        // the clip's own outline.
        const double e = std::hypot(x + 0.5 - kCx, y + 0.5 - kCy) - kR;
        if (x >= kLeft && x < kLeft + 2 && e < -8)
          ++side, side_dark += luma(r.background.at(x, y)) < 100;
      }
    ASSERT_GT(side, 100) << "sheet alpha " << int(sheet.a);
    EXPECT_LE(side_dark, side / 20)
        << "the strand's outline stayed over the clip, sheet alpha " << int(sheet.a);
  }
}

}  // namespace
}  // namespace hair25d::completion
