// The noise floor of the occluding threshold (paper §4.1, step 3 of
// docs/layering.md): the lines are measured on grey levels blurred at a
// quarter line width, so the floor is a multiple of the noise left after
// that blur, not of the raw pixels' noise. A faint outline (18 grey levels)
// under noise of σ 6 is a line when the lines are 5 px wide; a boundary
// with no line under the same noise is not, at any width.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "hair25d/layering/layering.h"
#include "line_response.h"

namespace hair25d::layering {
namespace {

constexpr int kPaint = 70;  // the strands' and the backdrop's grey level
constexpr int kInk = 52;    // a faint outline: 18 grey levels under the paint

// 200 × 140: three strands on a backdrop of their own paint, outlined by
// rings `ring` px wide (label 0). With `inked`, every ring is ink; else the
// third strand's ring is paint (no line around it) and the others are ink.
// Gaussian noise of σ `noise` on the grey level (all channels alike).
struct Strands {
  Image image{200, 140, Rgba{kPaint, kPaint, kPaint, 255}};
  LabelMap labels{200, 140, 0};
  Strands(int ring, bool inked, double noise) {
    std::vector<int> ink(200 * 140, 0);
    auto strand = [&](int x0, int x1, int y0, int y1, int id, bool line) {
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
          const bool edge = x < x0 + ring || x >= x1 - ring || y < y0 + ring || y >= y1 - ring;
          ink[y * 200 + x] = edge && line;
          labels.at(x, y) = edge ? 0 : id;
        }
    };
    strand(15, 110, 12, 128, 1, true);
    strand(100, 185, 12, 128, 2, true);
    strand(60, 150, 40, 100, 3, inked);
    std::mt19937 rng(7);
    std::normal_distribution<double> n(0.0, noise);
    for (int y = 0; y < 140; ++y)
      for (int x = 0; x < 200; ++x) {
        const double g = (ink[y * 200 + x] ? kInk : kPaint) + n(rng);
        const auto v = static_cast<std::uint8_t>(std::clamp(std::lround(g), 0L, 255L));
        image.at(x, y) = Rgba{v, v, v, 255};
      }
  }
};

const BoundaryReport* between(const Result& r, int a, int b) {
  for (const BoundaryReport& rep : r.boundaries)
    if ((rep.left == a && rep.right == b) || (rep.left == b && rep.right == a)) return &rep;
  return nullptr;
}

// Before: the floor was 4 × the raw noise σ (about 24 here), over the
// outline's contrast, so every boundary was non-occluding and every pair
// "equal".
TEST(NoiseFloor, FaintOutlineUnderNoiseIsALine) {
  const Strands d(5, true, 6.0);
  const Result r = layer_regions(d.image, d.labels);
  for (const auto& [a, b] : {std::pair{1, 2}, std::pair{1, 3}, std::pair{2, 3}}) {
    const BoundaryReport* rep = between(r, a, b);
    ASSERT_NE(rep, nullptr) << a << "|" << b;
    EXPECT_TRUE(rep->occluding) << a << "|" << b << " contrast " << rep->line_contrast
                                << " threshold " << r.line_threshold;
  }
  for (const RegionRelation& rel : r.relations)
    EXPECT_NE(rel.relation, Relation::kEqual) << rel.a << "|" << rel.b;
}

// The noise alone reads as a contrast of a few σ of the blurred grey levels
// (the brightest paper and the darkest centre are extremes of noisy
// samples): the floor stays over it, at thin and at wide lines.
TEST(NoiseFloor, NoLineUnderNoiseIsNoLine) {
  for (const int ring : {2, 3, 5, 7})
    for (const double noise : {3.0, 6.0, 10.0}) {
      const Strands d(ring, false, noise);
      const Result r = layer_regions(d.image, d.labels);
      const BoundaryReport* rep = between(r, 1, 3);
      ASSERT_NE(rep, nullptr) << ring;
      EXPECT_FALSE(rep->occluding)
          << "ring " << ring << " noise " << noise << " contrast " << rep->line_contrast
          << " threshold " << r.line_threshold << " width " << r.line_width;
      EXPECT_LT(rep->line_contrast, 0.5 * r.line_threshold)
          << "ring " << ring << " noise " << noise;
    }
}

}  // namespace
}  // namespace hair25d::layering
