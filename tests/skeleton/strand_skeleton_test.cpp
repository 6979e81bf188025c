#include "hair25d/skeleton/strand_skeleton.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "hair25d/core/error.h"
#include "shapes.h"

namespace hair25d::skeleton {
namespace {

using test::forked_strand;
using test::tapered_strand;

int child_count(const Skeleton& s, int node) {
  int n = 0;
  for (int p : s.parent) n += p == node;
  return n;
}

void expect_well_formed(const Skeleton& s, const Polyline& outline, double spacing) {
  ASSERT_FALSE(s.nodes.empty());
  ASSERT_EQ(s.parent.size(), s.nodes.size());
  EXPECT_EQ(s.parent[0], -1);
  for (std::size_t i = 1; i < s.nodes.size(); ++i) {
    EXPECT_GE(s.parent[i], 0);
    EXPECT_LT(s.parent[i], static_cast<int>(i)) << "parents come before children";
    const double step = (s.nodes[i] - s.nodes[s.parent[i]]).norm();
    EXPECT_LE(step, spacing * 1.5 + 1e-9) << "node " << i;
  }
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    // Nodes on the outline itself (tips) count as inside: test a hair inward.
    const bool inside = point_in_polygon(outline, s.nodes[i]);
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < outline.size(); ++k) {
      const Vec2 a = outline[k], b = outline[(k + 1) % outline.size()];
      const double t = std::clamp((s.nodes[i] - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      nearest = std::min(nearest, (a + t * (b - a) - s.nodes[i]).norm());
    }
    EXPECT_TRUE(inside || nearest < 1e-6) << "node " << i << " at " << s.nodes[i].transpose();
  }
  for (int t : s.tips) EXPECT_EQ(child_count(s, t), 0) << "tips are leaves";
}

TEST(StrandSkeleton, TaperedStrandGivesOnePathFromRootToTip) {
  const Polyline outline = tapered_strand({40, 30}, 220, 18, 25);
  Input in;
  in.outline = outline;
  in.root_hint = Vec2(0, 30);
  Options options;
  const Result r = build_skeleton(in, options);
  expect_well_formed(r.skeleton, outline, options.node_spacing);
  EXPECT_EQ(r.status, SkeletonStatus::kTips);
  ASSERT_EQ(r.skeleton.tips.size(), 1u);
  // A single path: every node has at most one child.
  for (std::size_t i = 0; i < r.skeleton.nodes.size(); ++i)
    EXPECT_LE(child_count(r.skeleton, static_cast<int>(i)), 1);
  const Vec2 tip = r.skeleton.nodes[r.skeleton.tips[0]];
  EXPECT_LT((tip - Vec2(260, 30 + 25 * std::sin(0.9 * M_PI))).norm(), 2.0);
  EXPECT_LT(r.skeleton.nodes[0].x(), 50.0) << "root at the wide end near the hint";
  // The path runs the strand's length: about 220 px of curve.
  double length = 0;
  for (std::size_t i = 1; i < r.skeleton.nodes.size(); ++i)
    length += (r.skeleton.nodes[i] - r.skeleton.nodes[r.skeleton.parent[i]]).norm();
  EXPECT_GT(length, 200.0);
  EXPECT_LT(length, 270.0);
}

// A root hint so far away that squared distances overflow still picks the
// end toward it (it crashed: no node was nearer than infinity).
TEST(StrandSkeleton, RootHintFarAwayStillGivesARoot) {
  const Polyline outline = tapered_strand({40, 30}, 220, 18, 25);
  Input in;
  in.outline = outline;
  Options options;
  for (const Vec2& hint : {Vec2(-1e200, 30), Vec2(-1e308, 1e308), Vec2(-1e20, 30)}) {
    in.root_hint = hint;
    const Result r = build_skeleton(in, options);
    expect_well_formed(r.skeleton, outline, options.node_spacing);
    EXPECT_LT(r.skeleton.nodes[0].x(), 50.0) << "hint " << hint.transpose();
  }
}

TEST(StrandSkeleton, ForkedStrandGivesATreeWithTwoTips) {
  const Polyline outline = forked_strand({30, 80});
  Input in;
  in.outline = outline;
  in.root_hint = Vec2(-20, 80);
  Options options;
  const Result r = build_skeleton(in, options);
  expect_well_formed(r.skeleton, outline, options.node_spacing);
  ASSERT_EQ(r.skeleton.tips.size(), 2u);
  int forks = 0;
  for (std::size_t i = 0; i < r.skeleton.nodes.size(); ++i)
    forks += child_count(r.skeleton, static_cast<int>(i)) == 2;
  EXPECT_EQ(forks, 1);
  std::vector<Vec2> tips;
  for (int t : r.skeleton.tips) tips.push_back(r.skeleton.nodes[t]);
  std::sort(tips.begin(), tips.end(), [](const Vec2& a, const Vec2& b) { return a.y() < b.y(); });
  EXPECT_LT((tips[0] - Vec2(190, 20)).norm(), 1.0);
  EXPECT_LT((tips[1] - Vec2(190, 140)).norm(), 1.0);
  EXPECT_LT(r.skeleton.nodes[0].x(), 40.0);
}

TEST(StrandSkeleton, CoveredCornerIsNotATip) {
  const Polyline outline = forked_strand({0, 0});
  Input in;
  in.outline = outline;
  in.root_hint = Vec2(-50, 0);
  in.covered.assign(outline.size(), false);
  in.covered[2] = true;  // the upper arm's tip lies under another strand
  const Result r = build_skeleton(in);
  ASSERT_EQ(r.skeleton.tips.size(), 1u);
  EXPECT_LT((r.skeleton.nodes[r.skeleton.tips[0]] - Vec2(160, 60)).norm(), 1.0);
}

// A fork whose lower arm ends in a rounded tip (radius 8, no corner sharper
// than 80° over 9 px): §6's sharp-corner rule finds only the upper arm's tip
// and the lower arm had no skeleton; as a visible tapering end it is a tip.
TEST(StrandSkeleton, RoundedTipOfAForkIsATip) {
  const Polyline sharp = forked_strand({30, 80});
  const Polyline outline = test::round_corner(sharp, 4, 8.0);
  const Vec2 apex = test::rounded_apex(sharp, 4, 8.0);
  ASSERT_EQ(find_tip_corners(outline, {}).size(), 1u) << "only the upper arm is sharp";
  Input in;
  in.outline = outline;
  in.root_hint = Vec2(-20, 80);
  const Result r = build_skeleton(in);
  expect_well_formed(r.skeleton, outline, Options{}.node_spacing);
  EXPECT_EQ(r.status, SkeletonStatus::kTips);
  EXPECT_EQ(r.rounded_tips, 1);
  ASSERT_EQ(r.skeleton.tips.size(), 2u);
  std::vector<Vec2> tips;
  for (int t : r.skeleton.tips) tips.push_back(r.skeleton.nodes[t]);
  std::sort(tips.begin(), tips.end(), [](const Vec2& a, const Vec2& b) { return a.y() < b.y(); });
  EXPECT_LT((tips[0] - Vec2(190, 20)).norm(), 1.0);
  EXPECT_LT((tips[1] - apex).norm(), 3.0) << "the skeleton reaches the rounded end";
  int forks = 0;
  for (std::size_t i = 0; i < r.skeleton.nodes.size(); ++i)
    forks += child_count(r.skeleton, static_cast<int>(i)) == 2;
  EXPECT_EQ(forks, 1);

  // The paper's rule alone: one tip, the rounded arm left out.
  Options sharp_only;
  sharp_only.find_rounded_tips = false;
  const Result s = build_skeleton(in, sharp_only);
  EXPECT_EQ(s.rounded_tips, 0);
  ASSERT_EQ(s.skeleton.tips.size(), 1u);
  EXPECT_LT((s.skeleton.nodes[s.skeleton.tips[0]] - Vec2(190, 20)).norm(), 1.0);

  // Hidden under another strand, the rounded end is no tip (§6 "locally above").
  in.covered.assign(outline.size(), false);
  for (std::size_t i = 4; i <= 16; ++i) in.covered[i] = true;  // the arc
  const Result hidden = build_skeleton(in);
  EXPECT_EQ(hidden.rounded_tips, 0);
  EXPECT_EQ(hidden.skeleton.tips.size(), 1u);
}

// A strand tapering from 24 to 7 px half-width that ends in a half circle:
// a single path from the root that reaches the rounded end, found as a
// rounded tip.
TEST(StrandSkeleton, RoundedTaperedStrandReachesItsEnd) {
  const Polyline outline = test::rounded_strand({30, 40}, 260, 24, 7, 30);
  // The centre of the end's half circle (the end with no cap).
  const Vec2 cap_centre = test::rounded_strand_end({30, 40}, 260, 0, 30);
  ASSERT_TRUE(find_tip_corners(outline, {}).empty()) << "no sharp corner";
  Input in;
  in.outline = outline;
  in.root_hint = Vec2(0, 40);
  const Result r = build_skeleton(in);
  expect_well_formed(r.skeleton, outline, Options{}.node_spacing);
  EXPECT_EQ(r.status, SkeletonStatus::kTips);
  EXPECT_EQ(r.rounded_tips, 1);
  ASSERT_EQ(r.skeleton.tips.size(), 1u);
  for (std::size_t i = 0; i < r.skeleton.nodes.size(); ++i)
    EXPECT_LE(child_count(r.skeleton, static_cast<int>(i)), 1);
  // The tip is on the cap's outline (one of its samples), not short of it.
  const double from_centre = (r.skeleton.nodes[r.skeleton.tips[0]] - cap_centre).norm();
  EXPECT_GT(from_centre, 6.0);
  EXPECT_LT(from_centre, 7.5);
  EXPECT_GT(r.skeleton.nodes[r.skeleton.tips[0]].x(), cap_centre.x());
  EXPECT_LT(r.skeleton.nodes[0].x(), 50.0);
}

// A bump on the side of a strand next to the root hint: the chordal axis
// has an end there (a short spur), which used to become the root, leaving
// the strand's far end without skeleton (wikipe-tan's right tail lock, where
// a notch in the completed outline did that).
TEST(StrandSkeleton, RootIsAnEndOfTheStrandNotABump) {
  // A 280 x 40 bar, root at x = 0, sharp tip at (340, 20); a bump 6 px high
  // and 10 px wide on its upper side at x = 150, the hint just above it.
  const Polyline outline = {{0, 0},   {145, 0},  {148, -6}, {152, -6}, {155, 0},
                            {280, 0}, {340, 20}, {280, 40}, {0, 40}};
  Input in;
  in.outline = outline;
  in.root_hint = Vec2(150, -40);
  const Result r = build_skeleton(in);
  expect_well_formed(r.skeleton, outline, Options{}.node_spacing);
  ASSERT_EQ(r.skeleton.tips.size(), 1u);
  EXPECT_LT((r.skeleton.nodes[r.skeleton.tips[0]] - Vec2(340, 20)).norm(), 1.0);
  EXPECT_LT(r.skeleton.nodes[0].x(), 10.0) << "root at the far end, not at the bump";
}

TEST(StrandSkeleton, AllTipStrandFallsBackToFarthestEnd) {
  // A thin diamond is "all tip": its sharp corners are covered, nothing else is sharp.
  const Polyline outline = {{10, 50}, {150, 44}, {290, 50}, {150, 56}};
  Input in;
  in.outline = outline;
  in.covered = {true, false, true, false};
  in.root_hint = Vec2(0, 50);
  const Result r = build_skeleton(in);
  EXPECT_EQ(r.status, SkeletonStatus::kFarthestTip);
  expect_well_formed(r.skeleton, outline, Options{}.node_spacing);
  ASSERT_EQ(r.skeleton.tips.size(), 1u);
  EXPECT_GT(r.skeleton.nodes[r.skeleton.tips[0]].x(), 250.0);
}

TEST(StrandSkeleton, PropertiesOverGeneratedStrands) {
  for (int k = 0; k < 12; ++k) {
    const double length = 80 + 30 * k, w0 = 6 + 2 * k, bend = (k % 2 ? -1 : 1) * 5.0 * k;
    const Polyline outline =
        tapered_strand({20.0 + k, 200.0 - 3 * k}, length, w0, bend, 40 + 5 * k);
    Input in;
    in.outline = outline;
    in.root_hint = Vec2(0, 200);
    Options options;
    options.node_spacing = 5 + k % 4;
    const Result r = build_skeleton(in, options);
    SCOPED_TRACE(k);
    expect_well_formed(r.skeleton, outline, options.node_spacing);
    EXPECT_EQ(r.skeleton.tips.size(), 1u);
    // Reversing the outline's orientation gives the same tip.
    Input rev = in;
    std::reverse(rev.outline.begin(), rev.outline.end());
    const Result r2 = build_skeleton(rev, options);
    ASSERT_EQ(r2.skeleton.tips.size(), 1u);
    EXPECT_LT(
        (r.skeleton.nodes[r.skeleton.tips[0]] - r2.skeleton.nodes[r2.skeleton.tips[0]]).norm(),
        1.0);
  }
}

TEST(StrandSkeleton, TipCornersOfAKnownShape) {
  const Polyline outline = forked_strand({0, 0});
  const std::vector<int> tips = find_tip_corners(outline, {});
  ASSERT_EQ(tips.size(), 2u);
  EXPECT_TRUE((tips[0] == 2 && tips[1] == 4) || (tips[0] == 4 && tips[1] == 2));
}

TEST(StrandSkeleton, DegenerateAndTinyShapesDoNotCrash) {
  Input line;
  line.outline = {{0, 0}, {10, 0}, {20, 0}};
  const Result r = build_skeleton(line);
  EXPECT_EQ(r.status, SkeletonStatus::kDegenerate);
  EXPECT_EQ(r.skeleton.nodes.size(), 1u);
  Input pixel;  // a one-pixel region's outline
  pixel.outline = {{5, 5}, {6, 5}, {6, 6}, {5, 6}};
  const Result p = build_skeleton(pixel);
  ASSERT_FALSE(p.skeleton.nodes.empty());
  EXPECT_EQ(p.skeleton.parent[0], -1);
}

TEST(StrandSkeleton, BadInputThrows) {
  Input few;
  few.outline = {{0, 0}, {1, 1}};
  EXPECT_THROW(build_skeleton(few), Error);
  Input dup;
  dup.outline = {{0, 0}, {0, 0}, {3, 3}, {3, 3}};
  EXPECT_THROW(build_skeleton(dup), Error);
  Input nan;
  nan.outline = {{0, 0}, {std::nan(""), 1}, {3, 0}};
  EXPECT_THROW(build_skeleton(nan), Error);
  Input covered;
  covered.outline = forked_strand({0, 0});
  covered.covered = {true};
  EXPECT_THROW(build_skeleton(covered), Error);
  Options bad;
  bad.node_spacing = 0;
  std::string why;
  EXPECT_FALSE(bad.is_valid(&why));
  EXPECT_NE(why.find("node_spacing"), std::string::npos);
  Input ok;
  ok.outline = forked_strand({0, 0});
  EXPECT_THROW(build_skeleton(ok, bad), Error);
  Options bad_angle;
  bad_angle.tip_angle_deg = 190;
  EXPECT_THROW(find_tip_corners(ok.outline, {}, bad_angle), Error);
}

}  // namespace
}  // namespace hair25d::skeleton
