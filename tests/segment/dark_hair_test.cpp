// Dark hair on light paper (paper §3, curve extraction): the hair's black
// outline borders light paper on one side and a dark fill on the other, and
// it must be found as a line like any other; so must a black line drawn
// inside the dark fill.
#include <gtest/gtest.h>

#include <cmath>

#include "drawing.h"
#include "hair25d/segment/curves.h"
#include "hair25d/segment/mesh.h"
#include "hair25d/segment/segmenter.h"

namespace hair25d::segment {
namespace {

constexpr Rgba kPaper{235, 238, 242, 255};
constexpr Rgba kInk{30, 30, 30, 255};

// Pixels whose centre lies inside the ellipse (c, radii r) take `fill`.
void fill_ellipse(Image& img, Vec2 c, Vec2 r, Rgba fill) {
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) {
      const double u = (x + 0.5 - c.x()) / r.x(), v = (y + 0.5 - c.y()) / r.y();
      if (u * u + v * v <= 1.0) img.at(x, y) = fill;
    }
}

Polyline ellipse(Vec2 c, Vec2 r, int n = 120) {
  Polyline out;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    out.emplace_back(c.x() + r.x() * std::cos(a), c.y() + r.y() * std::sin(a));
  }
  return out;
}

double distance_to_curves(const std::vector<Curve>& curves, Vec2 p) {
  double best = 1e300;
  for (const Curve& c : curves)
    for (std::size_t i = 0; i + 1 < c.points.size(); ++i) {
      const Vec2 a = c.points[i], d = c.points[i + 1] - a;
      const double t = std::clamp((p - a).dot(d) / std::max(d.squaredNorm(), 1e-12), 0.0, 1.0);
      best = std::min(best, (p - (a + t * d)).norm());
    }
  return best;
}

// A dark filled ellipse with a black outline on light paper, 190 × 130.
struct DarkShape {
  Image image{190, 130, kPaper};
  Vec2 centre{95.0, 64.0};
  Vec2 radii{70.0, 46.0};
};

DarkShape dark_shape(Rgba fill) {
  DarkShape s;
  fill_ellipse(s.image, s.centre, s.radii, fill);
  testing::draw_polyline(s.image, ellipse(s.centre, s.radii), 3.5, kInk, true);
  return s;
}

// Fraction of points along `line` that lie within `tolerance` px of a curve.
double found_fraction(const std::vector<Curve>& curves, const Polyline& line, double tolerance) {
  int near = 0;
  for (const Vec2& p : line) near += distance_to_curves(curves, p) <= tolerance;
  return static_cast<double>(near) / static_cast<double>(line.size());
}

TEST(DarkHair, BlackOutlineOfADarkGreyFillIsFound) {
  // Grey 57 against ink 30: the luminance is all the line detector sees.
  const DarkShape s = dark_shape({57, 57, 57, 255});
  const CurveResult r = extract_curves(s.image);
  EXPECT_GE(found_fraction(r.curves, ellipse(s.centre, s.radii), 2.0), 0.95);
}

TEST(DarkHair, BlackOutlineOfADarkBlueFillIsFound) {
  const DarkShape s = dark_shape({39, 49, 143, 255});
  const CurveResult r = extract_curves(s.image);
  EXPECT_GE(found_fraction(r.curves, ellipse(s.centre, s.radii), 2.0), 0.95);
  // The outline is no double line: one curve for the whole ellipse, not a
  // line plus a step edge beside it.
  double length = 0.0;
  for (const Curve& c : r.curves)
    for (std::size_t i = 0; i + 1 < c.points.size(); ++i)
      length += (c.points[i + 1] - c.points[i]).norm();
  const double perimeter = 2.0 * M_PI * std::sqrt(0.5 * (70.0 * 70.0 + 46.0 * 46.0));
  EXPECT_NEAR(length, perimeter, 0.1 * perimeter);
}

TEST(DarkHair, BlackLineInsideADarkBlueFillIsFound) {
  DarkShape s = dark_shape({39, 49, 143, 255});
  const Polyline split{{95.0, 20.0}, {100.0, 64.0}, {95.0, 108.0}};
  testing::draw_polyline(s.image, split, 3.0, kInk);
  const CurveResult r = extract_curves(s.image);
  // Away from its ends, where it meets the outline.
  Polyline inner;
  for (double t = 0.15; t <= 0.85; t += 0.02) {
    const double y = 20.0 + 88.0 * t;
    inner.emplace_back(95.0 + 5.0 * (1.0 - std::abs(y - 64.0) / 44.0), y);
  }
  EXPECT_GE(found_fraction(r.curves, inner, 2.0), 0.95);
}

TEST(DarkHair, TwoDarkStrandsSplitByTheirLinesAndNotTheirPaper) {
  DarkShape s = dark_shape({39, 49, 143, 255});
  testing::draw_polyline(s.image, {{95.0, 10.0}, {95.0, 120.0}}, 3.0, kInk);
  Strokes strokes;
  strokes.strokes.push_back(testing::stroke(1, {{60.0, 45.0}, {70.0, 85.0}}));
  strokes.strokes.push_back(testing::stroke(2, {{130.0, 45.0}, {120.0, 85.0}}));
  const SegmentResult r = segment_image(s.image, &strokes);
  const LabelMap got = rasterize_triangle_values(
      r.segmentation.mesh, r.segmentation.triangle_region, s.image.width(), s.image.height());
  // Compare away from the lines (4 px either side of the outline and split).
  int checked = 0, wrong = 0;
  for (int y = 0; y < s.image.height(); ++y)
    for (int x = 0; x < s.image.width(); ++x) {
      const double u = (x + 0.5 - s.centre.x()) / s.radii.x();
      const double v = (y + 0.5 - s.centre.y()) / s.radii.y();
      const double rho = std::sqrt(u * u + v * v);
      if (std::abs(rho - 1.0) * 46.0 < 4.0 || std::abs(x + 0.5 - 95.0) < 4.0) continue;
      const int want = rho > 1.0 ? 0 : (x < 95 ? 1 : 2);
      ++checked;
      wrong += got.at(x, y) != want;
    }
  EXPECT_GT(checked, 15000);
  EXPECT_LT(wrong, checked / 100) << wrong << " of " << checked << " pixels";
}

}  // namespace
}  // namespace hair25d::segment
