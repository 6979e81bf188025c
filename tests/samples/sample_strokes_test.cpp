// The stroke files shipped with the real drawings in samples/: they parse, name
// regions 1..n plus background, stay inside the picture, and no stroke touches
// a drawn (dark) line, so each stroke marks one region.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "hair25d/core/image_io.h"
#include "hair25d/core/strokes.h"

namespace hair25d {
namespace {

namespace fs = std::filesystem;

// Luminance of the pixel composited over white paper (transparent = paper).
int paper_luminance(const Rgba& p) {
  auto over_white = [&](int c) { return (c * p.a + 255 * (255 - p.a)) / 255; };
  return (299 * over_white(p.r) + 587 * over_white(p.g) + 114 * over_white(p.b)) / 1000;
}

// How strokes keep off lines in each drawing. Wikipe-tan and Sylvie have dark
// outlines on lighter fills: no stroke pixel may be as dark as a line. Lucy's
// hair is as dark as its lines, so there hair strokes must lie on dark
// unsaturated (hair) pixels and background strokes on light ones.
struct Drawing {
  const char* folder;
  std::size_t min_labels;
  bool dark_hair;
};

class SampleStrokes : public testing::TestWithParam<Drawing> {};

TEST_P(SampleStrokes, MarkRegionsOffTheLines) {
  const Drawing drawing = GetParam();
  const fs::path dir = fs::path(HAIR25D_SAMPLES_DIR) / drawing.folder;
  if (!fs::exists(dir / "strokes.json")) GTEST_SKIP() << "no strokes.json in " << dir;
  const Image image = load_image(dir / "image.png");
  const Strokes strokes = read_strokes(dir / "strokes.json");

  ASSERT_TRUE(strokes.head_center.has_value());
  EXPECT_TRUE(image.contains(static_cast<int>(strokes.head_center->x()),
                             static_cast<int>(strokes.head_center->y())));
  const std::vector<int> labels = strokes.labels();
  ASSERT_GE(labels.size(), drawing.min_labels);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    EXPECT_EQ(labels[i], static_cast<int>(i) + 1) << "labels are 1..n without gaps";
  }
  int background = 0;
  for (const Stroke& s : strokes.strokes) {
    background += s.label == 0;
    for (const Vec2& p : s.points) {
      EXPECT_TRUE(image.contains(static_cast<int>(p.x()), static_cast<int>(p.y())))
          << "label " << s.label << " point " << p.transpose();
    }
  }
  EXPECT_GE(background, 3);

  // Each stroke on its own, so overlaps between strokes do not hide pixels.
  constexpr int kLineLuminance = 90;  // outlines in the line drawings are darker
  constexpr int kDarkHair = 120;      // Lucy's hair is at most this bright
  for (const Stroke& s : strokes.strokes) {
    Strokes one;
    one.strokes = {s};
    const LabelMap painted = rasterize_strokes(one, image.width(), image.height());
    for (int y = 0; y < image.height(); ++y) {
      for (int x = 0; x < image.width(); ++x) {
        if (painted.at(x, y) == kNoStroke) continue;
        const int lum = paper_luminance(image.at(x, y));
        if (!drawing.dark_hair) {
          ASSERT_GE(lum, kLineLuminance) << drawing.folder << ": stroke of label " << s.label
                                         << " touches a line at " << x << "," << y;
        } else if (s.label > 0) {
          ASSERT_LE(lum, kDarkHair) << drawing.folder << ": hair stroke " << s.label
                                    << " leaves the hair at " << x << "," << y;
        } else {
          ASSERT_GT(lum, kDarkHair)
              << drawing.folder << ": background stroke on hair at " << x << "," << y;
        }
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Drawings, SampleStrokes,
                         testing::Values(Drawing{"wikipe-tan", 20, false},
                                         Drawing{"sylvie", 12, false}, Drawing{"lucy", 7, true}),
                         [](const testing::TestParamInfo<Drawing>& info) {
                           std::string name = info.param.folder;
                           std::erase(name, '-');
                           return name;
                         });

}  // namespace
}  // namespace hair25d
