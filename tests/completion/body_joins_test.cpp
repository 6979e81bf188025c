// Back hair across the neck and body: the back hair is one mass hanging
// behind the head, so pieces seen on both sides of the neck are one piece
// that the neck (no region, no hair) hides (completion/src/body_joins.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "hair25d/completion/completion.h"
#include "synthetic.h"

namespace hair25d::completion {
namespace {

// The shared synthetic drawings and helpers (synthetic.h).
using namespace test;

const Rgba kBack{110, 70, 60, 255};
const Rgba kOther{70, 110, 150, 255};
const Rgba kSkin{252, 228, 205, 255};
const Rgba kClothes{120, 170, 200, 255};
constexpr double kCx = 180, kCy = 100, kRadius = 70;

bool in_face(double x, double y) { return std::hypot(x - kCx, y - kCy) < kRadius; }
bool in_neck(double x, double y) { return x > 150 && x < 210 && y > 120; }

// A 360 × 300 drawing: back hair (regions 1 left, 2 right, `right` its
// paint) hanging behind the head below the face, the neck (down to the
// image's bottom edge, in the clothes' colour) lying over its middle, the
// face over the neck's top. The pieces border the neck, not the face, and
// nothing that is hair lies over both: no edge, path, mass or face join
// reaches them.
Drawing back_hair_behind_the_neck(Rgba right) {
  Drawing d = blank(360, 300);
  paint(
      d, [](double x, double y) { return x > 30 && x <= 180 && y > 190 && y < 285; }, kBack, 1);
  paint(
      d, [](double x, double y) { return x > 180 && x < 330 && y > 190 && y < 285; }, right, 2);
  paint_skin(d, in_neck, kClothes);
  paint_skin(d, in_face, kSkin);
  return d;
}

Result run(const Drawing& d) {
  Options o;
  o.inpaint_strands = false;
  o.inpaint_background = false;
  return complete_strands(test::input_of(d, Vec2(kCx, kCy)), o);
}

TEST(BodyJoins, BackHairOnBothSidesOfTheNeckIsJoinedBehindIt) {
  const Drawing d = back_hair_behind_the_neck(kBack);
  const Result r = run(d);
  EXPECT_EQ(test::regions_with(r, 1), (std::vector<int>{1, 2}));
  // The completed part lies behind the neck, between the pieces.
  const CompletedStrand* s = test::strand_with(r, 1);
  ASSERT_NE(s, nullptr);
  int behind = 0;
  for (int y = 200; y < 280; y += 4)
    for (int x = 156; x < 205; x += 4) {
      const int mx = x - s->origin.x(), my = y - s->origin.y();
      behind += s->mask.contains(mx, my) && s->mask.at(mx, my) == 2;
    }
  EXPECT_GT(behind, 100);
  // Pieces of another paint stay apart.
  EXPECT_EQ(test::regions_with(run(back_hair_behind_the_neck(kOther)), 1), (std::vector<int>{1}));
  // Without the neck the pieces face each other across the paper, which
  // hides nothing.
  Drawing paper = blank(360, 300);
  paint(
      paper, [](double x, double y) { return x > 30 && x < 150 && y > 190 && y < 285; }, kBack, 1);
  paint(
      paper, [](double x, double y) { return x > 210 && x < 330 && y > 190 && y < 285; }, kBack, 2);
  paint_skin(paper, in_face, kSkin);
  EXPECT_EQ(test::regions_with(run(paper), 1), (std::vector<int>{1}));
}

// A horizontal gradient: 0.4 RGB a px along x on every channel from
// kBack at x = 150.
Rgba along_x(double x) { return test::along_x(kBack, 150, 0.4, x); }

TEST(BodyJoins, PiecesOfTwoGradientsAreNotJoinedBehindTheNeck) {
  // One gradient over both pieces carries on behind the neck: joined,
  // though the windows at the neck's sides step ~27 RGB.
  Drawing one = back_hair_behind_the_neck(kBack);
  test::repaint(one, 1, [](int x, int) { return along_x(x); });
  test::repaint(one, 2, [](int x, int) { return along_x(x); });
  EXPECT_EQ(test::regions_with(run(one), 1), (std::vector<int>{1, 2}));
  // The right piece mirrors the left one's gradient about the neck's
  // middle: the windows at the neck's sides are one colour, but no linear
  // field paints both pieces (they darken away from the neck both ways):
  // two locks. The windows alone joined them (gradient 2000-2099: 5 wrong
  // body joins, no right one).
  Drawing mirrored = back_hair_behind_the_neck(kBack);
  test::repaint(mirrored, 1, [](int x, int) { return along_x(x); });
  test::repaint(mirrored, 2, [](int x, int) { return along_x(360 - x); });
  EXPECT_EQ(test::regions_with(run(mirrored), 1), (std::vector<int>{1}));
}

TEST(BodyJoins, StrandsLyingOnTheNeckAreNotBackHair) {
  // Back hair (3, 4) beside the neck's top, and below it two strands (1, 2)
  // of another paint hanging over the neck: the neck lies on both sides of
  // each strand, so they lie in front of it, not behind. The back hair is
  // joined, the strands are not.
  Drawing d = blank(360, 300);
  paint(
      d, [](double x, double y) { return x > 30 && x <= 180 && y > 190 && y < 240; }, kBack, 3);
  paint(
      d, [](double x, double y) { return x > 180 && x < 330 && y > 190 && y < 240; }, kBack, 4);
  paint_skin(d, in_neck, kClothes);
  paint_skin(d, in_face, kSkin);
  paint(
      d, [](double x, double y) { return x > 156 && x < 172 && y > 245 && y < 295; }, kOther, 1);
  paint(
      d, [](double x, double y) { return x > 188 && x < 204 && y > 245 && y < 295; }, kOther, 2);
  const Result r = run(d);
  EXPECT_EQ(test::regions_with(r, 3), (std::vector<int>{3, 4}));
  EXPECT_EQ(test::regions_with(r, 1), (std::vector<int>{1}));
}

}  // namespace
}  // namespace hair25d::completion
