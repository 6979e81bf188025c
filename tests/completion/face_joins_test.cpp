// Joins across the face: back hair seen on both sides of the face is one
// piece hidden by the face, which is no region (completion/src/face_joins.h).
#include <gtest/gtest.h>

#include <cmath>

#include "hair25d/completion/completion.h"
#include "synthetic.h"

namespace hair25d::completion {
namespace {

// The shared synthetic drawings and helpers (synthetic.h).
using namespace test;

const Rgba kBack{110, 70, 60, 255};
const Rgba kOther{60, 150, 210, 255};
const Rgba kBang{150, 100, 80, 255};
const Rgba kSkin{252, 228, 205, 255};
const Rgba kInk{20, 15, 10, 255};
constexpr double kCx = 180, kCy = 140, kRadius = 70;

bool in_face(double x, double y) { return std::hypot(x - kCx, y - kCy) < kRadius; }

// The face: skin with a 3 px ink outline, no region (label 0), painted over
// whatever is below it.
void paint_face(Drawing& d) {
  for (int y = 0; y < d.image.height(); ++y)
    for (int x = 0; x < d.image.width(); ++x) {
      const double r = std::hypot(x + 0.5 - kCx, y + 0.5 - kCy);
      if (r >= kRadius) continue;
      d.image.at(x, y) = r > kRadius - 3 ? kInk : kSkin;
      d.regions.at(x, y) = 0;
    }
  // Eyes: dark dots on the face.
  for (double ex : {kCx - 28, kCx + 28})
    for (int y = 0; y < d.image.height(); ++y)
      for (int x = 0; x < d.image.width(); ++x)
        if (std::hypot(x + 0.5 - ex, y + 0.5 - (kCy - 5)) < 8) d.image.at(x, y) = kInk;
}

// A 360 × 260 drawing: a band of back hair behind the face (regions 1 left
// and 2 right, `right` its colour), the face, bangs (3) over the face's top.
Drawing face_over_back_hair(Rgba right) {
  Drawing d = blank(360, 260);
  paint(
      d, [](double x, double y) { return x > 30 && x < 180 && y > 95 && y < 215; }, kBack, 1);
  paint(
      d, [](double x, double y) { return x >= 180 && x < 330 && y > 95 && y < 215; }, right, 2);
  paint_face(d);
  paint(
      d, [](double x, double y) { return x > 80 && x < 280 && y > 40 && y < 100; }, kBang, 3);
  d.relations = {below(1, 3), below(2, 3)};
  return d;
}

Result run(const Drawing& d) {
  const Input in = test::input_of(d, Vec2(kCx, kCy + 10));
  Options o;
  o.inpaint_strands = false;
  o.inpaint_background = false;
  // The face joins alone: path joins (mass_joins_test.cpp) also join pieces
  // whose tops lie under the bangs, and back hair over tails is back hair
  // to them as to the mass joins.
  o.path_joins = false;
  return complete_strands(in, o);
}

bool completed(const CompletedStrand& s, int x, int y) {
  const int mx = x - s.origin.x(), my = y - s.origin.y();
  return s.mask.contains(mx, my) && s.mask.at(mx, my) == 2;
}

TEST(FaceJoins, BackHairOnBothSidesOfTheFaceIsJoinedBehindIt) {
  const Drawing d = face_over_back_hair(kBack);
  const Result r = run(d);
  const CompletedStrand* s = strand_with(r, 1);
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->regions, (std::vector<int>{1, 2}));
  const CompletedStrand* bang = strand_with(r, 3);
  ASSERT_NE(bang, nullptr);
  EXPECT_EQ(bang->regions, (std::vector<int>{3}));
  // The completed part lies behind the face or the bangs only, never where
  // the drawing shows the paper.
  for (int y = 0; y < s->mask.height(); ++y)
    for (int x = 0; x < s->mask.width(); ++x) {
      if (s->mask.at(x, y) != 2) continue;
      const int gx = x + s->origin.x(), gy = y + s->origin.y();
      const int l = r.regions.at(gx, gy);
      EXPECT_TRUE(l == 3 || (l == 0 && in_face(gx + 0.5, gy + 0.5)))
          << "completed pixel at " << gx << "," << gy << " shows " << l;
    }
  // Most of the band behind the face, 8 px in from its outline, is completed.
  int inside = 0, done = 0;
  for (int y = 105; y < 205; ++y)
    for (int x = 120; x < 240; ++x) {
      if (std::hypot(x + 0.5 - kCx, y + 0.5 - kCy) > kRadius - 8) continue;
      ++inside;
      done += completed(*s, x, y);
    }
  ASSERT_GT(inside, 1000);
  EXPECT_GT(done, 0.8 * inside);
  // The paper above the band, beside the face, stays uncompleted.
  EXPECT_FALSE(completed(*s, 100, 80));
  EXPECT_FALSE(completed(*s, 260, 80));
  int joined = 0;
  for (const EdgeReport& e : r.edges)
    if (e.completion == EdgeCase::kJoined && (e.region == 1 || e.region == 2))
      joined += e.joined_region == 3 - e.region;
  EXPECT_GE(joined, 2);
  // Without face joins the two pieces stay apart (the face is no occluder).
  const Input in = test::input_of(d, Vec2(kCx, kCy + 10));
  Options o;
  o.inpaint_strands = o.inpaint_background = false;
  o.face_joins = false;
  o.path_joins = false;
  const Result off = complete_strands(in, o);
  ASSERT_NE(strand_with(off, 1), nullptr);
  EXPECT_EQ(strand_with(off, 1)->regions, (std::vector<int>{1}));
}

TEST(FaceJoins, PiecesOfAnotherColourAreNotJoined) {
  const Result r = run(face_over_back_hair(kOther));
  ASSERT_NE(strand_with(r, 1), nullptr);
  EXPECT_EQ(strand_with(r, 1)->regions, (std::vector<int>{1}));
}

TEST(FaceJoins, PiecesOfOtherFlatPaintsAreNotJoined) {
  // 10 RGB off the back's paint: within max_colour_distance (the old rules
  // joined it), but on a cel drawing another flat paint is another lock
  // (generated seed 2064: a tail 7 RGB off the back, joined across the face).
  const Result r = run(face_over_back_hair(Rgba{116, 76, 66, 255}));
  ASSERT_NE(strand_with(r, 1), nullptr);
  EXPECT_EQ(strand_with(r, 1)->regions, (std::vector<int>{1}));
  // The same paint is joined.
  const Result same = run(face_over_back_hair(kBack));
  ASSERT_NE(strand_with(same, 1), nullptr);
  EXPECT_EQ(strand_with(same, 1)->regions, (std::vector<int>{1, 2}));
}

TEST(FaceJoins, PiecesOfTwoGradientsAreNotJoined) {
  // One gradient over both pieces (0.2 RGB a px along x) carries on behind
  // the face: joined, though the pieces' mean colours lie ~52 RGB apart.
  const auto gradient = [](int x, int) { return test::along_x(kBack, 180, 0.2, x); };
  Drawing one = face_over_back_hair(kBack);
  test::repaint(one, 1, gradient);
  test::repaint(one, 2, gradient);
  ASSERT_NE(strand_with(run(one), 1), nullptr);
  EXPECT_EQ(strand_with(run(one), 1)->regions, (std::vector<int>{1, 2}));
  // The right piece leaves the face's middle in the same colour but at
  // 0.45 RGB a px: within max_colour_distance, but no linear field paints
  // both pieces: two locks (gradient 2000-2099 and 3000-3099: 16 wrong face
  // joins of 27, tails and strands lying on the face joined to the back
  // hair).
  Drawing two = face_over_back_hair(kBack);
  test::repaint(two, 1, gradient);
  test::repaint(two, 2, [](int x, int) { return test::along_x(kBack, 180, 0.45, x); });
  ASSERT_NE(strand_with(run(two), 1), nullptr);
  EXPECT_EQ(strand_with(run(two), 1)->regions, (std::vector<int>{1}));
}

TEST(FaceJoins, PiecesAboveOtherHairAreNotBackHair) {
  // The same band, but each piece lies over a lock of hair (4, 5) at the
  // canvas sides: they are front hair, not the bottom layer.
  Drawing d = face_over_back_hair(kBack);
  paint(
      d, [](double x, double y) { return x > 5 && x < 45 && y > 150 && y < 250; }, kBack, 4);
  paint(
      d, [](double x, double y) { return x > 315 && x < 355 && y > 150 && y < 250; }, kBack, 5);
  d.relations.push_back(below(4, 1));
  d.relations.push_back(below(5, 2));
  const Result r = run(d);
  ASSERT_NE(strand_with(r, 1), nullptr);
  EXPECT_EQ(std::count(strand_with(r, 1)->regions.begin(), strand_with(r, 1)->regions.end(), 2), 0);
}

TEST(FaceJoins, StrandTipsLyingOnTheFaceAreNotJoined) {
  // Two strands reaching onto the face from left and right, their round
  // tips drawn over it: the face does not hide them, they end there.
  Drawing d = blank(360, 260);
  paint_face(d);
  paint(
      d,
      [](double x, double y) {
        return (x > 30 && x < 150 && std::abs(y - 160) < 22) || std::hypot(x - 150, y - 160) < 22;
      },
      kBack, 1);
  paint(
      d,
      [](double x, double y) {
        return (x > 210 && x < 330 && std::abs(y - 160) < 22) || std::hypot(x - 210, y - 160) < 22;
      },
      kBack, 2);
  paint(
      d, [](double x, double y) { return x > 80 && x < 280 && y > 40 && y < 100; }, kBang, 3);
  const Result r = run(d);
  ASSERT_NE(strand_with(r, 1), nullptr);
  EXPECT_EQ(strand_with(r, 1)->regions, (std::vector<int>{1}));
}

TEST(FaceJoins, TailsHangingFromUnderTheBackHairAreNotJoined) {
  // The same pieces, now hanging from under a band of back hair (5, itself
  // under a bang 6) instead of under bangs: tails (lowest regions covered
  // only by back hair that lies over nothing else), not back hair seen on
  // both sides of the face. The generator's twin tails were joined so.
  Drawing d = blank(360, 260);
  paint(
      d, [](double x, double y) { return x > 30 && x < 180 && y > 95 && y < 215; }, kBack, 1);
  paint(
      d, [](double x, double y) { return x >= 180 && x < 330 && y > 95 && y < 215; }, kBack, 2);
  paint_face(d);
  paint(
      d,
      [](double x, double y) { return x > 20 && x < 340 && y > 40 && y < 100 && !in_face(x, y); },
      kBack, 5);
  paint(
      d, [](double x, double y) { return x > 150 && x < 210 && y > 20 && y < 90; }, kBang, 6);
  d.relations = {below(1, 5), below(2, 5), below(5, 6)};
  const Result r = run(d);
  const CompletedStrand* s = strand_with(r, 1);
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->regions, (std::vector<int>{1}));
}

// Path joins (mass_paths.cpp) take pieces above no region for back hair.
// Two thin strands (1, 2) lying on the face hang from under a bang (3) whose
// tongue reaches down between them, so a path runs from one to the other
// under the bang, its chord under the bang or over 3 px face gaps (generated
// 1000 x 800 seed 14: bangs 17 and 11 joined under bang 20 this way). The
// bang lies on a strand (4) over back hair (5), so 1 and 2 are no tails.
Drawing strands_lying_on_the_face() {
  Drawing d = blank(360, 260);
  paint_face(d);
  paint(
      d, [](double x, double y) { return x > 40 && x < 320 && y > 5 && y < 32; }, kBack, 5);
  paint(
      d, [](double x, double y) { return x > 60 && x < 100 && y > 20 && y < 62; }, kOther, 4);
  paint(
      d, [](double x, double y) { return x > 165 && x < 172 && y > 98 && y < 165; }, kBack, 1);
  paint(
      d, [](double x, double y) { return x > 188 && x < 195 && y > 98 && y < 165; }, kBack, 2);
  paint(
      d,
      [](double x, double y) {
        return (x > 110 && x < 250 && y > 72 && y < 110) || (x > 175 && x < 185 && y < 125);
      },
      kBang, 3);
  d.relations = {below(1, 3), below(2, 3), below(4, 3), below(5, 4)};
  return d;
}

TEST(PathJoins, StrandsLyingOnTheFaceAreNotBackHair) {
  const Drawing d = strands_lying_on_the_face();
  const Input in = test::input_of(d, Vec2(kCx, kCy + 10));
  Options o;
  o.inpaint_strands = false;
  o.inpaint_background = false;
  // No strand join (tangents within 0.5 degrees of the chord, widths within
  // 1 %): only the region-level joins could join them.
  o.max_join_angle_deg = 0.5;
  o.min_width_ratio = 0.99;
  EXPECT_EQ(test::regions_with(complete_strands(in, o), 1), (std::vector<int>{1}));
  EXPECT_EQ(test::regions_with(complete_strands(in, o), 2), (std::vector<int>{2}));
  // Without the face (face joins off: no face is looked for) the path join
  // takes them for back hair and joins them.
  o.face_joins = false;
  EXPECT_EQ(test::regions_with(complete_strands(in, o), 1), (std::vector<int>{1, 2}));
}

}  // namespace
}  // namespace hair25d::completion
