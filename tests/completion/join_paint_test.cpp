// The flat colours a strand piece is painted in (completion/src/join_paint.h,
// the colour term of strand joins): each flat colour found once, whatever
// its channels, and mixed with no other.
#include "join_paint.h"

#include <gtest/gtest.h>

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
  return flat_colours(image, pixels, 2, 0.15);
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

}  // namespace
}  // namespace hair25d::completion::detail
