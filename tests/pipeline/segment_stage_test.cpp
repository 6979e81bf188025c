// The segmentation stage as the pipeline runs it: outputs, writing the
// output folder, and bad input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "common/temp_dir.h"
#include "hair25d/core/error.h"
#include "hair25d/core/image_io.h"
#include "hair25d/pipeline/segment_stage.h"
#include "hair25d/segment/segmentation_io.h"

namespace hair25d::pipeline {
namespace {

namespace fs = std::filesystem;

// A 96 x 64 light drawing split by a dark vertical line at x = 40.
Image split_drawing() {
  Image img(96, 64, {240, 210, 140, 255});
  for (int y = 0; y < 64; ++y)
    for (int x = 39; x <= 41; ++x) img.at(x, y) = {15, 15, 15, 255};
  return img;
}

class CountingProgress final : public Progress {
 public:
  void report(std::string_view, double fraction, std::string_view) override {
    last = fraction;
    ++calls;
  }
  double last = -1.0;
  int calls = 0;
};

TEST(SegmentStage, StrokesGiveLabelledRegionsAndOverlay) {
  const Image img = split_drawing();
  Strokes s;
  s.strokes = {{3, 3.0, {{10, 30}, {20, 40}}}, {8, 3.0, {{80, 10}}}};
  CountingProgress progress;
  const SegmentRun run = run_segment(img, &s, &progress);
  EXPECT_EQ(run.regions.width(), 96);
  EXPECT_EQ(run.regions.height(), 64);
  EXPECT_EQ(run.regions.at(5, 5), 3);
  EXPECT_EQ(run.regions.at(90, 60), 8);
  EXPECT_EQ(run.overlay.width(), 96);
  EXPECT_EQ(run.overlay.height(), 64);
  EXPECT_EQ(run.segmentation.triangle_region.size(),
            static_cast<std::size_t>(run.segmentation.mesh.triangle_count()));
  EXPECT_DOUBLE_EQ(progress.last, 1.0);
  EXPECT_GE(progress.calls, 3);
}

TEST(SegmentStage, WithoutTheOverlayTheRegionsAreTheSame) {
  const Image img = split_drawing();
  Strokes s;
  s.strokes = {{3, 3.0, {{10, 30}, {20, 40}}}, {8, 3.0, {{80, 10}}}};
  const SegmentRun with = run_segment(img, &s);
  const SegmentRun without = run_segment(img, &s, nullptr, false);
  EXPECT_TRUE(without.overlay.empty());
  EXPECT_FALSE(with.overlay.empty());
  EXPECT_EQ(without.regions, with.regions);
  EXPECT_EQ(without.segmentation.triangle_region, with.segmentation.triangle_region);
}

TEST(SegmentStage, WithoutStrokesRegionsAreNumberedFromOne) {
  const SegmentRun run = run_segment(split_drawing(), nullptr);
  EXPECT_EQ(run.regions.labels(), (std::vector<int>{1, 2}));
  EXPECT_NE(run.regions.at(5, 5), run.regions.at(90, 5));
}

TEST(SegmentStage, HairColourPicksTheRegionsOfThatColour) {
  Image img = split_drawing();  // light tan left and right of the line ...
  for (int y = 0; y < 64; ++y)
    for (int x = 60; x < 96; ++x) img.at(x, y) = {40, 90, 200, 255};  // ... and a blue part
  for (int y = 0; y < 64; ++y)
    for (int x = 59; x <= 61; ++x) img.at(x, y) = {15, 15, 15, 255};
  const SegmentRun run = run_segment_by_colour(img, {40, 90, 200}, 30.0);
  EXPECT_EQ(run.regions.at(80, 30), 1);
  EXPECT_EQ(run.regions.at(10, 30), 0);
  EXPECT_EQ(run.regions.at(50, 30), 0);
  EXPECT_THROW(run_segment_by_colour(img, {255, 0, 255}, 10.0), Error);
  EXPECT_THROW(run_segment_by_colour(img, {40, 90, 200}, -1.0), Error);
}

TEST(SegmentStage, WritesTheOutputFolderAtomically) {
  const hair25d::testing::TempDir tmp;
  const fs::path dir = tmp / "segment";
  Strokes s;
  s.strokes = {{1, 3.0, {{10, 30}}}, {2, 3.0, {{80, 30}}}};
  const SegmentRun run = run_segment(split_drawing(), &s);
  write_segment_run(dir, run);
  EXPECT_EQ(load_label_map(dir / "regions.png"), run.regions);
  EXPECT_EQ(segment::read_segmentation(dir / "segmentation.json").triangle_region,
            run.segmentation.triangle_region);
  EXPECT_EQ(load_image(dir / "overlay.png"), run.overlay);
  // Writing again replaces the folder: no stale files survive.
  std::ofstream(dir / "stale.txt") << "old";
  write_segment_run(dir, run);
  EXPECT_FALSE(fs::exists(dir / "stale.txt"));
  fs::remove_all(dir);
}

TEST(SegmentStage, BadInputIsAClearError) {
  Strokes background_only;
  background_only.strokes = {{0, 5.0, {{2, 2}, {30, 2}}}};
  EXPECT_THROW(run_segment(split_drawing(), &background_only), Error);
  Strokes empty;
  EXPECT_THROW(run_segment(split_drawing(), &empty), Error);
  EXPECT_THROW(run_segment(Image(), nullptr), Error);
  // Labels must fit the 16-bit regions.png.
  Strokes big;
  big.strokes = {{70000, 3.0, {{10, 30}}}};
  const SegmentRun too_big = run_segment(split_drawing(), &big);
  const hair25d::testing::TempDir tmp;
  const fs::path dir = tmp / "big";
  EXPECT_THROW(write_segment_run(dir, too_big), Error);
  EXPECT_FALSE(fs::exists(dir));
  // Tiny and non-square drawings are fine.
  Strokes dot;
  dot.strokes = {{1, 1.0, {{0, 0}}}};
  EXPECT_EQ(run_segment(Image(1, 1, {200, 200, 200, 255}), &dot).regions.at(0, 0), 1);
  EXPECT_EQ(run_segment(Image(3, 2, {200, 200, 200, 255}), &dot).regions.labels(),
            std::vector<int>{1});
}

}  // namespace
}  // namespace hair25d::pipeline
