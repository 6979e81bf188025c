// Transparent paper is no hair (paper §3; docs/segment.md): a region never
// claims a pixel whose alpha is below kOpaqueAlpha (128), whatever colour the
// file stores under it, and strokes over transparent pixels mark nothing.
#include <gtest/gtest.h>

#include <cmath>

#include "drawing.h"
#include "hair25d/core/error.h"
#include "hair25d/segment/graph_cut.h"
#include "hair25d/segment/mesh.h"
#include "hair25d/segment/regions.h"
#include "hair25d/segment/segmenter.h"

namespace hair25d::segment {
namespace {

// Transparent black, as most painting programs store an empty layer.
constexpr Rgba kClear{0, 0, 0, 0};

const Vec2 kLockCentre(100.0, 62.0), kLockRadii(72.0, 44.0);

// How far (about, pixels) the pixel centre lies inside the lock's edge.
double inside_lock(int x, int y) {
  const double u = (x + 0.5 - kLockCentre.x()) / kLockRadii.x();
  const double v = (y + 0.5 - kLockCentre.y()) / kLockRadii.y();
  return (1.0 - std::sqrt(u * u + v * v)) * std::min(kLockRadii.x(), kLockRadii.y());
}

// A dark brown lock on transparent paper, 200 × 130: the alpha is the
// coverage of each pixel by the ellipse (anti-aliased edge), the colour stays.
Image lock_on_clear(bool outline) {
  Image img(200, 130, kClear);
  const Vec2 c = kLockCentre, r = kLockRadii;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) {
      const double inside = inside_lock(x, y);
      const double cover = std::clamp(inside + 0.5, 0.0, 1.0);
      if (cover > 0.0)
        img.at(x, y) = {70, 45, 30, static_cast<std::uint8_t>(std::lround(255.0 * cover))};
    }
  if (outline) {
    Polyline ring;
    for (int i = 0; i < 120; ++i) {
      const double a = 2.0 * M_PI * i / 120;
      ring.emplace_back(c.x() + (r.x() - 1.5) * std::cos(a), c.y() + (r.y() - 1.5) * std::sin(a));
    }
    testing::draw_polyline(img, ring, 3.0, {20, 20, 20, 255}, true);
  }
  return img;
}

Strokes lock_strokes() {
  Strokes s;
  // One stroke inside the lock, one running out over the transparent paper.
  s.strokes.push_back(testing::stroke(1, {{70.0, 62.0}, {130.0, 62.0}}));
  s.strokes.push_back(testing::stroke(1, {{100.0, 40.0}, {100.0, 125.0}}, 5.0));
  return s;
}

// Transparent pixels (alpha < 128) claimed by a region; and the lock's pixels
// at least `depth` px inside its edge (past the outline and the triangles
// along it), and how many of those a region claims.
struct Claims {
  int transparent_claimed = 0, interior = 0, interior_claimed = 0;
};

Claims claims(const Image& img, const LabelMap& regions, double depth = 8.0) {
  Claims c;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) {
      if (img.at(x, y).a < kOpaqueAlpha && regions.at(x, y) > 0) ++c.transparent_claimed;
      if (inside_lock(x, y) >= depth) ++c.interior, c.interior_claimed += regions.at(x, y) > 0;
    }
  return c;
}

TEST(Transparency, RegionMapLeavesPixelsBelowHalfAlphaOut) {
  // 9 × 4, one label on both triangles; the alpha steps along x.
  Image img(9, 4, {200, 150, 90, 255});
  const std::uint8_t alpha[9] = {0, 1, 64, 127, 128, 129, 200, 254, 255};
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 9; ++x) img.at(x, y).a = alpha[x];
  const MeshResult m = build_mesh({}, 9, 4);
  const std::vector<int> labels(m.mesh.triangle_count(), 5);
  const LabelMap got = region_map(img, m.mesh, labels);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 9; ++x) EXPECT_EQ(got.at(x, y), x < 4 ? 0 : 5) << x << "," << y;
}

TEST(Transparency, StrokesNeverMakeTransparentPaperHair) {
  for (bool outline : {false, true}) {
    const Image img = lock_on_clear(outline);
    const Strokes strokes = lock_strokes();
    const SegmentResult r = segment_image(img, &strokes);
    const Segmentation& s = r.segmentation;
    const Claims pixels = claims(img, region_map(img, s.mesh, s.triangle_region));
    EXPECT_EQ(pixels.transparent_claimed, 0) << "outline " << outline;
    EXPECT_EQ(pixels.interior_claimed, pixels.interior) << "outline " << outline;
    // The triangles themselves: hair triangles hold only the lock's edge of
    // transparent paper, not the paper around it (the stored colour, black,
    // is nearer the dark lock than the paper is).
    const Claims triangles = claims(
        img, rasterize_triangle_values(s.mesh, s.triangle_region, img.width(), img.height()));
    EXPECT_LT(triangles.transparent_claimed, 200) << "outline " << outline;
  }
}

TEST(Transparency, AutomaticRegionsLeaveTransparentPaperOut) {
  const Image img = lock_on_clear(true);
  const SegmentResult r = segment_image(img, nullptr);
  const Segmentation& s = r.segmentation;
  // The lock inside its outline is region 1; the paper around is none, and
  // the ids stay 1..n.
  const LabelMap map = region_map(img, s.mesh, s.triangle_region);
  EXPECT_EQ(map.at(100, 62), 1);
  EXPECT_EQ(map.at(3, 3), 0);
  EXPECT_EQ(map.at(196, 126), 0);
  EXPECT_EQ(claims(img, map).transparent_claimed, 0);
  EXPECT_EQ(*std::max_element(s.triangle_region.begin(), s.triangle_region.end()), 1);
}

TEST(Transparency, OpaqueDrawingIsUnchangedByTheAlphaRule) {
  Image img = testing::split_rectangle(140, 90, 70.0);
  Strokes s;
  s.strokes.push_back(testing::stroke(1, {{20.0, 45.0}, {40.0, 45.0}}));
  s.strokes.push_back(testing::stroke(2, {{100.0, 45.0}, {120.0, 45.0}}));
  const SegmentResult r = segment_image(img, &s);
  const Segmentation& g = r.segmentation;
  const LabelMap a = region_map(img, g.mesh, g.triangle_region);
  const LabelMap b = rasterize_triangle_values(g.mesh, g.triangle_region, 140, 90);
  for (int y = 0; y < 90; ++y)
    for (int x = 0; x < 140; ++x) ASSERT_EQ(a.at(x, y), b.at(x, y));
}

TEST(Transparency, HairStrokesOnlyOverTransparentPaperAreAnError) {
  const Image img = lock_on_clear(false);
  Strokes s;
  s.strokes.push_back(testing::stroke(1, {{5.0, 5.0}, {5.0, 120.0}}));
  try {
    segment_image(img, &s);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("opaque"), std::string::npos) << e.what();
  }
}

TEST(Transparency, BadInput) {
  const Image img(12, 7, {255, 255, 255, 255});
  const MeshResult m = build_mesh({}, 12, 7);
  std::vector<int> labels(m.mesh.triangle_count() + 1, 1);
  EXPECT_THROW(region_map(img, m.mesh, labels), Error);
  EXPECT_THROW(clear_paper_regions(img, m.mesh, labels), Error);
  labels.pop_back();
  EXPECT_EQ(clear_paper_regions(img, m.mesh, labels), 0);
  // An empty image gives an empty map.
  EXPECT_TRUE(region_map(Image(), build_mesh({}, 1, 1).mesh, {1, 1}).empty());
}

}  // namespace
}  // namespace hair25d::segment
