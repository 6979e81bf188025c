// Strand joins of pieces whose own outline gives no direction (joins.cpp):
// a nub — a strand's rounded root peeking out from under an occluder — is
// joined by the other piece's tangents.
#include <gtest/gtest.h>

#include "hair25d/completion/completion.h"
#include "synthetic.h"

namespace hair25d::completion {
namespace {

using test::below;
using test::blank;
using test::Drawing;
using test::paint;

constexpr Rgba kBack{120, 90, 70, 255};
constexpr Rgba kStrand{200, 150, 110, 255};

// A vertical strand (x 100..140) over a wide lowest region 4, its rounded
// root (half an ellipse `top` px tall, ending at y 140) peeking out above a
// band 3 (y 118..162) lying over it as the nub 1; below the band the long
// piece 2 (y 140..230). `lower_dx` shifts the lower piece sideways.
Drawing nub_over_band(double top, double lower_dx = 0.0) {
  Drawing d = blank(250, 300);
  paint(
      d, [](double x, double y) { return x > 20 && x < 230 && y > 20 && y < 280; }, kBack, 4);
  paint(
      d,
      [top](double x, double y) {
        const double u = (x - 120) / 20, v = (y - 140) / top;
        return y < 140 && u * u + v * v < 1;
      },
      kStrand, 1);
  paint(
      d,
      [lower_dx](double x, double y) {
        return x > 100 + lower_dx && x < 140 + lower_dx && y >= 140 && y < 230;
      },
      kStrand, 2);
  paint(
      d, [](double x, double y) { return x > 40 && x < 210 && y > 118 && y < 162; }, kStrand, 3);
  d.relations = {below(4, 1), below(4, 2), below(4, 3), below(1, 3), below(2, 3)};
  return d;
}

std::vector<int> joined_with_1(const Drawing& d) {
  Options o;
  o.inpaint_background = false;
  o.face_joins = false;
  o.path_joins = false;
  return test::regions_with(complete_strands(test::input_of(d, Vec2(125, 10)), o), 1);
}

TEST(StrandJoins, NubIsJoinedByTheOtherPiecesTangents) {
  // The nub shows 12-15 px of its root above the band, ~28 px wide: its
  // outline beside the cut turns round the root, so its tangents lie over
  // 70° off the join and it made no strand join. The lower piece points
  // straight at its cut. A lower piece 40 px to the right, whose tangents lie
  // ~42° off the chords to the nub's cut (more than the 30° a one-sided join
  // allows), stays apart.
  for (double top : {30.0, 33.0}) {
    EXPECT_EQ(joined_with_1(nub_over_band(top)), (std::vector<int>{1, 2})) << top;
    EXPECT_EQ(joined_with_1(nub_over_band(top, 40)), (std::vector<int>{1})) << top;
  }
}

}  // namespace
}  // namespace hair25d::completion
