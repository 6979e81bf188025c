// Joins across the face completed as §5.1 case 1: two C¹ Bézier curves from
// the ends of the pieces' outlines, the area between them filled — not the
// convex hull of the pieces' cut outlines (completion/src/join_curves.h).
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "hair25d/completion/completion.h"
#include "synthetic.h"

namespace hair25d::completion {
namespace {

// The shared synthetic drawings and helpers (synthetic.h).
using namespace test;

const Rgba kBack{110, 70, 60, 255};
const Rgba kSkin{252, 228, 205, 255};
const Rgba kInk{20, 15, 10, 255};
// A 420 × 300 drawing: a face (disc, 3 px ink outline, no region) over a
// band of back hair that sags behind it: an annulus round (210, −20) of
// radii 230 … 300, regions 1 (left) and 2 (right).
constexpr double kCx = 210, kCy = 150, kFace = 75;
constexpr double kBandX = 210, kBandY = -100, kInner = 230, kOuter = 300;

bool in_band(double x, double y) {
  const double r = std::hypot(x - kBandX, y - kBandY);
  return r > kInner && r < kOuter && y > kBandY;
}

Drawing sagging_band_behind_face() {
  Drawing d = blank(420, 300);
  paint(
      d, [](double x, double y) { return in_band(x, y) && x < kCx; }, kBack, 1);
  paint(
      d, [](double x, double y) { return in_band(x, y) && x >= kCx; }, kBack, 2);
  for (int y = 0; y < d.image.height(); ++y)
    for (int x = 0; x < d.image.width(); ++x) {
      const double r = std::hypot(x + 0.5 - kCx, y + 0.5 - kCy);
      if (r >= kFace) continue;
      d.image.at(x, y) = r > kFace - 3 ? kInk : kSkin;
      d.regions.at(x, y) = 0;
    }
  return d;
}

Result run(const Drawing& d) {
  Options o;
  o.inpaint_strands = false;
  o.inpaint_background = false;
  return complete_strands(test::input_of(d, Vec2(kCx, kCy)), o);
}

int mask_at(const CompletedStrand& s, int x, int y) {
  const int mx = x - s.origin.x(), my = y - s.origin.y();
  return s.mask.contains(mx, my) ? s.mask.at(mx, my) : 0;
}

// Top (or bottom) edge of the strand's mask in column x within the rows
// [y0, y1): the first (last) masked row, nullopt when none.
std::optional<double> edge_row(const CompletedStrand& s, int x, int y0, int y1, bool top) {
  std::optional<double> found;
  for (int y = y0; y < y1; ++y)
    if (mask_at(s, x, y) != 0) {
      if (top) return y;
      found = y + 1;
    }
  return found;
}

TEST(JoinCurves, PiecesSplitByTheFaceGiveABandOfTheirWidthNotAHull) {
  const Drawing d = sagging_band_behind_face();
  const Result r = run(d);
  const CompletedStrand* s = strand_with(r, 1);
  ASSERT_NE(s, nullptr);
  ASSERT_EQ(s->regions, (std::vector<int>{1, 2}));
  // In the middle columns the completed band lies where the annulus does,
  // 70 px wide, 130 … 200 at x = 210; the hull of the cut outlines would
  // span the rows between the cuts' ends (about 118 … 155) instead.
  for (int x = 190; x <= 230; x += 5) {
    const double dx = x + 0.5 - kBandX;
    const double top = kBandY + std::sqrt(kInner * kInner - dx * dx);
    const double bottom = kBandY + std::sqrt(kOuter * kOuter - dx * dx);
    int inside = 0, rows = 0;
    for (int y = static_cast<int>(top) + 3; y < static_cast<int>(bottom) - 3; ++y, ++rows)
      inside += mask_at(*s, x, y) == 2;
    SCOPED_TRACE(x);
    EXPECT_GE(inside, rows - 1) << "the band behind the face is completed";
    for (int y = 80; y < static_cast<int>(top) - 6; ++y)
      EXPECT_EQ(mask_at(*s, x, y), 0) << "above the band, y " << y;
    for (int y = static_cast<int>(bottom) + 6; y < 220; ++y)
      EXPECT_EQ(mask_at(*s, x, y), 0) << "below the band, y " << y;
  }
}

TEST(JoinCurves, CompletedPixelsLieOnTheFace) {
  const Drawing d = sagging_band_behind_face();
  const Result r = run(d);
  const CompletedStrand* s = strand_with(r, 1);
  ASSERT_NE(s, nullptr);
  int completed = 0;
  for (int y = 0; y < d.image.height(); ++y)
    for (int x = 0; x < d.image.width(); ++x) {
      if (mask_at(*s, x, y) != 2) continue;
      ++completed;
      // The face (with the lines along it, up to the outline reach) is the
      // only thing hiding the pieces; the drawn pieces stay as they are.
      EXPECT_LT(std::hypot(x + 0.5 - kCx, y + 0.5 - kCy), kFace + 3.0) << x << ", " << y;
      EXPECT_EQ(d.regions.at(x, y), 0) << x << ", " << y;
    }
  EXPECT_GT(completed, 1500);
}

// The outline of the joined strand continues without a kink where the
// curves meet the pieces' visible outlines: the slope of the mask's top and
// bottom edges just outside and just inside the face agree (C¹), at the
// four attachment points.
TEST(JoinCurves, JoinedOutlineIsC1WhereItMeetsThePieces) {
  const Drawing d = sagging_band_behind_face();
  const Result r = run(d);
  const CompletedStrand* s = strand_with(r, 1);
  ASSERT_NE(s, nullptr);
  for (bool top : {true, false}) {
    const double radius = top ? kInner : kOuter;
    for (int side : {-1, 1}) {
      // Where this edge of the annulus crosses the face's circle.
      double xa = kCx;
      for (double x = kCx; std::abs(x - kCx) < 200; x += side * 0.25) {
        const double dx = x - kBandX;
        if (std::abs(dx) >= radius) break;
        const double y = kBandY + std::sqrt(radius * radius - dx * dx);
        if (std::hypot(x - kCx, y - kCy) >= kFace) {
          xa = x;
          break;
        }
      }
      auto slope = [&](int from, int to) {  // least squares over the columns
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        int n = 0;
        for (int x = std::min(from, to); x <= std::max(from, to); ++x) {
          const auto e = edge_row(*s, x, 40, 260, top);
          if (!e) continue;
          sx += x, sy += *e, sxx += static_cast<double>(x) * x, sxy += x * *e, ++n;
        }
        EXPECT_GE(n, 5);
        return (n * sxy - sx * sy) / (n * sxx - sx * sx);
      };
      const int a = static_cast<int>(xa);
      const double outside = slope(a + side * 6, a + side * 16);
      const double inside = slope(a - side * 16, a - side * 6);
      SCOPED_TRACE(std::string(top ? "top" : "bottom") + (side < 0 ? " left" : " right"));
      EXPECT_LT(std::abs(std::atan(outside) - std::atan(inside)), 0.2)
          << "slopes " << outside << " outside, " << inside << " inside, at x " << xa;
    }
  }
}

}  // namespace
}  // namespace hair25d::completion
