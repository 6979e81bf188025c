// The drawings the learned layering models are trained on
// (bench/layering/train_layering_style.h): the thin-line and fading-fork
// drawings the patch networks also learn from vary only what they are for.
#include <gtest/gtest.h>

#include <set>
#include <utility>

#include "train_layering_style.h"

namespace {

using hair25d::layering_training::thin_fork_style;
using hair25d::layering_training::training_style;

constexpr std::uint64_t kSeed = 20000;

TEST(ThinForkStyle, KeepsEverythingButLinesAndForks) {
  for (int i = 2400; i < 2400 + 420; ++i) {
    const hair25d::generator::Options t = thin_fork_style(i, kSeed);
    const hair25d::generator::Options o = training_style(i, kSeed);
    EXPECT_EQ(t.seed, o.seed) << i;
    EXPECT_EQ(t.shading, o.shading) << i;
    EXPECT_EQ(t.jpeg_quality, o.jpeg_quality) << i;
    EXPECT_EQ(t.noise_sigma, o.noise_sigma) << i;
    EXPECT_EQ(t.coloured_lines, o.coloured_lines) << i;
    EXPECT_EQ(t.strand_count, o.strand_count) << i;
    EXPECT_EQ(t.width, o.width) << i;
    EXPECT_EQ(t.height, o.height) << i;
    EXPECT_FALSE(t.strand_masks) << i;
    std::string error;
    EXPECT_TRUE(t.is_valid(&error)) << i << ": " << error;
  }
}

TEST(ThinForkStyle, ThinLinesAndForksInHalfSpreadOverTheOtherOptions) {
  // 840 drawings: a whole number of periods of every option (4, 5, 6, 7, 24).
  const int first = 2400, count = 840;
  int forks = 0;
  std::set<std::pair<int, bool>> shading_forks;
  std::set<std::pair<double, int>> line_jpeg;
  std::set<std::pair<double, int>> line_shading;
  std::set<std::pair<bool, int>> forks_strands;
  for (int i = first; i < first + count; ++i) {
    const hair25d::generator::Options t = thin_fork_style(i, kSeed);
    EXPECT_GE(t.line_width, 1.0) << i;
    EXPECT_LE(t.line_width, 1.8) << i;
    forks += t.fading_forks;
    shading_forks.insert({static_cast<int>(t.shading), t.fading_forks});
    line_jpeg.insert({t.line_width, t.jpeg_quality});
    line_shading.insert({t.line_width, static_cast<int>(t.shading)});
    forks_strands.insert({t.fading_forks, t.strand_count});
  }
  EXPECT_EQ(forks, count / 2);
  // Neither the forks nor the line width is tied to another option:
  // every combination occurs.
  EXPECT_EQ(shading_forks.size(), 4u * 2u);
  EXPECT_EQ(line_jpeg.size(), 5u * 4u);  // widths 1, 1.2, 1.4, 1.5, 1.8; JPEG 0, 40, 70, 90
  EXPECT_EQ(line_shading.size(), 5u * 4u);
  EXPECT_EQ(forks_strands.size(), 2u * 6u);
}

}  // namespace
