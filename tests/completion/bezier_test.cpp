#include "hair25d/completion/bezier.h"

#include <gtest/gtest.h>

namespace hair25d::completion {
namespace {

TEST(Bezier, JoinIsC1WithTheTangentsAtBothEnds) {
  const Vec2 p(10, 20), q(90, 35);
  const Vec2 tp = Vec2(1, 0.2).normalized(), tq = Vec2(1, -0.3).normalized();
  const CubicBezier b = join_bezier(p, tp, q, tq);
  EXPECT_LT((b.point(0) - p).norm(), 1e-12);
  EXPECT_LT((b.point(1) - q).norm(), 1e-12);
  const Vec2 d0 = b.derivative(0), d1 = b.derivative(1);
  EXPECT_NEAR(d0.normalized().dot(tp), 1.0, 1e-12);
  EXPECT_NEAR(d1.normalized().dot(tq), 1.0, 1e-12);
  // Magnitudes equal the chord: a C¹ continuation of unit-speed curves scaled by it.
  EXPECT_NEAR(d0.norm(), (q - p).norm(), 1e-9);
  EXPECT_NEAR(d1.norm(), (q - p).norm(), 1e-9);
  // The derivative is continuous in between (finite differences agree).
  for (double t = 0.05; t < 1.0; t += 0.1) {
    const Vec2 fd = (b.point(t + 1e-6) - b.point(t - 1e-6)) / 2e-6;
    EXPECT_LT((fd - b.derivative(t)).norm(), 1e-4);
  }
  const Polyline s = b.sample(10);
  ASSERT_EQ(s.size(), 11u);
  EXPECT_LT((s.front() - p).norm(), 1e-12);
  EXPECT_LT((s.back() - q).norm(), 1e-12);
}

}  // namespace
}  // namespace hair25d::completion
