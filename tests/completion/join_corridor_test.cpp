// The corridor under the occluders (completion/src/join_corridor.h,
// Options::corridor_width): a strand of some shape, not only the patch's,
// may run hidden from one piece's cut to the other's.
#include "join_corridor.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "facing_cuts.h"
#include "join_shapes.h"

namespace hair25d::completion::detail {
namespace {

constexpr int kWidth = 160, kHeight = 200;  // never square

// Piece 1 (x 40..70, y 20..60) and piece 2 (the same columns, y 120..170)
// of a strand running down under band 3 (y 60..120, the whole width). A
// wall of paper crosses the band at y 85..95 but for a gap `gap` px wide
// centred on x `centre`; with `related` false the band lies over neither
// piece (the relations say nothing of it).
struct Case {
  Context ctx;
  Edge a, b;
};

Case make_case(int gap, int centre, bool related = true) {
  Case c;
  const FacingCuts cuts = facing_cuts(40);
  c.a = cuts.a, c.b = cuts.b;
  c.ctx.labels = LabelMap(kWidth, kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      int& l = c.ctx.labels.at(x, y);
      if (x >= 40 && x < 70 && y >= 20 && y < 60)
        l = 1;
      else if (x >= 40 && x < 70 && y >= 120 && y < 170)
        l = 2;
      else if (y >= 60 && y < 120 && !(y >= 85 && y < 95 && std::abs(x - centre) * 2 >= gap))
        l = 3;
    }
  if (related) {
    c.ctx.above[1] = {3};
    c.ctx.above[2] = {3};
  }
  return c;
}

bool corridor(const Case& c, double width) {
  return corridor_under_occluders(c.ctx, c.a, c.b, join_patch(c.a, c.b), cv::Mat(), false, width,
                                  30.0);
}

TEST(JoinCorridor, RunsThroughAGapAsWideAsTheCorridor) {
  // Half the 30 px cut: 15 px.
  EXPECT_TRUE(corridor(make_case(20, 55), 15));
  EXPECT_TRUE(corridor(make_case(40, 55), 15));
  EXPECT_FALSE(corridor(make_case(10, 55), 15));
  EXPECT_FALSE(corridor(make_case(0, 55), 15));
  // A narrower strand passes the 10 px gap.
  EXPECT_TRUE(corridor(make_case(10, 55), 6));
}

TEST(JoinCorridor, MayLeaveThePatchWithinReach) {
  // The gap lies beside the pieces (x 80..100), off the straight patch but
  // within its box's reach of 30 px.
  EXPECT_TRUE(corridor(make_case(20, 90), 15));
  // Beyond the reach (x 125..145 is 55 px off the patch's box).
  EXPECT_FALSE(corridor(make_case(20, 135), 15));
}

TEST(JoinCorridor, OnlyUnderOccludersOfThePieces) {
  EXPECT_FALSE(corridor(make_case(40, 55, false), 15));
}

TEST(JoinCorridor, BadInputIsNoCorridor) {
  Case c = make_case(40, 55);
  EXPECT_FALSE(corridor(c, 0));
  EXPECT_FALSE(corridor_under_occluders(c.ctx, c.a, c.b, Polyline{}, cv::Mat(), false, 15, 30));
  const Polyline patch = join_patch(c.a, c.b);
  c.b.points.clear();  // no cut to reach
  EXPECT_FALSE(corridor_under_occluders(c.ctx, c.a, c.b, patch, cv::Mat(), false, 15, 30));
}

}  // namespace
}  // namespace hair25d::completion::detail
