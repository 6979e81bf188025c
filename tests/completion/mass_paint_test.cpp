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

using test::below;
using test::blank;
using test::Drawing;
using test::paint;

using test::kBack;
using test::kFan;

// Repaints the drawn pixels of `region` with colour(x, y).
void repaint(Drawing& d, int region, const std::function<Rgba(int, int)>& colour) {
  for (int y = 0; y < d.image.height(); ++y)
    for (int x = 0; x < d.image.width(); ++x)
      if (d.regions.at(x, y) == region) d.image.at(x, y) = colour(x, y);
}

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
// under strand 3 lying on both, strand 4 on the sliver only.
Drawing back_hair_and_sliver() {
  Drawing d = blank(300, 210);
  paint(
      d, [](double x, double y) { return x > 20 && x < 150 && y > 40 && y < 170; }, kBack, 1);
  paint(
      d, [](double x, double y) { return x > 150 && x < 200 && y > 40 && y < 170; }, kBack, 2);
  paint(
      d, [](double x, double y) { return x > 135 && x < 177 && y > 10 && y < 200; }, kFan, 3);
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

}  // namespace
}  // namespace hair25d::completion
