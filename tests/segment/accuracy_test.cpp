// Segmentation from the cases' strokes must reproduce their regions: mean
// region IoU >= 0.95, outline pixels left out (paper §3; issue 2).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "hair25d/core/annotation.h"
#include "hair25d/core/atomic_file.h"
#include "hair25d/core/image_io.h"
#include "hair25d/segment/mesh.h"
#include "hair25d/segment/overlay.h"
#include "hair25d/segment/regions.h"
#include "hair25d/segment/segmenter.h"
#include "segment_eval.h"
#ifdef HAIR25D_HAVE_GENERATOR
#include "hair25d/generator/generator.h"
#endif

namespace hair25d::segment {
namespace {

namespace fs = std::filesystem;

// Optional: HAIR25D_SEGMENT_DEBUG_DIR=<dir> writes each case's overlay there.
void maybe_write_overlay(const std::string& name, const Image& image, const SegmentResult& r,
                         const LabelMap& regions, const LabelMap& truth) {
  const char* dir = std::getenv("HAIR25D_SEGMENT_DEBUG_DIR");
  if (dir == nullptr) return;
  fs::create_directories(dir);
  save_image(fs::path(dir) / (name + "_overlay.png"), draw_overlay(image, r.segmentation, regions));
  save_image(fs::path(dir) / (name + "_truth.png"), draw_overlay(image, Segmentation{}, truth));
  const auto faces = automatic_regions(r.segmentation.mesh);
  save_image(fs::path(dir) / (name + "_faces.png"),
             draw_overlay(image, Segmentation{},
                          rasterize_triangle_values(r.segmentation.mesh, faces, image.width(),
                                                    image.height())));
}

double case_mean_iou(const std::string& name, const AnnotatedCase& c, double line_width) {
  const SegmentResult r = segment_image(c.image, &*c.strokes);
  const LabelMap predicted =
      region_map(c.image, r.segmentation.mesh, r.segmentation.triangle_region);
  maybe_write_overlay(name, c.image, r, predicted, c.regions);
  const LabelMap excluded = testing::outline_exclusion(c.regions, line_width);
  const auto scores = testing::region_ious(c.regions, predicted, excluded);
  if (const char* dir = std::getenv("HAIR25D_SEGMENT_DEBUG_DIR")) {
    // Wrong pixels in red over the faded drawing.
    Image diff = c.image;
    for (int y = 0; y < diff.height(); ++y)
      for (int x = 0; x < diff.width(); ++x) {
        Rgba& p = diff.at(x, y);
        p = {static_cast<std::uint8_t>(128 + p.r / 2), static_cast<std::uint8_t>(128 + p.g / 2),
             static_cast<std::uint8_t>(128 + p.b / 2), 255};
        if (!excluded.at(x, y) && c.regions.at(x, y) != predicted.at(x, y)) p = {255, 0, 0, 255};
      }
    save_image(fs::path(dir) / (name + "_diff.png"), diff);
  }
  std::string worst;
  for (const auto& s : scores)
    if (s.iou < 0.9)
      worst += " region " + std::to_string(s.label) + " (" + std::to_string(s.truth_pixels) +
               " px) IoU " + std::to_string(s.iou) + ";";
  const double m = testing::mean_iou(scores);
  std::printf(
      "[ segment ] %s: %zu regions, mean IoU %.4f, %d triangles, %zu curves, line width %.2f%s\n",
      name.c_str(), scores.size(), m, r.segmentation.mesh.triangle_count(),
      r.segmentation.curves.size(), r.line_width, worst.c_str());
  return m;
}

TEST(SegmentAccuracy, AnnotatedCasesReachMeanIoU095) {
  const fs::path root = fs::path(HAIR25D_TEST_DATA_DIR) / "annotated";
  const auto cases = find_annotated_cases(root);
  ASSERT_EQ(cases.size(), 6u);
  double sum = 0.0;
  for (const fs::path& folder : cases) {
    const AnnotatedCase c = read_annotated_case(folder);
    ASSERT_TRUE(c.strokes.has_value()) << folder;
    // The annotation records the drawing's line width; outlines are that wide.
    const auto doc = nlohmann::json::parse(read_text_file(folder / "layering.json"));
    const double line_width = doc.value("line_width", 6.0);
    const double m = case_mean_iou(c.name, c, line_width);
    EXPECT_GE(m, 0.85) << c.name;  // a floor per case; the mean is the goal
    sum += m;
  }
  const double mean = sum / static_cast<double>(cases.size());
  std::printf("[ segment ] annotated cases: mean IoU %.4f\n", mean);
  EXPECT_GE(mean, 0.95);
}

#ifdef HAIR25D_HAVE_GENERATOR
// Generated drawings over the styles the issue names: anti-aliased lines 2-6
// px wide, coloured lines, cel shading, gradients, screentone, noise, JPEG.
TEST(SegmentAccuracy, GeneratedCasesReachMeanIoU095) {
  struct Variant {
    const char* name;
    generator::Options o;
  };
  std::vector<Variant> variants;
  auto add = [&](const char* name, auto tweak) {
    generator::Options o;
    o.width = 720;
    o.height = 560;
    o.strand_count = 14;
    o.strand_masks = false;
    o.seed = 11 + variants.size();
    tweak(o);
    variants.push_back({name, o});
  };
  add("flat_w3", [](auto&) {});
  add("flat_w2", [](auto& o) { o.line_width = 2.0; });
  add("flat_w6", [](auto& o) { o.line_width = 6.0; });
  add("two_tone", [](auto& o) { o.shading = generator::Shading::kTwoTone; });
  add("gradient", [](auto& o) { o.shading = generator::Shading::kGradient; });
  add("screentone", [](auto& o) { o.shading = generator::Shading::kScreentone; });
  add("coloured_lines", [](auto& o) { o.coloured_lines = true; });
  add("noise", [](auto& o) { o.noise_sigma = 6.0; });
  add("jpeg", [](auto& o) { o.jpeg_quality = 60; });
  add("tall", [](auto& o) {
    o.width = 480;
    o.height = 760;
    o.line_width = 4.0;
  });
  double sum = 0.0;
  for (const Variant& v : variants) {
    const AnnotatedCase c = generator::generate_case(v.o);
    ASSERT_TRUE(c.strokes.has_value());
    const double m = case_mean_iou(std::string("generated_") + v.name, c, v.o.line_width);
    EXPECT_GE(m, 0.85) << v.name;
    sum += m;
  }
  const double mean = sum / static_cast<double>(variants.size());
  std::printf("[ segment ] generated cases: mean IoU %.4f\n", mean);
  EXPECT_GE(mean, 0.95);
}

// The set `hair25d-generate --count 12 --seed 1000 --shading -1` writes (640 ×
// 480, shading cycling flat, two-tone, gradient, screentone): dark hair on
// light paper among them, whose black outline is a line beside a dark fill.
// Mean 0.902 when that outline was missed, 0.930 since (docs/segment.md).
TEST(SegmentAccuracy, GeneratedSeed1000SetReachesMeanIoU092) {
  double sum = 0.0;
  constexpr int kCases = 12;
  for (int i = 0; i < kCases; ++i) {
    generator::Options o;
    o.seed = 1000 + i;
    o.shading = static_cast<generator::Shading>(i % 4);
    o.strand_masks = false;
    const AnnotatedCase c = generator::generate_case(o);
    ASSERT_TRUE(c.strokes.has_value());
    char name[32];
    std::snprintf(name, sizeof name, "seed%d", 1000 + i);
    const double m = case_mean_iou(name, c, o.line_width);
    EXPECT_GE(m, 0.78) << name;
    sum += m;
  }
  const double mean = sum / kCases;
  std::printf("[ segment ] seed 1000 set: mean IoU %.4f\n", mean);
  EXPECT_GE(mean, 0.92);
}
#endif

}  // namespace
}  // namespace hair25d::segment
