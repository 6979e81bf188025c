// A lock's point lying on the face right beside an eye (paper §5.4,
// background): its converging outlines make a wedge of the outline's colour
// that touches the iris, so the dark piece they form holds a pixel of
// another colour (generated seed 50's third wedge, beside its left eye).
#include <gtest/gtest.h>

#include <cmath>

#include "hair25d/completion/completion.h"
#include "synthetic.h"

namespace hair25d::completion {
namespace {

constexpr Rgba kSkin{250, 205, 170, 255};
constexpr Rgba kInk{35, 25, 25, 255};
constexpr Rgba kHair{70, 45, 35, 255};
constexpr Rgba kOutline{20, 15, 10, 255};  // test::paint's outline colour
constexpr Rgba kIris{25, 60, 30, 255};     // dark green: dark, of no hair colour

constexpr int kW = 300, kH = 240;
constexpr double kCx = 150, kCy = 140, kR = 62, kCapBottom = 122;
constexpr double kEyeX = kCx + 10, kEyeY = 136, kEyeR = 7;

int luma(const Rgba& c) { return (299 * c.r + 587 * c.g + 114 * c.b) / 1000; }

bool in_eye(double x, double y) { return std::hypot(x - kEyeX, y - kEyeY) < kEyeR; }
// The point: 10 px wide at the cap, 30 px long, with a core of the lock's
// fill colour between its two lines near the cap.
bool in_wedge(double x, double y) {
  const double t = (y - (kCapBottom - 3)) / 30.0;
  return t >= 0 && t < 1 && std::abs(x - kCx) < 5.0 * (1 - t);
}
bool in_core(double x, double y) {
  const double t = (y - (kCapBottom - 3)) / 30.0;
  return t >= 0 && t < 0.35 && std::abs(x - kCx) < 1.5 * (1 - t);
}

test::Drawing drawing() {
  test::Drawing d{Image(kW, kH, Rgba{0, 0, 0, 0}), LabelMap(kW, kH, 0), {}};
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double r = std::hypot(x + 0.5 - kCx, y + 0.5 - kCy);
      if (r < kR) d.image.at(x, y) = r > kR - 3 ? kInk : kSkin;
    }
  test::paint(
      d,
      [](double x, double y) { return std::hypot(x - kCx, y - (kCy - 8)) < 84 && y < kCapBottom; },
      kHair, 1);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double px = x + 0.5, py = y + 0.5;
      if (in_eye(px, py)) d.image.at(x, y) = kIris;
      if (in_wedge(px, py) && d.regions.at(x, y) == 0)
        d.image.at(x, y) = in_core(px, py) ? kHair : kOutline;
    }
  return d;
}

// The wedge goes with the hair and the eye it touches stays. Before, the
// whole dark piece (wedge and iris) was "mixed" and kept: the wedge stayed
// on the face as a black spike.
TEST(HeadBehindHairWedgeAtAnEye, WedgeTouchingAnIrisGoesTheIrisStays) {
  const test::Drawing d = drawing();
  ASSERT_TRUE(in_eye(kCx + 4.5, kCapBottom + 14)) << "the eye touches the wedge";
  Options o;
  o.inpaint_strands = false;
  const Result r = complete_strands(test::input_of(d, Vec2(kCx, kCy)), o);
  int tip = 0, tip_dark = 0, eye = 0, eye_kept = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double px = x + 0.5, py = y + 0.5;
      const Rgba& c = r.background.at(x, y);
      if (in_wedge(px, py) && !in_eye(px, py) && py >= kCapBottom + 2) {
        ++tip;
        tip_dark += luma(c) < 120;
      }
      if (in_eye(px, py) && !in_wedge(px, py) && d.regions.at(x, y) == 0) {
        ++eye;
        eye_kept += c == d.image.at(x, y);
      }
    }
  ASSERT_GT(tip, 100);
  ASSERT_GT(eye, 100);
  EXPECT_LE(tip_dark, tip / 50) << "the wedge is left on the face";
  EXPECT_GE(eye_kept, eye * 85 / 100) << "the eye went with the wedge";
}

// The same face without the core of the lock's colour: a piece all of the
// outline's colour touching an eye is a face line of that colour (an upper
// lash), and stays.
TEST(HeadBehindHairWedgeAtAnEye, LineOfTheOutlineColourWithoutFillStays) {
  test::Drawing d = drawing();
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      if (in_core(x + 0.5, y + 0.5) && d.regions.at(x, y) == 0) d.image.at(x, y) = kOutline;
  Options o;
  o.inpaint_strands = false;
  const Result r = complete_strands(test::input_of(d, Vec2(kCx, kCy)), o);
  int tip = 0, tip_dark = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double px = x + 0.5, py = y + 0.5;
      if (in_wedge(px, py) && !in_eye(px, py) && py >= kCapBottom + 8) {
        ++tip;
        tip_dark += luma(r.background.at(x, y)) < 120;
      }
    }
  ASSERT_GT(tip, 50);
  EXPECT_GE(tip_dark, tip * 9 / 10) << "a line of the outline's colour at an eye went";
}

}  // namespace
}  // namespace hair25d::completion
