// Two pieces of a strand running down for the join-shape and corridor
// tests: piece 1's cut along y 60 (x 40..70) and piece 2's along y 120
// (x `b_left`..`b_left` + 30), outlines running the same way round both
// (p to q), every tangent straight into the gap, each cut 30 px wide.
#pragma once

#include "context.h"

namespace hair25d::completion::detail {

struct FacingCuts {
  Edge a, b;
};

inline FacingCuts facing_cuts(int b_left) {
  FacingCuts c;
  c.a.region = 1;
  c.a.p = Vec2(40, 60), c.a.q = Vec2(70, 60);
  c.a.tangent_p = c.a.tangent_q = Vec2(0, 1);
  c.b.region = 2;
  c.b.p = Vec2(b_left + 30, 120), c.b.q = Vec2(b_left, 120);
  c.b.tangent_p = c.b.tangent_q = Vec2(0, -1);
  for (int x = 40; x <= 70; ++x) c.a.points.push_back(Vec2(x, 60));
  for (int x = b_left + 30; x >= b_left; --x) c.b.points.push_back(Vec2(x, 120));
  c.a.width = c.b.width = 30;
  return c;
}

}  // namespace hair25d::completion::detail
