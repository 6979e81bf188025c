// Cubic Bézier curves for joining the pieces of an occluded strand (paper §5.1:
// "two Bézier curves with C¹ continuity") and for sharp tips (§5.3).
#pragma once

#include <array>

#include "hair25d/core/geometry.h"

namespace hair25d::completion {

struct CubicBezier {
  std::array<Vec2, 4> control;  // pixels: start, two handles, end

  Vec2 point(double t) const;       // t in [0, 1]
  Vec2 derivative(double t) const;  // d point / dt
  // `segments` + 1 points from start to end, evenly spaced in t.
  Polyline sample(int segments) const;
};

// The cubic from `start` to `end` that leaves `start` along `start_tangent`
// and arrives at `end` moving along `end_tangent` (unit vectors; the curve's
// derivative at each end is parallel to them, so it continues C¹ the curves it
// joins). Handles are a third of the chord long, scaled by `handle_scale`.
CubicBezier join_bezier(const Vec2& start, const Vec2& start_tangent, const Vec2& end,
                        const Vec2& end_tangent, double handle_scale = 1.0);

// The same cubic with handles of their own lengths: `start_share` and
// `end_share` of the chord (join_bezier's are a third each). Another guess
// at the hidden shape of the strand, C¹ with the curves it joins as well.
CubicBezier join_bezier_arms(const Vec2& start, const Vec2& start_tangent, const Vec2& end,
                             const Vec2& end_tangent, double start_share, double end_share);

}  // namespace hair25d::completion
