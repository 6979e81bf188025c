// The crop of the drawing around a strand-join candidate (session 28,
// completion/src/join_crop.h): the chord between the cuts runs left to
// right through the centre, piece a on the left, piece b on the right,
// whichever way the join runs in the drawing.
#include "join_crop.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "hair25d/completion/completion.h"
#include "invalid_options.h"

namespace hair25d::completion::detail {
namespace {

constexpr int kSize = 20;
const Rgba kRed{200, 30, 20, 255}, kBlue{20, 40, 210, 255}, kGrey{90, 90, 90, 255};

// Two pieces 1 (red) and 2 (blue) of a strand running along x, cut by
// region 3 (grey) over x in [35, 55); with `transpose` the same drawing
// with x and y swapped (the strand runs down). The image is 90 × 60 (or
// 60 × 90), never square.
struct Drawing {
  Image image;
  LabelMap labels;
  Vec2 pa, qa, pb, qb;
  Polyline patch;
};

Drawing make_drawing(bool transpose) {
  const int w = 90, h = 60;
  Drawing d{transpose ? Image(h, w, Rgba{}) : Image(w, h, Rgba{}),
            transpose ? LabelMap(h, w) : LabelMap(w, h)};
  auto put = [&](int x, int y, int label, Rgba c) {
    if (transpose) std::swap(x, y);
    d.labels.at(x, y) = label;
    d.image.at(x, y) = c;
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (x >= 35 && x < 55 && y >= 10 && y < 50)
        put(x, y, 3, kGrey);
      else if (x >= 5 && x < 35 && y >= 20 && y < 40)
        put(x, y, 1, kRed);
      else if (x >= 55 && x < 85 && y >= 20 && y < 40)
        put(x, y, 2, kBlue);
    }
  auto pt = [&](double x, double y) { return transpose ? Vec2(y, x) : Vec2(x, y); };
  d.pa = pt(35, 20), d.qa = pt(35, 40), d.pb = pt(55, 40), d.qb = pt(55, 20);
  d.patch = {pt(35, 20), pt(55, 20), pt(55, 40), pt(35, 40)};
  return d;
}

struct Planes {
  std::vector<std::uint8_t> data;
  int at(int channel, int col, int row) const {
    return data[static_cast<std::size_t>(channel) * kSize * kSize + row * kSize + col];
  }
  // Pixels of a mask in the columns [c0, c1).
  int count(int channel, int c0, int c1) const {
    int n = 0;
    for (int row = 0; row < kSize; ++row)
      for (int col = c0; col < c1; ++col) n += at(channel, col, row) > 0;
    return n;
  }
};

Planes crop_of(const Drawing& d, int a, int b) {
  const bool forward = a == 1;
  const JoinCropFrame f = forward ? join_crop_frame(d.pa, d.qa, d.pb, d.qb, kSize)
                                  : join_crop_frame(d.pb, d.qb, d.pa, d.qa, kSize);
  return {render_join_crop(
      d.image, d.labels, a, b, [](int l) { return l == 3; }, d.patch, f)};
}

// The chord (35, 30) → (55, 30) is 20 px, the cuts 20 px: the crop spans
// 40 px, 2 px a crop pixel, from x 25 and y 10. Piece a fills columns 0-4,
// the occluder 5-14, piece b 15-19; the patch the occluder's columns
// between rows 5 and 14.
void expect_aligned(const Planes& p, Rgba colour_a) {
  EXPECT_EQ(p.count(3, 0, 5), 5 * 10) << "piece a: columns 0-4, rows 5-14";
  EXPECT_EQ(p.count(3, 5, kSize), 0) << "piece a right of the occluder";
  EXPECT_EQ(p.count(4, 15, kSize), 5 * 10) << "piece b: columns 15-19";
  EXPECT_EQ(p.count(4, 0, 15), 0) << "piece b left of the occluder";
  EXPECT_EQ(p.count(5, 5, 15), 10 * 20) << "the occluder: columns 5-14, every row";
  EXPECT_EQ(p.count(5, 0, 5) + p.count(5, 15, kSize), 0);
  EXPECT_EQ(p.count(6, 0, kSize), 0) << "no other hair";
  EXPECT_GE(p.count(7, 5, 15), 9 * 9) << "the patch lies between the cuts";
  EXPECT_LE(p.count(7, 5, 15), 11 * 11);
  EXPECT_EQ(p.count(7, 0, 4) + p.count(7, 16, kSize), 0);
  // Drawn colours where a lies; paper (transparent) white above and below.
  EXPECT_EQ(p.at(0, 2, 10), colour_a.r);
  EXPECT_EQ(p.at(1, 2, 10), colour_a.g);
  EXPECT_EQ(p.at(2, 2, 10), colour_a.b);
  EXPECT_EQ(p.at(0, 2, 0), 255);
  EXPECT_EQ(p.at(2, 2, 0), 255);
}

TEST(JoinCrop, ChordRunsLeftToRightWithPieceAOnTheLeft) {
  expect_aligned(crop_of(make_drawing(false), 1, 2), kRed);
}

TEST(JoinCrop, AStrandRunningDownIsTurnedToRunAcross) {
  expect_aligned(crop_of(make_drawing(true), 1, 2), kRed);
}

TEST(JoinCrop, PiecesTheOtherWayRoundSwapSides) {
  expect_aligned(crop_of(make_drawing(false), 2, 1), kBlue);
  expect_aligned(crop_of(make_drawing(true), 2, 1), kBlue);
}

// The frame maps the cuts' middles a quarter and three quarters across the
// middle row, and back.
TEST(JoinCrop, FrameMapsTheCutsAndBack) {
  const Drawing d = make_drawing(true);
  const JoinCropFrame f = join_crop_frame(d.pa, d.qa, d.pb, d.qb, kSize);
  const Vec2 a = f.to_crop(0.5 * (d.pa + d.qa)), b = f.to_crop(0.5 * (d.pb + d.qb));
  EXPECT_NEAR(a.x(), kSize / 4.0 - 0.5, 1e-9);
  EXPECT_NEAR(b.x(), 3 * kSize / 4.0 - 0.5, 1e-9);
  EXPECT_NEAR(a.y(), kSize / 2.0 - 0.5, 1e-9);
  EXPECT_NEAR(b.y(), kSize / 2.0 - 0.5, 1e-9);
  const Vec2 p = f.to_drawing(3.25, 17.5);
  EXPECT_NEAR((f.to_crop(p) - Vec2(3.25, 17.5)).norm(), 0.0, 1e-9);
}

// Cuts on one spot (touching pieces) still give a crop of the minimum side.
TEST(JoinCrop, TouchingCutsGiveTheMinimumSide) {
  const JoinCropFrame f = join_crop_frame({10, 10}, {10, 13}, {10, 13}, {10, 10}, kSize);
  EXPECT_NEAR(f.side, 16.0, 1e-9);
  EXPECT_NEAR(f.along.norm(), 1.0, 1e-9);
}

TEST(JoinCrop, CropSizeOutOfRangeIsRefused) {
  JoinScorerOptions o;
  o.crop_size = -1;
  std::string error;
  test::expect_invalid(o, "crop_size = -1");
  o.crop_size = 48;
  EXPECT_TRUE(o.is_valid(&error));
}

}  // namespace
}  // namespace hair25d::completion::detail
