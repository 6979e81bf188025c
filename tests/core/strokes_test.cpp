#include "hair25d/core/strokes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "common/temp_dir.h"
#include "hair25d/core/atomic_file.h"
#include "hair25d/core/error.h"

namespace hair25d {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_strokes(text, "s.json");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Strokes, ParsesTheDocumentedExample) {
  const Strokes s = parse_strokes(R"({
    "format": "hair25d-strokes/1", "head_center": [523.7, 663.7],
    "strokes": [
      {"label": 3, "width": 3, "points": [[471, 265], [413, 316], [333, 372]]},
      {"label": 0, "width": 5, "points": [[40, 40], [41, 41]]},
      {"label": 3, "width": 1.5, "points": [[1, 2]]}]})",
                                  "s.json");
  ASSERT_EQ(s.strokes.size(), 3u);
  EXPECT_EQ(s.strokes[0].label, 3);
  EXPECT_DOUBLE_EQ(s.strokes[0].width, 3.0);
  EXPECT_TRUE(s.strokes[0].points[2].isApprox(Vec2(333, 372)));
  ASSERT_TRUE(s.head_center.has_value());
  EXPECT_DOUBLE_EQ(s.head_center->y(), 663.7);
  EXPECT_EQ(s.labels(), std::vector<int>{3});
}

TEST(Strokes, MalformedFilesNameTheKeyAndTheRule) {
  EXPECT_NE(error_of("{").find("not valid JSON"), std::string::npos);
  EXPECT_NE(error_of("[]").find("expected an object"), std::string::npos);
  EXPECT_NE(error_of(R"({"strokes": []})").find("'format'"), std::string::npos);
  EXPECT_NE(error_of(R"({"format": "other/2", "strokes": []})").find("hair25d-strokes/1"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"format": "hair25d-strokes/1"})").find("'strokes'"), std::string::npos);
  const std::string head = R"({"format": "hair25d-strokes/1", "strokes": [)";
  EXPECT_NE(
      error_of(head + R"({"label": -1, "width": 3, "points": [[1,2]]}]})").find("strokes[0].label"),
      std::string::npos);
  EXPECT_NE(
      error_of(head + R"({"label": 1.5, "width": 3, "points": [[1,2]]}]})").find("an integer"),
      std::string::npos);
  EXPECT_NE(error_of(head + R"({"label": 1, "width": 0.5, "points": [[1,2]]}]})").find(">= 1"),
            std::string::npos);
  EXPECT_NE(
      error_of(head + R"({"label": 1, "width": 2, "points": []}]})").find("at least one point"),
      std::string::npos);
  EXPECT_NE(error_of(head + R"({"label": 1, "width": 2, "points": [[1,2],[3]]}]})")
                .find("strokes[0].points[1]"),
            std::string::npos);
  EXPECT_NE(error_of(head + R"({"label": 1, "width": 2, "points": [[1,"x"]]}]})").find("[x, y]"),
            std::string::npos);
  EXPECT_NE(error_of(head + R"(7]})").find("strokes[0]"), std::string::npos);
  EXPECT_NE(error_of(R"({"format": "hair25d-strokes/1", "head_center": [1], "strokes": []})")
                .find("head_center"),
            std::string::npos);
  // Every message names the file.
  EXPECT_EQ(error_of("{").rfind("s.json", 0), 0u);
}

TEST(Strokes, EmptyStrokeListIsValidMarkup) {
  const Strokes s = parse_strokes(R"({"format": "hair25d-strokes/1", "strokes": []})", "s.json");
  EXPECT_TRUE(s.strokes.empty());
  EXPECT_TRUE(s.labels().empty());
}

TEST(Strokes, RasterizeClipsOutsidePointsAndPaintsLaterOverEarlier) {
  Strokes s;
  s.strokes.push_back({1, 3.0, {{-50, 2}, {50, 2}}});  // crosses the whole image and beyond
  s.strokes.push_back({0, 1.0, {{4, 2}}});             // a dot over it
  s.strokes.push_back({2, 1.0, {{100, 100}}});         // wholly outside
  const LabelMap m = rasterize_strokes(s, 9, 5);
  EXPECT_EQ(m.at(0, 2), 1);
  EXPECT_EQ(m.at(8, 2), 1);
  EXPECT_EQ(m.at(8, 1), 1);  // width 3 covers the rows beside
  EXPECT_EQ(m.at(8, 4), kNoStroke);
  EXPECT_EQ(m.at(4, 2), 0);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 9; ++x) EXPECT_NE(m.at(x, y), 2);
}

// A thin stroke along pixel corners lies half a pixel from every centre:
// with a radius of 0.5 it marked nothing (a width-1 dot at (5.5, 4.5) gave
// no pixel, and segmentation then said there was no hair stroke).
TEST(Strokes, ThinBrushesMarkThePixelsTheyPassThrough) {
  Strokes s;
  s.strokes.push_back({1, 1.0, {{5.5, 4.5}, {5.6, 4.6}}});
  s.strokes.push_back({2, 1.0, {{0.5, 8.5}, {6.5, 8.5}}});  // along a row of corners
  const LabelMap m = rasterize_strokes(s, 11, 10);
  EXPECT_EQ(m.at(5, 4), 1);
  EXPECT_EQ(m.at(6, 5), 1);
  for (int x = 1; x <= 6; ++x) {
    EXPECT_EQ(m.at(x, 8), 2) << x;
    EXPECT_EQ(m.at(x, 9), 2) << x;
  }
  // Still thin: no pixel a whole pixel away is marked.
  EXPECT_EQ(m.at(4, 4), kNoStroke);
  EXPECT_EQ(m.at(3, 7), kNoStroke);
  EXPECT_EQ(m.at(8, 8), kNoStroke);
}

// The brush by its definition, pixel by pixel: every pixel within r of the
// whole (unclipped) segment.
LabelMap reference_stroke(const Vec2& a, const Vec2& b, double r, int w, int h) {
  LabelMap m(w, h, kNoStroke);
  const Vec2 d = b - a;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Vec2 p(x, y);
      const double t =
          d.squaredNorm() > 0.0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
      if ((p - (a + t * d)).squaredNorm() <= r * r) m.at(x, y) = 1;
    }
  return m;
}

TEST(Strokes, FarOutsidePointsAreClippedAsNearOnesAre) {
  const int w = 70, h = 45;
  auto one = [&](Vec2 a, Vec2 b, double width) {
    Strokes s;
    s.strokes.push_back({1, width, {a, b}});
    return rasterize_strokes(s, w, h);
  };
  // Horizontal, vertical, diagonal and leftward strokes leaving the image: an
  // end point at 5e9 (beyond int) paints what one just outside does.
  const LabelMap right = one({10, 20}, {5e9, 20}, 3);
  EXPECT_EQ(right, one({10, 20}, {w + 60, 20}, 3));
  for (int x = 10; x < w; ++x) ASSERT_EQ(right.at(x, 20), 1) << x;
  EXPECT_EQ(one({30, 7}, {30, 5e9}, 2), one({30, 7}, {30, h + 60}, 2));
  EXPECT_EQ(one({3, 3}, {5e9 + 3, 5e9 + 3}, 3), one({3, 3}, {203, 203}, 3));
  EXPECT_EQ(one({60, 9}, {-5e9, 9}, 4), one({60, 9}, {-60, 9}, 4));
  // Both ends far outside on either side, up to the largest doubles.
  const LabelMap across = one({-1.7e308, 12}, {1.7e308, 12}, 1);
  EXPECT_EQ(across, one({-80, 12}, {w + 80, 12}, 1));
  for (int x = 0; x < w; ++x) ASSERT_EQ(across.at(x, 12), 1) << x;
  // Wholly outside, even with a wide brush that stops short of the image.
  const LabelMap outside = one({-5e9, -30}, {5e9, -30}, 50);
  for (int i = 0; i < w * h; ++i) ASSERT_EQ(outside.data()[i], kNoStroke);
}

TEST(Strokes, ClippingPaintsExactlyTheBrushesDefinition) {
  const int w = 37, h = 23;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-120.0, 150.0), width(1.0, 30.0);
  int painted = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Vec2 a(coord(rng), coord(rng)), b(coord(rng), coord(rng));
    const double wd = width(rng);
    Strokes s;
    s.strokes.push_back({1, wd, {a, b}});
    const LabelMap got = rasterize_strokes(s, w, h);
    ASSERT_EQ(got, reference_stroke(a, b, std::max(kMinBrushRadius, wd / 2), w, h))
        << "trial " << trial << ": " << a.transpose() << " -> " << b.transpose() << " width " << wd;
    for (int i = 0; i < w * h; ++i) painted += got.data()[i] == 1;
  }
  EXPECT_GT(painted, 0);  // the strokes do reach the image
}

TEST(Strokes, AbsurdWidthsAreClampedToTheImageDiagonal) {
  const int w = 41, h = 26;
  auto dot = [&](Vec2 p, double width) {
    Strokes s;
    s.strokes.push_back({2, width, {p}});
    return rasterize_strokes(s, w, h);
  };
  // From inside the image a brush wider than the diagonal covers it all.
  const LabelMap huge = dot({5, 5}, 1e300);
  EXPECT_EQ(huge, dot({5, 5}, 1e6));
  for (int i = 0; i < w * h; ++i) ASSERT_EQ(huge.data()[i], 2);
  Strokes line;
  line.strokes.push_back({3, 1e300, {{-5e9, 3}, {5e9, 3}}});
  const LabelMap all = rasterize_strokes(line, w, h);
  for (int i = 0; i < w * h; ++i) ASSERT_EQ(all.data()[i], 3);
  // From outside, the radius is the diagonal (the documented clamp): a dot
  // just under one diagonal right of the image's last column reaches that
  // column only.
  const double diagonal = std::hypot(double(w), double(h));
  const LabelMap far = dot({w - 1 + diagonal - 0.25, 0}, 1e300);
  EXPECT_EQ(far.at(w - 1, 0), 2);
  EXPECT_EQ(far.at(w - 2, 0), kNoStroke);
}

TEST(Strokes, WriteThenReadRoundTrips) {
  testing::TempDir dir;
  Strokes s;
  s.head_center = Vec2(10.5, 20.25);
  s.strokes.push_back({4, 2.5, {{1, 2}, {3, 4}}});
  write_strokes(dir / "s.json", s);
  const Strokes back = read_strokes(dir / "s.json");
  ASSERT_EQ(back.strokes.size(), 1u);
  EXPECT_EQ(back.strokes[0].label, 4);
  EXPECT_DOUBLE_EQ(back.strokes[0].width, 2.5);
  EXPECT_TRUE(back.head_center->isApprox(*s.head_center));
  EXPECT_THROW(read_strokes(dir / "missing.json"), Error);
}

}  // namespace
}  // namespace hair25d
