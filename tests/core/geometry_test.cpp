#include "hair25d/core/geometry.h"

#include <gtest/gtest.h>

namespace hair25d {
namespace {

TEST(Geometry, SignedAreaIsPositiveForCounterClockwiseInPixelFrame) {
  // Down the left side, along the bottom, up the right side: counter-clockwise
  // on screen, so negative in the (x, y) frame.
  const Polyline rect = {{0, 0}, {0, 3}, {4, 3}, {4, 0}};
  EXPECT_DOUBLE_EQ(signed_area(rect), -12.0);
  const Polyline reversed_rect = {{0, 0}, {4, 0}, {4, 3}, {0, 3}};
  EXPECT_DOUBLE_EQ(signed_area(reversed_rect), 12.0);
  EXPECT_DOUBLE_EQ(signed_area(rect), -signed_area(reversed_rect));
}

TEST(Geometry, PointInPolygonOnAnLShape) {
  const Polyline l_shape = {{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 5}, {0, 5}};
  EXPECT_TRUE(point_in_polygon(l_shape, {0.5, 4.0}));
  EXPECT_TRUE(point_in_polygon(l_shape, {3.5, 0.5}));
  EXPECT_FALSE(point_in_polygon(l_shape, {3.0, 3.0}));
  EXPECT_FALSE(point_in_polygon(l_shape, {-1.0, 0.5}));
}

TEST(Geometry, ResampleKeepsEndsAndSpacing) {
  const Polyline line = {{0, 0}, {10, 0}, {10, 5}};
  const Polyline out = resample_polyline(line, 1.0);
  ASSERT_EQ(out.size(), 16u);
  EXPECT_TRUE(out.front().isApprox(line.front()));
  EXPECT_TRUE(out.back().isApprox(line.back()));
  for (std::size_t i = 1; i < out.size(); ++i) {
    EXPECT_NEAR((out[i] - out[i - 1]).norm(), 1.0, 1e-9) << i;
  }
  EXPECT_DOUBLE_EQ(polyline_length(line), 15.0);
}

}  // namespace
}  // namespace hair25d
