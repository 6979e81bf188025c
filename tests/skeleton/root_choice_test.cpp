// Which end of a strand is its root (paper §6): the end by the head or under
// the occluder; tips are the sharp corners lying above their neighbourhood.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hair25d/skeleton/strand_skeleton.h"

namespace hair25d::skeleton {
namespace {

// A 280 x 40 bar with a flat end at x = 0 and a sharp point at (340, 20),
// a vertex every pixel or so (as traced outlines are: a covered flag then
// marks that stretch of outline).
Polyline pointed_bar() {
  const Polyline corners = {{0, 0}, {280, 0}, {340, 20}, {280, 40}, {0, 40}};
  Polyline dense;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec2 a = corners[i], b = corners[(i + 1) % corners.size()];
    const int steps = static_cast<int>(std::ceil((b - a).norm()));
    for (int k = 0; k < steps; ++k) dense.push_back(a + (b - a) * (static_cast<double>(k) / steps));
  }
  return dense;
}

// Covered flags for the outline points on the upper edge with x in [from, to].
std::vector<bool> cover_upper_edge(const Polyline& outline, double from, double to) {
  std::vector<bool> covered(outline.size(), false);
  for (std::size_t i = 0; i < outline.size(); ++i)
    covered[i] = outline[i].y() < 20.0 - 1e-9 && outline[i].x() >= from && outline[i].x() <= to;
  return covered;
}

// A bang whose top comes to a sharp point where its upper edge goes under
// the crown a few pixels short of it, the head beyond that point: the point
// is the strand's head end. Before, every sharp visible corner was a tip and
// never a root, so the root went to the far, blunt end (wikipe-tan's bang
// "strand 17" of session 8, rooted at its bottom).
TEST(RootChoice, SharpCornerUnderAnOccluderAtTheHeadEndIsTheRoot) {
  Input in;
  in.outline = pointed_bar();
  // The upper edge from x = 300 to 328 (ending 12 px short of the point)
  // runs under the crown.
  in.covered = cover_upper_edge(in.outline, 300, 328);
  in.root_hint = Vec2(420, 20);
  const Result r = build_skeleton(in);
  ASSERT_FALSE(r.skeleton.nodes.empty());
  EXPECT_LT((r.skeleton.nodes[0] - Vec2(340, 20)).norm(), 6.0)
      << "root at " << r.skeleton.nodes[0].transpose();
  ASSERT_EQ(r.skeleton.tips.size(), 1u);
  EXPECT_LT(r.skeleton.nodes[r.skeleton.tips[0]].x(), 20.0) << "the skeleton runs to the far end";
  for (const Vec2& t : r.tip_corners) EXPECT_GT((t - Vec2(340, 20)).norm(), 6.0);
}

// The same bar with nothing covered: its point lies above all its
// neighbours, so it is a tip even though the hint is beyond it (generated
// locks hanging past the head centre point their tips at it).
TEST(RootChoice, FreeSharpCornerNearTheHintStaysATip) {
  Input in;
  in.outline = pointed_bar();
  in.root_hint = Vec2(420, 20);
  const Result r = build_skeleton(in);
  ASSERT_FALSE(r.skeleton.nodes.empty());
  EXPECT_LT(r.skeleton.nodes[0].x(), 10.0) << "root at " << r.skeleton.nodes[0].transpose();
  ASSERT_EQ(r.skeleton.tips.size(), 1u);
  EXPECT_LT((r.skeleton.nodes[r.skeleton.tips[0]] - Vec2(340, 20)).norm(), 1.0);
}

// A corner whose covered stretch lies farther along the outline than the tip
// separation still lies above its neighbourhood: a tip.
TEST(RootChoice, CoverFartherThanTheSeparationLeavesTheCornerATip) {
  Input in;
  in.outline = pointed_bar();
  in.covered = cover_upper_edge(in.outline, 200, 270);  // > 70 px from the point
  in.root_hint = Vec2(420, 20);
  const Result r = build_skeleton(in);
  ASSERT_EQ(r.skeleton.tips.size(), 1u);
  EXPECT_LT((r.skeleton.nodes[r.skeleton.tips[0]] - Vec2(340, 20)).norm(), 1.0);
  EXPECT_LT(r.skeleton.nodes[0].x(), 10.0);
}

// Without a hint the root is the end farthest from the sharpest free tip;
// a point touching an occluder may be that root.
TEST(RootChoice, WithoutHintTheFarEndOfTheFreeTipIsTheRoot) {
  Input in;
  in.outline = pointed_bar();
  const Result r = build_skeleton(in);
  ASSERT_EQ(r.skeleton.tips.size(), 1u);
  EXPECT_LT((r.skeleton.nodes[r.skeleton.tips[0]] - Vec2(340, 20)).norm(), 1.0);
  EXPECT_LT(r.skeleton.nodes[0].x(), 10.0);
}

}  // namespace
}  // namespace hair25d::skeleton
