// Options::remote_across_occluder (session 33, joins77): a weak order the
// layering measured between two pieces of one paint that do not touch, both
// lying under a region that touches them, makes no occluder.
#include <gtest/gtest.h>

#include "hair25d/completion/completion.h"
#include "synthetic.h"

namespace hair25d::completion {
namespace {

using namespace test;

// Back hair (pieces 1 and 2, the right one painted `right`) under one wide
// strand 3, farther across than a cut edge's bank rays reach, so that only
// the region-level joins for back hair can join them; `extra` relations
// besides 1 and 2 under 3.
Drawing back_under_wide_strand(Rgba right, const std::vector<RegionRelation>& extra) {
  Drawing d = blank(340, 200);
  paint(
      d, [](double x, double y) { return x > 20 && x < 120 && y > 60 && y < 130; }, kBack, 1);
  paint(
      d, [](double x, double y) { return x > 195 && x < 320 && y > 66 && y < 128; }, right, 2);
  paint(
      d, [](double x, double y) { return x > 112 && x < 205 && y > 10 && y < 190; }, kFan, 3);
  d.relations = {below(1, 3), below(2, 3)};
  d.relations.insert(d.relations.end(), extra.begin(), extra.end());
  return d;
}

// The regions in piece 1's strand when only the region-level joins can
// join (run_region_joins's options), with the rule on or off.
std::vector<int> strand_of_1(const Drawing& d, bool rule) {
  Options o;
  o.max_join_angle_deg = 0.5;
  o.min_width_ratio = 0.99;
  o.inpaint_background = false;
  o.face_joins = false;
  o.remote_across_occluder = rule;
  return regions_with(complete_strands(input_of(d, Vec2(170, 20)), o), 1);
}

TEST(RemoteAcrossOccluder, WeakOrderBetweenBackPiecesUnderOneStrandMakesNoOccluder) {
  const std::vector<int> joined{1, 2}, apart{1};
  // No order between the pieces: both back hair, joined across the strand.
  EXPECT_EQ(strand_of_1(back_under_wide_strand(kBack, {}), false), joined);
  // A weak order 1 above 2 across the strand makes piece 1 front hair: the
  // back-hair passes leave it, unless the rule reads no occluder from it.
  const RegionRelation weak{1, 2, Relation::kAbove, 0.8};
  EXPECT_EQ(strand_of_1(back_under_wide_strand(kBack, {weak}), false), apart);
  EXPECT_EQ(strand_of_1(back_under_wide_strand(kBack, {weak}), true), joined);
  // A firm order, or pieces of two paints, keep the occluder.
  const RegionRelation firm{1, 2, Relation::kAbove, 3.0};
  EXPECT_EQ(strand_of_1(back_under_wide_strand(kBack, {firm}), true), apart);
  EXPECT_EQ(strand_of_1(back_under_wide_strand(Rgba{120, 160, 220, 255}, {weak}), true), apart);
}

}  // namespace
}  // namespace hair25d::completion
