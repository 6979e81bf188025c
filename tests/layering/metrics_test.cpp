// Φ_J, Φ_R and the junction geometry they are measured on (paper §4.2–4.4).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hair25d/layering/boundary_graph.h"
#include "hair25d/layering/metrics.h"

namespace hair25d::layering {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(JunctionMetric, IdealTJunctionPutsTheStraightRegionOnTop) {
  // Property 1: α = π, β = π/2 → A on top with the largest value, π/2.
  EXPECT_NEAR(junction_metric(kPi, kPi / 2), kPi / 2, 1e-12);
  EXPECT_NEAR(junction_metric(kPi / 2, kPi), -kPi / 2, 1e-12);
  EXPECT_GT(junction_metric(0.95 * kPi, 0.55 * kPi), 0.0);
}

TEST(JunctionMetric, Property2EqualAnglesGiveNoPreference) {
  for (double a : {0.3, 1.0, 1.7, 2.5, 3.0, 4.0}) EXPECT_NEAR(junction_metric(a, a), 0.0, 1e-12);
}

TEST(JunctionMetric, Property3SupplementaryAnglesGiveNoPreference) {
  // Several strands going under one: α + β = π.
  for (double a : {0.2, 0.9, 1.3, 2.0, 2.8}) EXPECT_NEAR(junction_metric(a, kPi - a), 0.0, 1e-12);
}

TEST(JunctionMetric, Property4SharpTipIsOnTop) {
  // β near 0 (a hair tip), α away from 0 and π: B on top, Φ_J < 0.
  for (double a : {0.6, 1.2, kPi / 2, 2.0, 2.6}) EXPECT_LT(junction_metric(a, 0.05), 0.0);
  // ...but not when α is near 0 or π as well (Properties 2 and 3).
  EXPECT_NEAR(junction_metric(0.05, 0.05), 0.0, 1e-12);
  EXPECT_NEAR(junction_metric(kPi - 0.05, 0.05), 0.0, 1e-12);
}

TEST(JunctionMetric, MeasuredOnARasterTJunction) {
  // A fills the top rows; B and C split the bottom at x = 20: a T at (20, 12)
  // with α = π for A, β = π/2 for B. Non-square on purpose.
  LabelMap m(41, 25);
  for (int y = 0; y < m.height(); ++y)
    for (int x = 0; x < m.width(); ++x) m.at(x, y) = y < 12 ? 1 : (x < 20 ? 2 : 3);
  const BoundaryGraph g = build_boundary_graph(m);
  int t = -1;
  for (std::size_t j = 0; j < g.junctions.size(); ++j)
    if (g.junctions[j].position == Vec2(20, 12)) t = static_cast<int>(j);
  ASSERT_GE(t, 0);
  std::vector<Vec2> rays;
  std::vector<const Boundary*> owners;
  for (int bi : g.junctions[t].boundaries) {
    const Boundary& b = g.boundaries[bi];
    Polyline pts = b.points;
    if (b.end == t) pts.assign(b.points.rbegin(), b.points.rend());
    rays.push_back(leaving_direction(pts, 6.0));
    owners.push_back(&b);
  }
  const RaySectors s = sectors_around(rays);
  ASSERT_EQ(s.sectors.size(), 3u);
  std::vector<double> sorted = s.sectors;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_NEAR(sorted[0], kPi / 2, 1e-9);
  EXPECT_NEAR(sorted[1], kPi / 2, 1e-9);
  EXPECT_NEAR(sorted[2], kPi, 1e-9);
  // For the A|B boundary: the sector of A is π and that of B is π/2.
  for (std::size_t k = 0; k < 3; ++k) {
    const Boundary& b = *owners[s.order[k]];
    if (!((b.left == 1 && b.right == 2) || (b.left == 2 && b.right == 1))) continue;
    const bool at_start = b.start == t;
    const double before = s.sectors[(k + 2) % 3], after = s.sectors[k];
    // Walking away from the junction, the left region fills the sector before.
    const int left_walking = at_start ? b.left : b.right;
    const double alpha = left_walking == 1 ? before : after;  // A's sector
    const double beta = left_walking == 1 ? after : before;
    EXPECT_NEAR(alpha, kPi, 1e-9);
    EXPECT_NEAR(beta, kPi / 2, 1e-9);
    EXPECT_GT(junction_metric(alpha, beta), 1.5);
  }
}

TEST(LeavingDirection, FollowsAStaircaseNotItsLastStep) {
  // A 4-connected staircase at atan(1/2) ≈ 26.6° below the x axis (y down).
  Polyline stairs{{0, 0}};
  for (int i = 0; i < 20; ++i) {
    stairs.push_back(stairs.back() + Vec2(1, 0));
    stairs.push_back(stairs.back() + Vec2(1, 0));
    stairs.push_back(stairs.back() + Vec2(0, 1));
  }
  const Vec2 d = leaving_direction(stairs, 30.0);
  EXPECT_NEAR(std::atan2(d.y(), d.x()), std::atan2(1.0, 2.0), 0.05);
}

TEST(OverlapMetric, HandComputedTriangle) {
  // Walking (0,0) → (10,0) the left (A) is up; the curve dips 5 pixels into B:
  // A overlaps B's side of the chord by a triangle of area 25.
  EXPECT_NEAR(overlap_metric({{0, 0}, {5, 5}, {10, 0}}), 25.0, 1e-12);
  EXPECT_NEAR(overlap_metric({{0, 0}, {5, -5}, {10, 0}}), -25.0, 1e-12);
  // An S-curve overlapping both ways equally: δ_A − δ_B = 0.
  EXPECT_NEAR(overlap_metric({{0, 0}, {2.5, 2}, {5, 0}, {7.5, -2}, {10, 0}}), 0.0, 1e-12);
}

TEST(CouplingWeight, TangentOfTheDeviationFromARightAngle) {
  EXPECT_NEAR(coupling_weight(kPi / 2, 10.0), 0.0, 1e-12);
  EXPECT_NEAR(coupling_weight(3 * kPi / 4, 10.0), 1.0, 1e-12);
  EXPECT_NEAR(coupling_weight(kPi / 4, 10.0), 1.0, 1e-12);
  // θ = π (smooth continuation) would be infinite: capped.
  EXPECT_NEAR(coupling_weight(kPi, 4.0), 4.0, 1e-9);
  EXPECT_NEAR(coupling_weight(0.0, 4.0), 4.0, 1e-9);
  EXPECT_TRUE(std::isfinite(coupling_weight(kPi, 1e300)));
}

}  // namespace
}  // namespace hair25d::layering

namespace hair25d::layering {
namespace {

TEST(CurvedLeavingDirection, FindsTheTangentOfABentOutline) {
  // A circle of radius 30 leaving (0, 0) along +x and bending toward +y: the
  // line through the points leans toward the chord, the quadratic keeps the
  // tangent at the junction.
  Polyline arc;
  for (int k = 0; k <= 60; ++k) {
    const double t = k * 0.01;  // radians along the circle, arc length 0.3 px a step
    arc.push_back(Vec2(30 * std::sin(t), 30 * (1 - std::cos(t))));
  }
  const Vec2 line = leaving_direction(arc, 18.0);
  const Vec2 curved = curved_leaving_direction(arc, 3.0, 18.0);
  const double line_error = std::atan2(line.y(), line.x());
  const double curved_error = std::atan2(curved.y(), curved.x());
  EXPECT_GT(line_error, 0.1);  // about a quarter of the 0.6 rad turned
  EXPECT_LT(std::abs(curved_error), 0.02);
  // A straight boundary gives its own direction with either fit.
  Polyline straight;
  for (int k = 0; k <= 20; ++k) straight.push_back(Vec2(-k * 0.6, k * 0.8));
  const Vec2 d = curved_leaving_direction(straight, 2.0, 12.0);
  EXPECT_NEAR(d.x(), -0.6, 1e-9);
  EXPECT_NEAR(d.y(), 0.8, 1e-9);
}

TEST(CurvedLeavingDirection, FallsBackOnShortCurves) {
  // Fewer than three points beyond the skipped blob: the line fit decides.
  const Polyline two{Vec2(0, 0), Vec2(1, 0), Vec2(2, 1)};
  const Vec2 d = curved_leaving_direction(two, 5.0, 12.0);
  const Vec2 e = leaving_direction(two, 12.0);
  EXPECT_NEAR(d.x(), e.x(), 1e-12);
  EXPECT_NEAR(d.y(), e.y(), 1e-12);
  EXPECT_EQ(curved_leaving_direction(Polyline{Vec2(3, 3)}, 1.0, 12.0), Vec2(1, 0));
}

}  // namespace
}  // namespace hair25d::layering
