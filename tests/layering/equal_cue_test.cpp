// The learned same-depth model (learned_metric.h, equal_metric): the two
// halves of a forked strand are divided by a drawn line just like an occluder
// and its occludee. Hand-built forks it must call "equal", the same shapes
// painted as two strands it must order, and the symmetry of its features.
#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "hair25d/layering/layering.h"
#include "hair25d/layering/learned_metric.h"
#include "layering/relation_lookup.h"

namespace hair25d::layering {
namespace {

using test::relation_of;

constexpr Rgba kInk{20, 15, 15, 255};
constexpr Rgba kPaper{235, 240, 250, 255};
constexpr Rgba kBack{200, 170, 120, 255};
constexpr Rgba kStrand{150, 110, 160, 255};

// Back hair (1) and a vertical strand over it whose lower part is split down
// the middle into a left (2) and a right (5) half, with a 3-pixel outline
// around both. The dividing line is drawn from the bottom up to `drawn_to_y`
// (it fades out inside the strand above that, as many artists draw a fork);
// the annotation splits the strand from y = 30 down. `right` paints the right
// half. 150 × 110.
struct Scene {
  Image image;
  LabelMap regions;
};

Scene fork(int drawn_to_y, Rgba right) {
  const int w = 150, h = 110, line = 3;
  Scene s{Image(w, h, kPaper), LabelMap(w, h, 0)};
  auto box = [&](int x0, int y0, int x1, int y1, int region, Rgba fill) {
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const bool edge = x - x0 < line || x1 - x < line || y - y0 < line || y1 - y < line;
        s.image.at(x, y) = edge ? kInk : fill;
        s.regions.at(x, y) = edge ? 0 : region;
      }
  };
  box(10, 10, 140, 100, 1, kBack);
  box(55, 2, 95, 108, 2, kStrand);
  for (int y = 30; y <= 105; ++y) {  // down to the strand's bottom outline
    for (int x = 74; x <= 92; ++x)
      if (x >= 77) {
        s.regions.at(x, y) = 5;
        s.image.at(x, y) = right;
      }
    // The dividing line: three pixels of ink where drawn, one pixel of label 0
    // (an annotator's cut) where it has faded out.
    for (int x = 74; x <= 76; ++x) {
      const bool drawn = y >= drawn_to_y;
      if (drawn) s.image.at(x, y) = kInk;
      s.regions.at(x, y) = (drawn || x == 75) ? 0 : (x < 75 ? 2 : 5);
    }
  }
  return s;
}

const BoundaryReport* between(const Result& r, int a, int b) {
  const BoundaryReport* best = nullptr;
  for (const BoundaryReport& x : r.boundaries)
    if ((x.left == a && x.right == b) || (x.left == b && x.right == a))
      if (!best || x.length > best->length) best = &x;
  return best;
}

TEST(EqualCue, ForkWhoseLineFadesIsEqual) {
  // The line covers the lower two thirds of the cut: the boundary is on a
  // drawn line by its median, so only the same-depth model can say "equal".
  const Scene s = fork(55, kStrand);
  const Result r = layer_regions(s.image, s.regions);
  const BoundaryReport* b = between(r, 2, 5);
  ASSERT_NE(b, nullptr);
  EXPECT_TRUE(b->occluding);
  EXPECT_LT(b->line_contrast_low, r.line_threshold);
  EXPECT_LT(b->colour_difference, 10.0);
  EXPECT_GT(b->equal, 0.0);
  EXPECT_EQ(relation_of(r, 2, 5), Relation::kEqual);
  EXPECT_EQ(r.depth.at(2), r.depth.at(5));
  EXPECT_EQ(relation_of(r, 1, 2), Relation::kBelow);
  EXPECT_EQ(relation_of(r, 1, 5), Relation::kBelow);

  // Without the model the drawn two thirds order the halves.
  Options off;
  off.learned_equal = false;
  const Result o = layer_regions(s.image, s.regions, off);
  EXPECT_NE(relation_of(o, 2, 5), Relation::kEqual);
}

TEST(EqualCue, DifferentPaintWithAFullLineIsOrdered) {
  // The same shapes, but the line runs the whole cut and the right part is
  // painted in another colour: two strands, one over the other.
  const Scene s = fork(30, Rgba{90, 160, 90, 255});
  const Result r = layer_regions(s.image, s.regions);
  const BoundaryReport* b = between(r, 2, 5);
  ASSERT_NE(b, nullptr);
  EXPECT_TRUE(b->occluding);
  EXPECT_GT(b->colour_difference, 40.0);
  EXPECT_LT(b->equal, 0.0);
  EXPECT_NE(relation_of(r, 2, 5), Relation::kEqual);
}

TEST(EqualCue, FeaturesDoNotDependOnTheWalkingDirection) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(0.05, 2 * std::numbers::pi - 0.3), unit(0, 1);
  for (int i = 0; i < 100; ++i) {
    EqualCues c;
    c.length_widths = 40 * unit(rng);
    c.contrast_ratio = 3 * unit(rng);
    c.contrast_low_ratio = 3 * unit(rng);
    c.colour_difference = 80 * unit(rng);
    c.typical_colour_difference = 40 * unit(rng);
    c.order_log_odds = 6 * unit(rng) - 3;
    c.area_left = 5000 * unit(rng);
    c.area_right = 5000 * unit(rng);
    c.start = {i % 3 != 0, angle(rng), angle(rng), 3, angle(rng), angle(rng)};
    c.end = {i % 4 != 0, angle(rng), angle(rng), 3, angle(rng), angle(rng)};
    for (EndAngles* e : {&c.start, &c.end}) {
      e->circle_left = angle(rng);
      e->circle_right = angle(rng);
    }
    c.shared_left = unit(rng);
    c.shared_right = unit(rng);
    EqualCues d = c;  // walked the other way: sides and ends swap
    d.order_log_odds = -c.order_log_odds;
    std::swap(d.area_left, d.area_right);
    for (EndAngles* e : {&d.start, &d.end}) {
      std::swap(e->left, e->right);
      std::swap(e->wide_left, e->wide_right);
      std::swap(e->circle_left, e->circle_right);
    }
    std::swap(d.shared_left, d.shared_right);
    std::swap(d.start, d.end);
    const EqualFeatures f = equal_features(c), g = equal_features(d);
    for (int k = 0; k < kEqualFeatureCount; ++k) EXPECT_NEAR(f[k], g[k], 1e-12) << k;
    EXPECT_NEAR(equal_metric(f), equal_metric(g), 1e-12);
  }
}

TEST(EqualCue, SamePaintSpeaksForSameDepth) {
  // The trained weights keep the cue's meaning: other things equal, the more
  // the paint differs across the line, the less likely one strand.
  EqualCues c;
  c.length_widths = 20;
  c.contrast_ratio = c.contrast_low_ratio = 2;
  c.typical_colour_difference = 20;
  c.area_left = c.area_right = 2000;
  double last = 1e9;
  for (double d : {0.0, 10.0, 30.0, 60.0}) {
    c.colour_difference = d;
    const double v = equal_metric(equal_features(c));
    EXPECT_LT(v, last) << d;
    last = v;
  }
}

}  // namespace
}  // namespace hair25d::layering
