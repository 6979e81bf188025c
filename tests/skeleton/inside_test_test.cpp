// The binned point-in-polygon test of the branch smoothing answers exactly as
// core's point_in_polygon, including on vertices' heights and outside the box.
#include "inside_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace hair25d::skeleton::detail {
namespace {

// A wobbly star: concave, many edges at the same heights.
Polyline star(int points, double cx, double cy, double r0, double r1, double wobble) {
  Polyline out;
  for (int i = 0; i < 2 * points; ++i) {
    const double t = M_PI * i / points;
    const double r = (i % 2 ? r0 : r1) * (1 + wobble * std::sin(7 * t));
    out.emplace_back(cx + r * std::cos(t), cy + 0.6 * r * std::sin(t));
  }
  return out;
}

TEST(InsideTest, AgreesWithPointInPolygon) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-60, 160);
  for (const Polyline& polygon :
       {star(5, 50, 40, 20, 45, 0.1), star(40, 30, 70, 5, 60, 0.3),
        Polyline{{0, 0}, {90, 0}, {90, 30}, {0, 30}}, Polyline{{3, 3}, {9, 3}, {6, 3}}}) {
    const InsideTest test(polygon);
    int inside = 0;
    for (int k = 0; k < 20000; ++k) {
      Vec2 p(u(rng), u(rng));
      // Every fourth point exactly at a vertex's height (the crossing rule's edge case).
      if (k % 4 == 0) p.y() = polygon[k % polygon.size()].y();
      ASSERT_EQ(test.contains(p), point_in_polygon(polygon, p)) << p.transpose();
      inside += test.contains(p);
    }
    if (polygon.size() > 3) {
      EXPECT_GT(inside, 100);
    }
  }
  EXPECT_FALSE(InsideTest(Polyline{}).contains(Vec2(0, 0)));
  EXPECT_FALSE(InsideTest(star(5, 50, 40, 20, 45, 0)).contains(Vec2(50, std::nan(""))));
}

}  // namespace
}  // namespace hair25d::skeleton::detail
