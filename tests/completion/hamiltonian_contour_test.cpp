#include <gtest/gtest.h>

#include <cmath>

#include "hair25d/completion/active_contour.h"
#include "hair25d/completion/hamiltonian.h"
#include "hair25d/core/error.h"

namespace hair25d::completion {
namespace {

TEST(Hamiltonian, StraightPieceGivesAFlowAlongIt) {
  Polyline line;
  for (int i = 0; i <= 10; ++i) line.emplace_back(20 + 2.0 * i, 30 + 1.0 * i);
  const HamiltonianField f = fit_hamiltonian(line);
  const Vec2 dir = Vec2(2, 1).normalized();
  EXPECT_LT(f.residual, 1e-3);
  // Further along the line the flow keeps the direction: the shape is extended.
  EXPECT_GT(f.flow(Vec2(60, 50)).normalized().dot(dir), 0.999);
  // ∂H/∂t = 0 along the piece: H is constant on it.
  EXPECT_NEAR(f.value(line.front()), f.value(line.back()), 1e-3);
}

TEST(Hamiltonian, ArcGivesACircularFlow) {
  const Vec2 c(100, 80);
  const double r = 40;
  Polyline arc;
  for (int i = 0; i <= 12; ++i) {
    const double a = 0.05 * i;
    arc.push_back(c + r * Vec2(std::cos(a), std::sin(a)));
  }
  const HamiltonianField f = fit_hamiltonian(arc, 0.0);
  EXPECT_LT(f.residual, 0.02);
  // Continuing around the circle, the flow stays tangent to it.
  const double a = 0.9;
  const Vec2 x = c + r * Vec2(std::cos(a), std::sin(a));
  const Vec2 tangent(-std::sin(a), std::cos(a));
  EXPECT_GT(f.flow(x).normalized().dot(tangent), 0.98);
}

TEST(Hamiltonian, BadPiecesThrow) {
  EXPECT_THROW(fit_hamiltonian({{0, 0}, {1, 1}}), Error);
  EXPECT_THROW(fit_hamiltonian({{0, 0}, {0, 0}, {0, 0}, {1, 1}}), Error);
  EXPECT_THROW(fit_hamiltonian({{0, 0}, {1, std::nan("")}, {2, 2}}), Error);
}

// A band y in [40, 70] coming from the left ends at x = 100 under an occluder
// x in [100, 150]: the contour grows from the cut into the occluder and stops.
struct BandUnderOccluder {
  ContourFields fields;
  Vec2 p{100, 40}, q{100, 70};
  std::function<bool(const Vec2&)> allowed = [](const Vec2& x) {
    const bool band = x.x() >= 10 && x.x() < 100 && x.y() >= 40 && x.y() < 70;
    const bool occluder = x.x() >= 100 && x.x() < 150 && x.y() >= 20 && x.y() < 90;
    return band || occluder;
  };
  BandUnderOccluder() {
    Polyline top, bottom;
    for (int i = 0; i <= 8; ++i) top.emplace_back(84 + 2.0 * i, 40);
    for (int i = 0; i <= 8; ++i) bottom.emplace_back(84 + 2.0 * i, 70);
    fields.at_p = fit_hamiltonian(top);
    fields.at_q = fit_hamiltonian(bottom);
    fields.sign_p = fields.at_p.value(p) - fields.at_p.value(q) >= 0 ? 1 : -1;
    fields.sign_q = fields.at_q.value(q) - fields.at_q.value(p) >= 0 ? 1 : -1;
  }
};

TEST(ActiveContour, GrowsUnderTheOccluderAndStops) {
  BandUnderOccluder s;
  ContourOptions options;
  const ContourResult r =
      grow_contour({s.p, s.q}, Vec2(1, 0), Vec2(1, 0), s.fields, s.allowed, options);
  EXPECT_NE(r.stop, ContourStop::kIterationCap);
  EXPECT_LT(r.iterations, options.max_iterations);
  ASSERT_GE(r.curve.size(), 5u);
  EXPECT_LT((r.curve.front() - s.p).norm(), 1e-9);
  EXPECT_LT((r.curve.back() - s.q).norm(), 1e-9);
  double reach = 0;
  for (const Vec2& x : r.curve) {
    EXPECT_TRUE(s.allowed(x)) << x.transpose();
    // Ω keeps the growth between the extended sides of the band.
    EXPECT_GT(x.y(), 38.0);
    EXPECT_LT(x.y(), 72.0);
    reach = std::max(reach, x.x());
  }
  EXPECT_GT(reach, 115.0) << "the curve moved into the occluder";
  EXPECT_LT(reach, 150.0);
}

TEST(ActiveContour, StopsWhenItWouldLeaveTheOccluder) {
  BandUnderOccluder s;
  // A narrow occluder: the growing front reaches its far side quickly.
  s.allowed = [](const Vec2& x) {
    return (x.x() >= 10 && x.x() < 100 && x.y() >= 40 && x.y() < 70) ||
           (x.x() >= 100 && x.x() < 108 && x.y() >= 20 && x.y() < 90);
  };
  ContourOptions options;
  options.epsilon = 1e-6;
  const ContourResult r =
      grow_contour({s.p, s.q}, Vec2(1, 0), Vec2(1, 0), s.fields, s.allowed, options);
  EXPECT_EQ(r.stop, ContourStop::kLeftAllowed);
  for (const Vec2& x : r.curve) EXPECT_TRUE(s.allowed(x));
}

// A notch of another region cuts into the occluder next to the band's top
// side: the points that reach it stay there while the rest of the curve
// grows (in Algorithm 1 as written the first point that would leave stops
// the whole curve, which on drawings stopped most curves in their first steps).
TEST(ActiveContour, PointsAtTheOccludersEdgeHoldWhileTheRestGrows) {
  BandUnderOccluder s;
  s.allowed = [](const Vec2& x) {
    const bool band = x.x() >= 10 && x.x() < 100 && x.y() >= 40 && x.y() < 70;
    const bool occluder = x.x() >= 100 && x.x() < 150 && x.y() >= 20 && x.y() < 90;
    const bool notch = x.x() >= 106 && x.x() < 112 && x.y() >= 30 && x.y() < 46;
    return band || (occluder && !notch);
  };
  const ContourResult r = grow_contour({s.p, s.q}, Vec2(1, 0), Vec2(1, 0), s.fields, s.allowed);
  EXPECT_NE(r.stop, ContourStop::kIterationCap);
  double reach = 0;
  for (const Vec2& x : r.curve) {
    EXPECT_TRUE(s.allowed(x)) << x.transpose();
    reach = std::max(reach, x.x());
  }
  EXPECT_GT(reach, 130.0) << "the curve grew past the notch";
}

// The occluder's top half ends 25 px in, its bottom half runs on for 300 px
// (a long occluder under which the strand's root ends): once the grown top
// of the curve meets the edge, the curve stops (Algorithm 1, lines 7–8)
// instead of growing on along the long half up to max_reach.
TEST(ActiveContour, StopsWhenTheGrownFrontMeetsTheOccludersEdge) {
  BandUnderOccluder s;
  s.allowed = [](const Vec2& x) {
    const bool band = x.x() >= 10 && x.x() < 100 && x.y() >= 40 && x.y() < 70;
    const bool top = x.x() >= 100 && x.x() < 125 && x.y() >= 20 && x.y() < 55;
    const bool bottom = x.x() >= 100 && x.x() < 400 && x.y() >= 55 && x.y() < 90;
    return band || top || bottom;
  };
  const ContourResult r = grow_contour({s.p, s.q}, Vec2(1, 0), Vec2(1, 0), s.fields, s.allowed);
  EXPECT_EQ(r.stop, ContourStop::kLeftAllowed);
  double reach = 0;
  for (const Vec2& x : r.curve) {
    EXPECT_TRUE(s.allowed(x)) << x.transpose();
    reach = std::max(reach, x.x());
  }
  EXPECT_GT(reach, 115.0) << "the curve grew into the occluder";
  EXPECT_LT(reach, 135.0) << "stopped about where the top half ends";
  // Never stopping on the grown front: the bottom half grows on.
  ContourOptions never;
  never.stop_share = 1.0;
  const ContourResult held =
      grow_contour({s.p, s.q}, Vec2(1, 0), Vec2(1, 0), s.fields, s.allowed, never);
  double held_reach = 0;
  for (const Vec2& x : held.curve) held_reach = std::max(held_reach, x.x());
  EXPECT_GT(held_reach, 140.0);
  ContourOptions bad;
  bad.stop_share = 1.5;
  std::string why;
  EXPECT_FALSE(bad.is_valid(&why));
  EXPECT_NE(why.find("stop_share"), std::string::npos);
  bad = ContourOptions{};
  bad.hold_distance = -1;
  EXPECT_FALSE(bad.is_valid(&why));
  EXPECT_NE(why.find("hold_distance"), std::string::npos);
}

// Under a wide occluder the growth stops max_reach chord lengths from p q.
TEST(ActiveContour, GrowthStopsAtMaxReachUnderAWideOccluder) {
  BandUnderOccluder s;
  s.allowed = [](const Vec2& x) {
    const bool band = x.x() >= 10 && x.x() < 100 && x.y() >= 40 && x.y() < 70;
    return band || (x.x() >= 100 && x.x() < 500 && x.y() >= 0 && x.y() < 110);
  };
  for (double max_reach : {1.0, 2.0}) {
    ContourOptions options;
    options.max_reach = max_reach;
    const ContourResult r =
        grow_contour({s.p, s.q}, Vec2(1, 0), Vec2(1, 0), s.fields, s.allowed, options);
    double reach = 0;
    for (const Vec2& x : r.curve) reach = std::max(reach, x.x());
    SCOPED_TRACE(max_reach);
    EXPECT_LE(reach, 100.0 + 30.0 * max_reach + 1e-9);  // |p − q| = 30
    EXPECT_GT(reach, 100.0 + 30.0 * max_reach - 4.0) << "grew up to the reach";
  }
  ContourOptions bad;
  bad.max_reach = 0;
  std::string why;
  EXPECT_FALSE(bad.is_valid(&why));
  EXPECT_NE(why.find("max_reach"), std::string::npos);
}

TEST(ActiveContour, ZeroFieldConvergesAtOnce) {
  BandUnderOccluder s;
  ContourFields zero;  // A = 0, B = 0: no force anywhere
  const ContourResult r = grow_contour({s.p, s.q}, Vec2(1, 0), Vec2(1, 0), zero, s.allowed);
  EXPECT_EQ(r.stop, ContourStop::kConverged);
  EXPECT_EQ(r.iterations, 1);
}

TEST(ActiveContour, BadInputThrows) {
  BandUnderOccluder s;
  EXPECT_THROW(grow_contour({s.p}, Vec2(1, 0), Vec2(1, 0), s.fields, s.allowed), Error);
  ContourOptions bad;
  bad.step = 0;
  std::string why;
  EXPECT_FALSE(bad.is_valid(&why));
  EXPECT_NE(why.find("step"), std::string::npos);
  EXPECT_THROW(grow_contour({s.p, s.q}, Vec2(1, 0), Vec2(1, 0), s.fields, s.allowed, bad), Error);
}

}  // namespace
}  // namespace hair25d::completion
