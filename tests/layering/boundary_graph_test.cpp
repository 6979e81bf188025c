// Crack-grid boundaries and junctions on tiny hand-built label maps.
#include <gtest/gtest.h>

#include <algorithm>

#include "hair25d/core/error.h"
#include "hair25d/layering/boundary_graph.h"

namespace hair25d::layering {
namespace {

// Regions: A (1) above y = 3, B (2) left and C (3) right of x = 4 below it.
LabelMap t_map(int w = 9, int h = 7) {
  LabelMap m(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) m.at(x, y) = y < 3 ? 1 : (x < 4 ? 2 : 3);
  return m;
}

const Boundary* find_boundary(const BoundaryGraph& g, int a, int b) {
  for (const Boundary& x : g.boundaries)
    if ((x.left == a && x.right == b) || (x.left == b && x.right == a)) return &x;
  return nullptr;
}

TEST(BoundaryGraph, TJunctionIsOneCornerWithThreeBoundaries) {
  const BoundaryGraph g = build_boundary_graph(t_map());
  // The T corner (4, 3) plus the three places where inner boundaries reach
  // the image border (meeting the outside label).
  const auto t = std::find_if(g.junctions.begin(), g.junctions.end(),
                              [](const Junction& j) { return j.position == Vec2(4, 3); });
  ASSERT_NE(t, g.junctions.end());
  EXPECT_EQ(t->boundaries.size(), 3u);
  const Boundary* ab = find_boundary(g, 1, 2);
  const Boundary* ac = find_boundary(g, 1, 3);
  const Boundary* bc = find_boundary(g, 2, 3);
  ASSERT_TRUE(ab && ac && bc);
  EXPECT_DOUBLE_EQ(ab->length(), 4.0);  // from x = 0 to x = 4 along y = 3
  EXPECT_DOUBLE_EQ(ac->length(), 5.0);
  EXPECT_DOUBLE_EQ(bc->length(), 4.0);  // from y = 3 to y = 7 along x = 4
  // Walking along a boundary, `left` is on the left as seen on the screen.
  const Vec2 dir = ab->points[1] - ab->points[0];
  const Vec2 left_normal(dir.y(), -dir.x());
  const Vec2 mid = 0.5 * (ab->points[0] + ab->points[1]) + 0.5 * left_normal;
  const int left_label = t_map().at(static_cast<int>(mid.x()), static_cast<int>(mid.y()));
  EXPECT_EQ(left_label, ab->left);
}

TEST(BoundaryGraph, EveryCrackEdgeIsInExactlyOneBoundary) {
  const LabelMap m = t_map(11, 6);
  const BoundaryGraph g = build_boundary_graph(m);
  // Count crack edges directly: adjacent pixels with different labels, and
  // the image border (against the outside).
  int expected = 2 * (m.width() + m.height());
  for (int y = 0; y < m.height(); ++y)
    for (int x = 0; x < m.width(); ++x) {
      if (x + 1 < m.width() && m.at(x, y) != m.at(x + 1, y)) ++expected;
      if (y + 1 < m.height() && m.at(x, y) != m.at(x, y + 1)) ++expected;
    }
  double total = 0;
  for (const Boundary& b : g.boundaries) total += b.length();
  EXPECT_DOUBLE_EQ(total, expected);
}

TEST(BoundaryGraph, IslandIsAClosedLoopWithoutJunctions) {
  LabelMap m(8, 6, 1);
  for (int y = 2; y < 4; ++y)
    for (int x = 3; x < 6; ++x) m.at(x, y) = 2;
  const BoundaryGraph g = build_boundary_graph(m);
  const Boundary* loop = find_boundary(g, 1, 2);
  ASSERT_NE(loop, nullptr);
  EXPECT_TRUE(loop->closed());
  EXPECT_DOUBLE_EQ(loop->length(), 10.0);  // 2 × (3 + 2)
  EXPECT_TRUE(g.junctions.empty());        // the border loop meets no third label either
}

TEST(BoundaryGraph, SaddleCornerIsNotAJunction) {
  // Two labels meeting diagonally at (2, 2).
  LabelMap m(4, 4, 1);
  for (int y = 0; y < 2; ++y)
    for (int x = 2; x < 4; ++x) m.at(x, y) = 2;
  for (int y = 2; y < 4; ++y)
    for (int x = 0; x < 2; ++x) m.at(x, y) = 2;
  const BoundaryGraph g = build_boundary_graph(m);
  for (const Junction& j : g.junctions) EXPECT_NE(j.position, Vec2(2, 2));
  for (const Boundary& b : g.boundaries) {
    if (b.left == kOutsideLabel || b.right == kOutsideLabel) continue;
    EXPECT_TRUE((b.left == 1 && b.right == 2) || (b.left == 2 && b.right == 1));
  }
}

TEST(BoundaryGraph, RejectsEmptyMap) { EXPECT_THROW(build_boundary_graph(LabelMap()), Error); }

TEST(OutlineFill, SplitsALineBetweenTwoRegionsInTheMiddle) {
  // Regions 1 and 2 separated by a 4-pixel wide column of 0 (an outline).
  LabelMap m(14, 9, 0);
  for (int y = 0; y < 9; ++y)
    for (int x = 0; x < 14; ++x) m.at(x, y) = x < 5 ? 1 : (x >= 9 ? 2 : 0);
  const OutlineFill f = fill_outlines(m);
  EXPECT_NEAR(f.line_width, 4.0, 1.0);
  for (int y = 0; y < 9; ++y) {
    EXPECT_EQ(f.labels.at(6, y), 1);
    EXPECT_EQ(f.labels.at(7, y), 2);
  }
}

TEST(OutlineFill, FarBackgroundStaysBackground) {
  LabelMap m(40, 12, 0);
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 4; ++x) m.at(x, y) = 1;
  for (int y = 0; y < 12; ++y) m.at(39, y) = 2;
  const OutlineFill f = fill_outlines(m, {.max_distance = 3.0});
  EXPECT_EQ(f.labels.at(6, 5), 1);   // within 3 pixels
  EXPECT_EQ(f.labels.at(20, 5), 0);  // far from any region
}

TEST(OutlineFill, RejectsBadInput) {
  EXPECT_THROW(fill_outlines(LabelMap()), Error);
  OutlineFillOptions bad;
  bad.max_distance = std::numeric_limits<double>::quiet_NaN();
  std::string why;
  EXPECT_FALSE(bad.is_valid(&why));
  EXPECT_NE(why.find("max_distance"), std::string::npos);
  EXPECT_THROW(fill_outlines(LabelMap(3, 2, 1), bad), Error);
}

}  // namespace
}  // namespace hair25d::layering
