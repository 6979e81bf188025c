// Session 35 (JoinScorerOptions::angle_refusal_threshold): the tangents an
// angle refusal's second chance tries for each edge (angle_retry.h;
// internal: the test sees completion/src).
#include "angle_retry.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hair25d::completion::detail {
namespace {

using Kind = TriedTangents::Kind;

// Two cuts facing each other across a 20 px gap: a's at x 0 (its piece on
// the left), b's at x 20 (on the right). A clean strand's tangents point
// +x at a and −x at b.
Edge cut(double x, bool left, Vec2 tp, Vec2 tq) {
  Edge e;
  e.p = left ? Vec2(x, 0) : Vec2(x, 10);
  e.q = left ? Vec2(x, 10) : Vec2(x, 0);
  e.points = {e.p, e.q};
  e.width = 10;
  e.tangent_p = tp.normalized();
  e.tangent_q = tq.normalized();
  e.arm_p = e.arm_q = 20;
  return e;
}

RetriedTangents retry(const Edge& a, const Edge& b) {
  return retry_tangents(a, b, b.q - a.p, a.q - b.p, 70.0 * M_PI / 180.0);
}

const Vec2 kRight(1, 0), kLeft(-1, 0), kUp(0, -1);

// An arm round a tip turns one end's tangent 90°: the other end's for both.
TEST(AngleRetry, OneEndsTangentForBoth) {
  const Edge a = cut(0, true, kRight, kUp), b = cut(20, false, kLeft, kLeft);
  const RetriedTangents r = retry(a, b);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.a.kind, Kind::kEitherEnd);
  EXPECT_EQ(r.b.kind, Kind::kOwn);
  EXPECT_NEAR(r.worst, 0.0, 1e-9);
  EXPECT_NEAR(r.a.q.x(), 1.0, 1e-9);
}

// Both tangents pointing away from the cut: read reversed.
TEST(AngleRetry, ReversedTangents) {
  const Edge a = cut(0, true, kLeft, kLeft), b = cut(20, false, kLeft, kLeft);
  const RetriedTangents r = retry(a, b);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.a.kind, Kind::kReversed);
  EXPECT_NEAR(r.worst, 0.0, 1e-9);
  // Not without `turn_round` (JoinScorerOptions::angle_refusal_turned off).
  EXPECT_FALSE(retry_tangents(a, b, b.q - a.p, a.q - b.p, 70.0 * M_PI / 180.0, false).found);
}

// Tangents along the cut: no reading of the edges' own fits helps, the side
// tangent or the dropped direction does.
TEST(AngleRetry, SideAndTurnedTangents) {
  Edge a = cut(0, true, kUp, kUp);
  const Edge b = cut(20, false, kLeft, kLeft);
  EXPECT_FALSE(retry(a, b).found);
  a.side_tangent = Vec2(1, 0.2).normalized();
  RetriedTangents r = retry(a, b);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.a.kind, Kind::kSide);
  a.turned_tangent = kRight;
  r = retry(a, b);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.a.kind, Kind::kTurned);
  EXPECT_NEAR(r.worst, 0.0, 1e-9);
  r = retry_tangents(a, b, b.q - a.p, a.q - b.p, 70.0 * M_PI / 180.0, false);
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.a.kind, Kind::kSide);
}

// Tangents along both cuts: reversed or taken from either end they still
// lie along the cuts, 90° off the chords.
TEST(AngleRetry, NoReadingWithinTheLimit) {
  const Edge a = cut(0, true, kUp, kUp), b = cut(20, false, kUp, kUp);
  EXPECT_FALSE(retry(a, b).found);
}

// The net's inputs: which readings were used and what backs the ends.
TEST(AngleRetry, TermsSayWhatWasTried) {
  Edge a = cut(0, true, kRight, kUp);
  const Edge b = cut(20, false, kLeft, kLeft);
  a.arm_q = 2;
  a.ends_part = M_PI / 2;
  const RetriedTangents r = retry(a, b);
  JoinTerms t;
  add_retry_terms(a, b, r, 90.0 / 70.0, 20.0, &t);
  EXPECT_TRUE(t.retried);
  EXPECT_TRUE(t.retried_either_end);
  EXPECT_FALSE(t.retried_reversed || t.retried_side || t.retried_turned);
  EXPECT_NEAR(t.own_worst_angle, 90.0 / 70.0, 1e-12);
  EXPECT_NEAR(t.arm_min, 0.1, 1e-12);
  EXPECT_NEAR(t.arm_mean, (20 + 2 + 20 + 20) / 4.0 / 20.0, 1e-12);
  EXPECT_NEAR(t.ends_part, 0.5, 1e-12);
  EXPECT_NEAR(t.sliver, 0.0, 1e-12);  // a run as long as its chord
}

}  // namespace
}  // namespace hair25d::completion::detail
