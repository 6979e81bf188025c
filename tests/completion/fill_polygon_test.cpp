// fill_polygon (completion/src/raster.h) leaves out the inner vertices of
// straight whole-pixel runs (session 40): the masks must be those of
// cv::fillPoly given every vertex. And the rasters' kept scratch bytes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <opencv2/imgproc.hpp>
#include <random>
#include <vector>

#include "raster.h"

namespace hair25d::completion::detail {
namespace {

constexpr int kSize = 120;

// cv::fillPoly with every vertex, at fill_polygon's 1/16 pixel.
cv::Mat every_vertex(const Polyline& polygon, const cv::Point& origin) {
  std::vector<cv::Point> pts;
  for (const Vec2& p : polygon)
    pts.emplace_back(static_cast<int>(std::lround((p.x() - origin.x - 0.5) * 16)),
                     static_cast<int>(std::lround((p.y() - origin.y - 0.5) * 16)));
  cv::Mat mask(kSize, kSize, CV_8U, cv::Scalar(0));
  const cv::Point* data = pts.data();
  const int count = static_cast<int>(pts.size());
  cv::fillPoly(mask, &data, &count, 1, cv::Scalar(255), cv::LINE_8, 4);
  return mask;
}

// An outline walked through pixel centres a step at a time, in runs of one
// direction (axis or diagonal), now and then jumping by a fraction of a
// pixel (a Bézier's samples) or by half pixels (runs that are not whole).
Polyline walk(std::mt19937& rng) {
  static const int kDx[8] = {1, 1, 0, -1, -1, -1, 0, 1}, kDy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
  Polyline out;
  Vec2 p(60.5, 60.5);
  const int n = 20 + static_cast<int>(rng() % 200);
  int dir = static_cast<int>(rng() % 8), left = 0;
  for (int i = 0; i < n; ++i) {
    out.push_back(p);
    if (left == 0) dir = static_cast<int>(rng() % 8), left = 1 + static_cast<int>(rng() % 12);
    --left;
    const int kind = static_cast<int>(rng() % 10);
    const double step = kind == 9 ? 0.5 : 1.0;
    if (kind == 8)
      p += Vec2((static_cast<int>(rng() % 41) - 20) / 16.0,
                (static_cast<int>(rng() % 41) - 20) / 16.0);
    else
      p += step * Vec2(kDx[dir], kDy[dir]);
    p = p.cwiseMax(Vec2(10.5, 10.5)).cwiseMin(Vec2(kSize - 10.5, kSize - 10.5));
  }
  return out;
}

TEST(FillPolygon, StraightRunsFillAsWithEveryVertex) {
  std::mt19937 rng(40);
  int shortened = 0;
  for (int t = 0; t < 3000; ++t) {
    const Polyline polygon = walk(rng);
    const cv::Point origin(static_cast<int>(rng() % 5), static_cast<int>(rng() % 5));
    cv::Mat mask(kSize, kSize, CV_8U, cv::Scalar(0));
    fill_polygon(mask, polygon, origin, 255);
    const cv::Mat expected = every_vertex(polygon, origin);
    ASSERT_EQ(cv::countNonZero(mask != expected), 0) << "polygon " << t;
    shortened += cv::countNonZero(mask) > 0;
  }
  EXPECT_GT(shortened, 2900);  // the walks fill something
}

// A rectangle's outline through every pixel centre: its sides are four runs.
TEST(FillPolygon, RectangleOutlineFillsTheRectangle) {
  Polyline outline;
  for (int x = 20; x < 50; ++x) outline.emplace_back(x + 0.5, 30.5);
  for (int y = 30; y < 70; ++y) outline.emplace_back(50.5, y + 0.5);
  for (int x = 50; x > 20; --x) outline.emplace_back(x + 0.5, 70.5);
  for (int y = 70; y > 30; --y) outline.emplace_back(20.5, y + 0.5);
  cv::Mat mask(kSize, kSize, CV_8U, cv::Scalar(0));
  fill_polygon(mask, outline, cv::Point(0, 0), 255);
  EXPECT_EQ(cv::countNonZero(mask), 31 * 41);
  EXPECT_EQ(cv::countNonZero(mask(cv::Rect(20, 30, 31, 41))), 31 * 41);
}

// Zeroed on every use, kept between uses, freed when over the cap.
TEST(ScratchBytes, ZeroedEachTimeAndLargeBuffersFreed) {
  std::vector<std::uint8_t> kept;
  {
    ScratchBytes scratch(kept, 1000);
    scratch.data()[10] = 7;
  }
  EXPECT_GE(kept.capacity(), 1000u);
  {
    ScratchBytes scratch(kept, 1000);
    EXPECT_EQ(scratch.data()[10], 0);
  }
  { ScratchBytes scratch(kept, ScratchBytes::kMaxKeptBytes + 1); }
  EXPECT_EQ(kept.capacity(), 0u);
}

}  // namespace
}  // namespace hair25d::completion::detail
