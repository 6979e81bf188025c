// The flat colours a strand piece is painted in (completion/src/join_paint.h,
// the colour term of strand joins): each flat colour found once, whatever
// its channels, and mixed with no other.
#include "join_paint.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace hair25d::completion::detail {
namespace {

// Half the pixels `a`, half `b`, on a 20 × 20 image.
std::vector<Eigen::Vector3d> flats_of_halves(Rgba a, Rgba b) {
  Image image(20, 20, a);
  std::vector<cv::Point> pixels;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) {
      if (x >= 10) image.at(x, y) = b;
      pixels.emplace_back(x, y);
    }
  return flat_colours(image, pixels, 2, 0.15, true);
}

// White (every channel in the top bin) and yellow (blue near 0) are two
// paints. Before, the bins' neighbours were found by adding to a packed key,
// so blue's top bin wrapped round to the next green bin's bottom: white's
// neighbourhood held yellow and the two came out as one flat colour, their
// mean (255, 255, 128) — screentone drawings' paper met such wraps.
TEST(JoinPaint, ColoursAtTheEndsOfTheChannelsStayApart) {
  const std::vector<Eigen::Vector3d> flats =
      flats_of_halves(Rgba{255, 255, 255, 255}, Rgba{255, 255, 0, 255});
  ASSERT_EQ(flats.size(), 2u);
  EXPECT_NEAR((flats[0] - flats[1]).norm(), 255.0, 1e-9) << "white and yellow mixed";
  EXPECT_NEAR(flats[0].head<2>().minCoeff(), 255.0, 1e-9);
  EXPECT_NEAR(flats[1].head<2>().minCoeff(), 255.0, 1e-9);
}

// Neighbouring bins are one paint: a flat colour and its anti-aliased
// neighbour 6 levels off come out as one, between them.
TEST(JoinPaint, NeighbouringBinsAreOnePaint) {
  const std::vector<Eigen::Vector3d> flats =
      flats_of_halves(Rgba{100, 60, 40, 255}, Rgba{106, 60, 40, 255});
  ASSERT_EQ(flats.size(), 1u);
  EXPECT_NEAR(flats[0].x(), 103.0, 1e-9);
  EXPECT_NEAR(flats[0].y(), 60.0, 1e-9);
}

// A 24 x 16 piece of cel paint: `base` on the left, `band` from column 14,
// and between them (columns 12, 13) the band edge's anti-aliased blends, a
// quarter and a half of the way from the base to the band (rounded).
std::vector<Eigen::Vector3d> flats_of_banded(Rgba base, Rgba band, int most,
                                             std::vector<cv::Point>* taken = nullptr) {
  Image image(24, 16, base);
  std::vector<cv::Point> pixels;
  const auto blend = [&](double t) {
    const auto mix = [t](std::uint8_t a, std::uint8_t b) {
      return static_cast<std::uint8_t>(std::lround((1 - t) * a + t * b));
    };
    return Rgba{mix(base.r, band.r), mix(base.g, band.g), mix(base.b, band.b), 255};
  };
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 24; ++x) {
      if (x == 12) image.at(x, y) = blend(0.25);
      if (x == 13) image.at(x, y) = blend(0.5);
      if (x >= 14) image.at(x, y) = band;
      pixels.emplace_back(x, y);
    }
  if (taken) *taken = pixels;
  return flat_colours(image, pixels, most, 0.05, true);
}

// A cel band's anti-aliased edge is no paint: its blends a quarter of the
// way fall into the bins round the base, and their mean pulled the base
// 0.8 RGB towards the band here (over 1.1 RGB for a tenth of the regions of
// dev two-tone 2000-2099), so
// two pieces of one strand, one seen with its band and one without, stepped
// over the rare paint's 0.5 RGB (joins.cpp kRarePaintStep). The paint is the
// exact colour holding most of the cluster.
TEST(JoinPaint, BandEdgeBlendsAreNoPaint) {
  const Rgba base{120, 80, 60, 255}, band{86, 58, 43, 255};
  const std::vector<Eigen::Vector3d> flats = flats_of_banded(base, band, 2);
  ASSERT_EQ(flats.size(), 2u);
  EXPECT_NEAR((flats[0] - Eigen::Vector3d(120, 80, 60)).norm(), 0.0, 1e-9) << flats[0].transpose();
  EXPECT_NEAR((flats[1] - Eigen::Vector3d(86, 58, 43)).norm(), 0.0, 1e-9) << flats[1].transpose();
}

// Pieces of one strand step nothing once the blends are left out, whichever
// paints their cuts show; a strand one level off in red still steps a level.
TEST(JoinPaint, OneStrandWithAndWithoutItsBandStepsNothing) {
  const Rgba base{120, 80, 60, 255}, band{86, 58, 43, 255};
  EdgePaint with_band, without, near;
  RegionPaint region_with_band, region_without, region_near;
  region_with_band.flats = with_band.flats = flats_of_banded(base, band, 2);
  region_without.flats = without.flats = flats_of_halves(base, base);
  region_near.flats = near.flats = flats_of_halves(Rgba{121, 80, 60, 255}, Rgba{121, 80, 60, 255});
  for (RegionPaint* r : {&region_with_band, &region_without, &region_near}) r->exact_share = 1.0;
  with_band.fit_residual = without.fit_residual = near.fit_residual = 30.0;  // not linear
  const Edge a, b;
  const Eigen::Vector3d no_shadow = Eigen::Vector3d::Zero();
  const PaintStep same =
      paint_step(a, b, with_band, without, region_with_band, region_without, no_shadow);
  EXPECT_TRUE(same.flat);
  EXPECT_NEAR(same.step, 0.0, 1e-9);
  const PaintStep other =
      paint_step(a, b, with_band, near, region_with_band, region_near, no_shadow);
  EXPECT_TRUE(other.flat);
  EXPECT_NEAR(other.step, 1.0, 1e-9);
}

// A gradient has no exact colour holding most of a cluster: its flat colour
// stays the cluster's mean (reds 100-107 in equal shares: 103.5).
TEST(JoinPaint, GradientClusterKeepsItsMean) {
  Image image(16, 8, Rgba{0, 0, 0, 255});
  std::vector<cv::Point> pixels;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x) {
      image.at(x, y) = Rgba{static_cast<std::uint8_t>(100 + x / 2), 60, 40, 255};
      pixels.emplace_back(x, y);
    }
  const std::vector<Eigen::Vector3d> flats = flat_colours(image, pixels, 1, 0.15, true);
  ASSERT_EQ(flats.size(), 1u);
  EXPECT_NEAR(flats[0].x(), 103.5, 1e-9);
}

}  // namespace
}  // namespace hair25d::completion::detail

namespace hair25d::completion::detail {
namespace {

// Linear windows at two cuts 40 px apart down a strand, sloping `top` and
// `bottom` RGB a pixel (every channel, down y), the lower one's colour
// `below` levels from the upper one's.
PaintStep step_of_windows(double top, double bottom, double below) {
  EdgePaint pa, pb;
  pa.fit_colour = Eigen::Vector3d(180, 140, 100);
  pb.fit_colour = pa.fit_colour + Eigen::Vector3d::Constant(below);
  pa.fit_centre = Vec2(120, 120);
  pb.fit_centre = Vec2(120, 160);
  pa.slope.col(1).setConstant(top);
  pb.slope.col(1).setConstant(bottom);
  pa.fit_residual = pb.fit_residual = 0.5;
  const RegionPaint shaded;  // no flat paint
  return paint_step(Edge{}, Edge{}, pa, pb, shaded, shaded, Eigen::Vector3d::Zero());
}

TEST(JoinPaint, UnevenWindowsOffTheGradientAreTold) {
  // The mean slope (-0.275 a channel) predicts -11 levels over 40 px; the
  // lower window is 30 darker: off the gradient both ways, and uneven where
  // one slope is under a quarter of the other's (0.05 against 0.5).
  const PaintStep uneven = step_of_windows(-0.5, -0.05, -30);
  EXPECT_TRUE(uneven.off_gradient);
  EXPECT_TRUE(uneven.uneven_slopes);
  const PaintStep even = step_of_windows(-0.5, -0.3, -40);
  EXPECT_TRUE(even.off_gradient);
  EXPECT_FALSE(even.uneven_slopes);
  // Where the slopes predict the step, nothing is off.
  EXPECT_FALSE(step_of_windows(-0.5, -0.5, -20).off_gradient);
}

}  // namespace
}  // namespace hair25d::completion::detail
