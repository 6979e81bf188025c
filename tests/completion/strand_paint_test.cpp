// The merged strand's paint judged as a whole (Options::strand_paint,
// strand_paint.h): a join whose two pieces pass the pair tests is refused
// when another piece already in one of the groups is painted apart from
// the other group.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hair25d/completion/completion.h"
#include "synthetic.h"

namespace hair25d::completion {
namespace {

using namespace test;

constexpr Rgba kBack{120, 90, 70, 255};
constexpr Rgba kStrand{200, 150, 110, 255};

// strand_under_band (pieces 1 above and 2 below band 3, over back 4) with
// piece 5 above piece 1 (x 100..140, y 30..70), the user's `equal` with it:
// 5 and 1 are one group before any join. Piece 2 is painted 1 RGB off
// piece 1, which the strand joins' flat step passes (1.5 RGB).
Drawing chain(Rgba first) {
  Drawing d = strand_under_band(kBack, kStrand);
  paint(
      d, [](double x, double y) { return x > 100 && x < 140 && y > 30 && y <= 70; }, first, 5);
  repaint(d, 2, [](int, int) { return Rgba{201, 150, 110, 255}; });
  d.relations.push_back(below(4, 5));
  d.relations.push_back({5, 1, Relation::kEqual, 1.0, true, false});
  return d;
}

std::vector<int> strand_of_2(const Drawing& d, bool strand_paint, Result* out = nullptr) {
  Options o;
  o.inpaint_background = false;
  o.face_joins = false;
  o.strand_paint = strand_paint;
  Result r = complete_strands(input_of(d, Vec2(125, 10)), o);
  std::vector<int> s = regions_with(r, 2);
  if (out) *out = std::move(r);
  return s;
}

Rgba scaled(Rgba c, double k) {
  const auto s = [k](std::uint8_t v) { return static_cast<std::uint8_t>(std::lround(v * k)); };
  return {s(c.r), s(c.g), s(c.b), 255};
}

TEST(StrandPaint, PieceOfTheGroupPaintedApartKeepsTheJoinOut) {
  // Piece 5 is 6 RGB off piece 1 and 7 off piece 2: the join 1-2 alone
  // passes, and without the check 5 comes into 2's strand with it.
  const Drawing d = chain(Rgba{194, 150, 110, 255});
  EXPECT_EQ(strand_of_2(d, false), (std::vector<int>{1, 2, 5}));
  Result r;
  EXPECT_EQ(strand_of_2(d, true, &r), (std::vector<int>{2}));
  EXPECT_EQ(regions_with(r, 1), (std::vector<int>{1, 5}));  // the user's equal stands
  ASSERT_EQ(r.paint_refusals.size(), 1u);
  const Result::PaintRefusal& f = r.paint_refusals.front();
  EXPECT_EQ(std::min(f.a, f.b), 1);
  EXPECT_EQ(std::max(f.a, f.b), 2);
  EXPECT_EQ(std::min(f.piece_a, f.piece_b), 2);
  EXPECT_EQ(std::max(f.piece_a, f.piece_b), 5);
}

TEST(StrandPaint, OnePaintAndItsShadeAreJoined) {
  // Piece 5 in the strand's paint, or in its cel shadow (0.72 of it, a
  // piece seen only in the band): one strand, nothing refused.
  for (const Rgba first : {kStrand, scaled(kStrand, 0.72)}) {
    Result r;
    EXPECT_EQ(strand_of_2(chain(first), true, &r), (std::vector<int>{1, 2, 5}));
    EXPECT_TRUE(r.paint_refusals.empty());
  }
}

TEST(StrandPaint, LayeringEqualOntoAGroupPaintedApartMakesNoStrand) {
  // Piece 6 above piece 5 (y 8..30) in 5's paint, the layering's equal
  // between them (not the user's, no evidence: never a weak one, so the
  // pair itself is trusted). 6 is 6 RGB off piece 1, already one group
  // with 5 by the user's equal: the equal unites nothing.
  const Rgba off{194, 150, 110, 255};
  Drawing d = chain(off);
  paint(
      d, [](double x, double y) { return x > 100 && x < 140 && y > 8 && y <= 30; }, off, 6);
  d.relations.push_back(below(4, 6));
  d.relations.push_back({6, 5, Relation::kEqual, 0.0, false, false});
  EXPECT_EQ(strand_of_2(d, false), (std::vector<int>{1, 2, 5, 6}));
  Result r;
  EXPECT_EQ(strand_of_2(d, true, &r), (std::vector<int>{2}));
  EXPECT_EQ(regions_with(r, 6), (std::vector<int>{6}));
  EXPECT_EQ(regions_with(r, 1), (std::vector<int>{1, 5}));
  ASSERT_FALSE(r.paint_refusals.empty());
  EXPECT_EQ(std::minmax(r.paint_refusals.front().a, r.paint_refusals.front().b), std::minmax(5, 6));
}

TEST(StrandPaint, LayeringEqualOfPiecesPaintedApartMakesNoStrand) {
  // Off screentone the layering's equal's own pieces are compared too: 5
  // and 1, 6 RGB apart, are not united; 1 and 2 are still joined.
  Drawing d = chain(Rgba{194, 150, 110, 255});
  d.relations.back() = {5, 1, Relation::kEqual, 0.0, false, false};
  EXPECT_EQ(strand_of_2(d, false), (std::vector<int>{1, 2, 5}));
  Result r;
  EXPECT_EQ(strand_of_2(d, true, &r), (std::vector<int>{1, 2}));
  ASSERT_EQ(r.paint_refusals.size(), 1u);
  EXPECT_EQ(std::minmax(r.paint_refusals.front().a, r.paint_refusals.front().b), std::minmax(1, 5));
}

}  // namespace
}  // namespace hair25d::completion
