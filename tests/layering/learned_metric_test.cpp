// The learned boundary metric: its features change sign with the walking
// direction (so the model cannot prefer a side), and the trained weights keep
// the paper's basic cues — the bar of an ideal T and the convex side on top.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "hair25d/layering/learned_metric.h"

namespace hair25d::layering {
namespace {

constexpr double kPi = std::numbers::pi;

BoundaryCues swapped(BoundaryCues c) {
  for (EndAngles* e : {&c.start, &c.end}) {
    std::swap(e->left, e->right);
    std::swap(e->wide_left, e->wide_right);
    std::swap(e->curved_left, e->curved_right);
    std::swap(e->circle_left, e->circle_right);
    std::swap(e->circle_wide_left, e->circle_wide_right);
  }
  std::swap(c.shared_left, c.shared_right);
  std::swap(c.start, c.end);  // walked the other way
  std::swap(c.area_left, c.area_right);
  std::swap(c.perimeter_left, c.perimeter_right);
  c.phi_r = -c.phi_r;
  c.turning = -c.turning;
  return c;
}

TEST(LearnedMetric, ChangesSignWhenTheBoundaryIsWalkedTheOtherWay) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0.05, 2 * kPi - 0.3), unit(-1, 1), size(10, 5000);
  for (int i = 0; i < 200; ++i) {
    BoundaryCues c;
    c.start = {i % 3 != 0, angle(rng), angle(rng), 3 + i % 2, angle(rng), angle(rng)};
    c.end = {i % 5 != 0, angle(rng), angle(rng), 3 + i % 3, angle(rng), angle(rng)};
    for (EndAngles* e : {&c.start, &c.end}) {
      e->curved_left = angle(rng);
      e->curved_right = angle(rng);
      e->circle_left = angle(rng);
      e->circle_right = angle(rng);
      e->circle_wide_left = angle(rng);
      e->circle_wide_right = angle(rng);
    }
    c.shared_left = 0.5 + 0.5 * unit(rng);
    c.shared_right = 0.5 + 0.5 * unit(rng);
    c.phi_r = 2 * unit(rng);
    c.turning = kPi * unit(rng);
    c.area_left = size(rng);
    c.area_right = size(rng);
    c.perimeter_left = size(rng) / 10;
    c.perimeter_right = size(rng) / 10;
    const BoundaryFeatures f = boundary_features(c), g = boundary_features(swapped(c));
    for (int k = 0; k < kBoundaryFeatureCount; ++k) EXPECT_NEAR(f[k], -g[k], 1e-12) << k;
    EXPECT_NEAR(learned_metric(f), -learned_metric(g), 1e-9);
  }
}

TEST(LearnedMetric, BarOfAnIdealTIsOnTop) {
  BoundaryCues c;
  // Every way of measuring the sectors sees the same ideal T.
  c.start = {true, kPi, kPi / 2, 3, kPi, kPi / 2, kPi, kPi / 2, kPi, kPi / 2, kPi, kPi / 2};
  c.end = c.start;
  c.area_left = c.area_right = 1000;
  c.perimeter_left = c.perimeter_right = 200;
  EXPECT_GT(learned_metric(boundary_features(c)), 1.0);
  EXPECT_LT(learned_metric(boundary_features(swapped(c))), -1.0);
}

TEST(LearnedMetric, ConvexSideIsOnTopWithoutJunctions) {
  BoundaryCues c;  // no junction ends used: only the region overlap speaks
  c.phi_r = 0.3;
  c.area_left = c.area_right = 1000;
  c.perimeter_left = c.perimeter_right = 200;
  EXPECT_GT(learned_metric(boundary_features(c)), 0.25);
}

TEST(LearnedMetric, CuspEndsSayNothing) {
  BoundaryCues c;
  c.start = {false, kPi, kPi / 2, 3, kPi, kPi / 2};
  c.end = {false, 0.2, 1.7, 3, 0.3, 1.6};
  const BoundaryFeatures f = boundary_features(c);
  for (double v : f) EXPECT_EQ(v, 0.0);
}

}  // namespace
}  // namespace hair25d::layering

namespace hair25d::layering {
namespace {

TEST(RegionContext, StandingAgainstTheOtherNeighbours) {
  // Region 1 is put over 3 (log-odds +2, 10 px) and region 2 under 3 (−2 as
  // walked 2 → 3, 30 px); 1 and 2 share a boundary whose own vote is left out
  // of their standing. Hand-computed with t = tanh(1).
  const double t = std::tanh(1.0);
  const std::vector<ContextBoundary> b{
      {1, 2, 20.0, 0.5, true},
      {1, 3, 10.0, 2.0, true},
      {2, 3, 30.0, -2.0, true},
      {3, 0, 50.0, 4.0, true},   // background: never counted
      {1, 3, 40.0, -9.0, false}  // not occluding: left out
  };
  const std::vector<double> d = context_differences(b);
  ASSERT_EQ(d.size(), b.size());
  // Pair (1, 2): 1 stands +t over its other neighbours, 2 stands −t.
  EXPECT_NEAR(d[0], 2 * t, 1e-12);
  // Pair (1, 3): 1 has only 2 left (+tanh(0.25)); 3 has 2 below it: +t.
  EXPECT_NEAR(d[1], std::tanh(0.25) - t, 1e-12);
  // Walked the other way, the difference changes sign.
  const std::vector<double> e = context_differences(
      {{2, 1, 20.0, -0.5, true}, {3, 1, 10.0, -2.0, true}, {3, 2, 30.0, 2.0, true}});
  EXPECT_NEAR(e[0], -d[0], 1e-12);
  EXPECT_NEAR(e[1], -d[1], 1e-12);
  EXPECT_EQ(d[3], 0.0);
  // The second stage changes sign with its inputs too.
  EXPECT_NEAR(context_metric(1.3, 0.4), -context_metric(-1.3, -0.4), 1e-12);
}

}  // namespace
}  // namespace hair25d::layering
