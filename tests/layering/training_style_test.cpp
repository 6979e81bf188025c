// The drawings the learned layering models are trained on
// (bench/layering/train_layering_style.h): the thin-line and fading-fork
// drawings the patch networks also learn from vary only what they are for.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

#include "train_layering_style.h"

namespace {

using hair25d::layering_training::dark_style;
using hair25d::layering_training::patch_style;
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

TEST(DarkStyle, KeepsEverythingButTheHairsDarkness) {
  for (int i = 2400; i < 2400 + 420; ++i) {
    const hair25d::generator::Options d = dark_style(i, kSeed);
    const hair25d::generator::Options o = training_style(i, kSeed);
    EXPECT_TRUE(d.dark_hair) << i;
    EXPECT_FALSE(o.dark_hair) << i;
    EXPECT_EQ(d.seed, o.seed) << i;
    EXPECT_EQ(d.shading, o.shading) << i;
    EXPECT_EQ(d.line_width, o.line_width) << i;
    EXPECT_EQ(d.jpeg_quality, o.jpeg_quality) << i;
    EXPECT_EQ(d.noise_sigma, o.noise_sigma) << i;
    EXPECT_EQ(d.coloured_lines, o.coloured_lines) << i;
    EXPECT_EQ(d.fading_forks, o.fading_forks) << i;
    EXPECT_EQ(d.strand_count, o.strand_count) << i;
    EXPECT_FALSE(d.strand_masks) << i;
  }
  // A run's drawings: training_style, from --extra-from on thin_fork_style,
  // from --dark-from on dark_style.
  for (int i : {0, 1899, 2399, 2400, 3599, 3600, 5000}) {
    const hair25d::generator::Options p = patch_style(i, kSeed, 2400, 3600);
    const hair25d::generator::Options want = i >= 3600   ? dark_style(i, kSeed)
                                             : i >= 2400 ? thin_fork_style(i, kSeed)
                                                         : training_style(i, kSeed);
    EXPECT_EQ(p.dark_hair, want.dark_hair) << i;
    EXPECT_EQ(p.line_width, want.line_width) << i;
    EXPECT_EQ(p.fading_forks, want.fading_forks) << i;
  }
}

// Grey level (0..255) of a pixel, as the layering's grey channel weighs it.
double grey(const hair25d::Rgba& c) { return 0.299 * c.r + 0.587 * c.g + 0.114 * c.b; }

// The median grey level of the hair regions' pixels of a drawing.
double hair_grey(const hair25d::AnnotatedCase& c) {
  std::vector<double> g;
  for (int y = 0; y < c.image.height(); ++y)
    for (int x = 0; x < c.image.width(); ++x)
      if (c.regions.at(x, y) > 0) g.push_back(grey(c.image.at(x, y)));
  std::nth_element(g.begin(), g.begin() + g.size() / 2, g.end());
  return g.empty() ? 0.0 : g[g.size() / 2];
}

// Dark hair: the paint about as dark as the ink (black lines are drawn at
// grey 8–31, coloured ones darker than the paint), where training_style's
// hair is never darker than grey 40 or so; the same seeds otherwise.
TEST(DarkStyle, HairIsPaintedAboutAsDarkAsTheInk) {
  for (int i = 2400; i < 2412; ++i) {
    hair25d::generator::Options d = dark_style(i, kSeed), o = training_style(i, kSeed);
    d.width = o.width = 320;
    d.height = o.height = 240;
    const double dark = hair_grey(hair25d::generator::generate_case(d));
    const double usual = hair_grey(hair25d::generator::generate_case(o));
    EXPECT_LT(dark, 70.0) << i;
    EXPECT_GT(usual, dark + 20.0) << i;
  }
}

}  // namespace
