// Curve extraction, smoothing and Douglas–Peucker (paper §3): exact small
// drawings, robustness to line styles, and bad input.
#include <gtest/gtest.h>

#include "drawing.h"
#include "hair25d/core/error.h"
#include "hair25d/segment/curves.h"

namespace hair25d::segment {
namespace {

using testing::draw_line;

double total_length(const std::vector<Curve>& curves) {
  double s = 0.0;
  for (const Curve& c : curves) s += polyline_length(c.points);
  return s;
}

TEST(ExtractCurves, VerticalLineGivesOneCurveOnItsCentre) {
  for (const double w : {2.0, 3.0, 4.0, 6.0}) {
    Image img(160, 100, {255, 255, 255, 255});
    draw_line(img, Vec2(80.5, 10), Vec2(80.5, 90), w);
    const CurveResult r = extract_curves(img);
    ASSERT_EQ(r.curves.size(), 1u) << "width " << w;
    const Curve& c = r.curves[0];
    EXPECT_FALSE(c.closed);
    EXPECT_EQ(c.ends[0], CurveEnd::kEndpoint);
    EXPECT_EQ(c.ends[1], CurveEnd::kEndpoint);
    for (const Vec2& p : c.points) EXPECT_NEAR(p.x(), 80.5, 0.6) << "width " << w;
    EXPECT_GT(polyline_length(c.points), 70.0) << "width " << w;
    EXPECT_LT(polyline_length(c.points), 81.0 + w) << "width " << w;  // round caps hold ink
    EXPECT_GE(r.line_width, 1.5);
    EXPECT_GT(r.line_mask.at(80, 50), 0);
    EXPECT_EQ(r.line_mask.at(20, 50), 0);
  }
}

TEST(ExtractCurves, ColouredNoisyLineIsFound) {
  Image img(140, 90, {230, 190, 110, 255});
  draw_line(img, Vec2(10, 20), Vec2(130, 70), 3.0, {120, 70, 30, 255});
  testing::add_noise(img, 6.0, 7);
  const CurveResult r = extract_curves(img);
  ASSERT_GE(r.curves.size(), 1u);
  EXPECT_GT(total_length(r.curves), 110.0);
  EXPECT_LT(total_length(r.curves), 150.0);
}

TEST(ExtractCurves, TJunctionGivesThreeBranchesMeetingAtOnePoint) {
  Image img(150, 110, {255, 255, 255, 255});
  draw_line(img, Vec2(10, 40), Vec2(140, 40), 3.0);
  draw_line(img, Vec2(70, 40), Vec2(70, 100), 3.0);
  const CurveResult r = extract_curves(img);
  ASSERT_EQ(r.curves.size(), 3u);
  std::vector<Vec2> junction_ends;
  for (const Curve& c : r.curves) {
    for (int e = 0; e < 2; ++e)
      if (c.ends[e] == CurveEnd::kJunction)
        junction_ends.push_back(e == 0 ? c.points.front() : c.points.back());
  }
  ASSERT_EQ(junction_ends.size(), 3u);
  for (const Vec2& p : junction_ends) {
    EXPECT_EQ(p, junction_ends[0]);  // one shared point, exactly
    EXPECT_NEAR(p.x(), 70.0, 3.0);
    EXPECT_NEAR(p.y(), 40.0, 3.0);
  }
}

TEST(ExtractCurves, CircleGivesOneClosedCurve) {
  Image img(130, 110, {255, 255, 255, 255});
  testing::draw_polyline(img, testing::circle(Vec2(65, 55), 35), 3.0, {20, 20, 20, 255}, true);
  const CurveResult r = extract_curves(img);
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_TRUE(r.curves[0].closed);
  EXPECT_EQ(r.curves[0].ends[0], CurveEnd::kFree);
  for (const Vec2& p : r.curves[0].points) EXPECT_NEAR((p - Vec2(65, 55)).norm(), 35.0, 1.0);
}

TEST(ExtractCurves, ToneStepScreentoneAndNoiseAreNotLines) {
  Image step(120, 80, {240, 200, 150, 255});
  testing::fill_rect(step, 60, 0, 120, 80, {170, 120, 80, 255});  // cel-shading edge
  EXPECT_TRUE(extract_curves(step).curves.empty());

  Image dots(120, 80, {255, 255, 255, 255});
  for (int y = 2; y < 80; y += 5)
    for (int x = 2; x < 120; x += 5) testing::fill_rect(dots, x, y, x + 2, y + 2, {0, 0, 0, 255});
  EXPECT_TRUE(extract_curves(dots).curves.empty());

  Image noise(120, 80, {200, 200, 200, 255});
  testing::add_noise(noise, 6.0, 3);
  EXPECT_TRUE(extract_curves(noise).curves.empty());
}

TEST(ExtractCurves, EmptyTinyAndBlankImagesGiveNoCurves) {
  EXPECT_TRUE(extract_curves(Image()).curves.empty());
  EXPECT_TRUE(extract_curves(Image(1, 1, {0, 0, 0, 255})).curves.empty());
  EXPECT_TRUE(extract_curves(Image(3, 2, {0, 0, 0, 255})).curves.empty());
  const CurveResult r = extract_curves(Image(50, 30, {128, 128, 128, 255}));
  EXPECT_TRUE(r.curves.empty());
  EXPECT_EQ(r.line_mask.width(), 50);
  EXPECT_EQ(r.line_mask.height(), 30);
}

TEST(ExtractCurves, TransparentPixelsCountAsWhite) {
  Image img(100, 60, {0, 0, 0, 0});  // transparent black: paper, not ink
  draw_line(img, Vec2(10, 30), Vec2(90, 30), 3.0);
  const CurveResult r = extract_curves(img);
  ASSERT_EQ(r.curves.size(), 1u);
  EXPECT_NEAR(r.curves[0].points[r.curves[0].points.size() / 2].y(), 30.0, 0.7);
}

TEST(ExtractCurves, InvalidOptionsAreRejected) {
  const Image img(20, 20, {255, 255, 255, 255});
  CurveOptions o;
  o.scales.clear();
  EXPECT_THROW(extract_curves(img, o), Error);
  o = {};
  o.low_threshold = 30.0;
  o.high_threshold = 10.0;
  std::string why;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find("high_threshold"), std::string::npos);
  EXPECT_THROW(extract_curves(img, o), Error);
  o = {};
  o.scales = {0.1};
  EXPECT_THROW(extract_curves(img, o), Error);
  o = {};
  o.gap_factor = -1.0;
  EXPECT_THROW(extract_curves(img, o), Error);
}

TEST(DouglasPeucker, KeepsCornersDropsCollinearPoints) {
  const Polyline straight{{0, 0}, {1, 0.1}, {2, -0.1}, {3, 0}};
  const Polyline s = douglas_peucker(straight, 0.5);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s.front(), straight.front());
  EXPECT_EQ(s.back(), straight.back());
  const Polyline corner{{0, 0}, {5, 0}, {10, 0}, {10, 5}, {10, 10}};
  const Polyline c = douglas_peucker(corner, 0.5);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[1], Vec2(10, 0));
  EXPECT_EQ(douglas_peucker({{1, 1}}, 1.0).size(), 1u);
}

TEST(SmoothAndSimplify, EndsStayPutAndNoiseIsRemoved) {
  Curve a;
  for (int i = 0; i <= 60; ++i) a.points.emplace_back(i, (i % 2 ? 0.3 : -0.3));
  a.ends = {CurveEnd::kJunction, CurveEnd::kEndpoint};
  Curve b;
  for (int i = 0; i <= 40; ++i) b.points.emplace_back(60, i);
  b.ends = {CurveEnd::kJunction, CurveEnd::kEndpoint};
  b.points.front() = a.points.back();
  const auto out = smooth_and_simplify({a, b});
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].points.front(), a.points.front());
  EXPECT_EQ(out[0].points.back(), a.points.back());
  EXPECT_EQ(out[1].points.front(), out[0].points.back());  // the junction is shared exactly
  EXPECT_LE(out[0].points.size(), 4u);
  EXPECT_EQ(out[1].points.size(), 2u);
  EXPECT_EQ(out[0].ends, a.ends);
}

TEST(SmoothAndSimplify, ClosedCurvesStayClosedAndRound) {
  Curve c;
  c.points = testing::circle(Vec2(50, 50), 20, 120);
  c.closed = true;
  c.ends = {CurveEnd::kFree, CurveEnd::kFree};
  const auto out = smooth_and_simplify({c});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].closed);
  EXPECT_GE(out[0].points.size(), 8u);
  EXPECT_LT(out[0].points.size(), 120u);
  for (const Vec2& p : out[0].points) EXPECT_NEAR((p - Vec2(50, 50)).norm(), 20.0, 0.8);
}

TEST(SmoothAndSimplify, BadInputIsRejected) {
  Curve c;
  c.points = {{0, 0}, {std::nan(""), 1}};
  EXPECT_THROW(smooth_and_simplify({c}), Error);
  SimplifyOptions o;
  o.tolerance = -1;
  EXPECT_THROW(smooth_and_simplify({}, o), Error);
  Curve one;
  one.points = {{1, 1}};
  EXPECT_TRUE(smooth_and_simplify({one}).empty());
}

}  // namespace
}  // namespace hair25d::segment
