// Tips of the strands' skeletons (§6): sharp corners lying above their
// neighbours. A strand merely lying alongside a tip leaves it a tip; a
// corner under a strand drawn above is none.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

#include "completion/synthetic.h"
#include "hair25d/core/error.h"
#include "hair25d/pipeline/model_stage.h"

namespace hair25d::pipeline {
namespace {

constexpr int kW = 220, kH = 190;
constexpr Rgba kSheet{245, 245, 240, 255};

struct Triangle {
  Vec2 a, b, c;
  bool contains(double x, double y) const {
    const auto side = [&](const Vec2& p, const Vec2& q) {
      return (q.x() - p.x()) * (y - p.y()) - (q.y() - p.y()) * (x - p.x());
    };
    const double s1 = side(a, b), s2 = side(b, c), s3 = side(c, a);
    return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
  }
};

// The strand holding `region`.
const Strand& strand_of(const ModelRun& run, int region, std::size_t* index) {
  for (std::size_t i = 0; i < run.model.strands.size(); ++i)
    for (int r : run.model.strands[i].regions)
      if (r == region) {
        *index = i;
        return run.model.strands[i];
      }
  throw Error("no strand holds region " + std::to_string(region));
}

// The distance from `p` to the nearest skeleton tip node of `s`.
double nearest_tip(const Strand& s, const Vec2& p) {
  double best = 1e18;
  for (int t : s.skeleton.tips) best = std::min(best, (s.skeleton.nodes[t] - p).norm());
  return best;
}

// Two flat locks hanging side by side from the top edge, 1 px apart; the right
// one (region 2, drawn above the left, region 1) runs straight down 25 px
// past the left one's point, which lies alongside it. Both points are tips:
// before, the front lock's pixels within 3 px of the left lock's point hid
// it and its skeleton ran to the farthest end instead.
TEST(SkeletonTips, LockBesideAFrontLockKeepsItsTip) {
  completion::test::Drawing d{Image(kW, kH, kSheet), LabelMap(kW, kH, 0), {}};
  const Triangle left{{40, 0}, {86, 0}, {86, 150}};
  const Triangle right{{87, 0}, {134, 0}, {87, 175}};
  completion::test::paint(
      d, [&](double x, double y) { return left.contains(x, y); }, Rgba{120, 80, 50, 255}, 1, 0);
  completion::test::paint(
      d, [&](double x, double y) { return right.contains(x, y); }, Rgba{150, 100, 60, 255}, 2, 0);
  const std::vector<RegionRelation> relations = {{1, 2, Relation::kBelow, 1.0}};
  const std::map<int, int> depth = {{1, 0}, {2, 1}};
  const ModelRun run = build_model(d.image, d.regions, relations, depth, Vec2(88, -40));
  ASSERT_EQ(run.model.strands.size(), 2u);
  std::size_t li = 0, ri = 0;
  const Strand& l = strand_of(run, 1, &li);
  const Strand& r = strand_of(run, 2, &ri);
  ASSERT_LT(l.depth, r.depth);
  EXPECT_EQ(run.strands[li].skeleton, skeleton::SkeletonStatus::kTips);
  EXPECT_EQ(run.strands[ri].skeleton, skeleton::SkeletonStatus::kTips);
  EXPECT_LT(nearest_tip(l, Vec2(85.5, 147)), 16.0);
  EXPECT_LT(nearest_tip(r, Vec2(87.5, 172)), 16.0);
}

// A lock whose point lies under a band drawn above it (region 2 across rows
// 110-170): its corners under the band are no tips, so no tip lies there.
TEST(SkeletonTips, PointUnderAFrontStrandIsNoTip) {
  completion::test::Drawing d{Image(kW, kH, kSheet), LabelMap(kW, kH, 0), {}};
  const Triangle lock{{50, 0}, {110, 0}, {80, 160}};
  completion::test::paint(
      d, [&](double x, double y) { return lock.contains(x, y); }, Rgba{120, 80, 50, 255}, 1);
  completion::test::paint(
      d, [](double x, double y) { return x > 20 && x < 160 && y > 110 && y < 175; },
      Rgba{90, 140, 190, 255}, 2);
  const std::vector<RegionRelation> relations = {{1, 2, Relation::kBelow, 1.0}};
  const std::map<int, int> depth = {{1, 0}, {2, 1}};
  const ModelRun run = build_model(d.image, d.regions, relations, depth, Vec2(80, -40));
  std::size_t li = 0;
  const Strand& l = strand_of(run, 1, &li);
  if (run.strands[li].skeleton == skeleton::SkeletonStatus::kTips) {
    for (int t : l.skeleton.tips)
      EXPECT_LT(l.skeleton.nodes[t].y(), 105.0) << "a tip under the band";
  }
}

}  // namespace
}  // namespace hair25d::pipeline
