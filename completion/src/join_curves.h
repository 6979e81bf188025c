// Case-1 completion curves (paper §5.1, private): two C¹ cubic Béziers from
// the ends of two pieces' cut outlines across the occluder, and the area
// between them. Used for joins across the face, which hides back hair as a
// strand does.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "face_joins.h"

namespace hair25d::completion::detail {

// Direction of a region's outline arriving at contour index `end` from the
// side `step` (−1: the points before it, +1: the points after it), fitted by
// PCA to up to `arm` px of outline a few px away from the end (the last
// pixels bend into the occluder's drawn line), oriented towards `end`, i.e.
// into the hidden part. False when fewer than 4 px of `usable` outline lie
// there (`usable[i]` says contour point i is visible outline; empty: all).
bool outline_tangent(const std::vector<cv::Point>& contour, int end, int step, int arm,
                     const std::vector<char>& usable, Vec2* direction);

// The closed area between two pieces' runs (each from p = front() to
// q = back(), both traversing their region's outline the same way round):
// the cubic p_a → q_b, run b back to p_b, the cubic p_b → q_a, run a back to
// p_a. The cubics leave p along `tangent_p` and arrive at q along
// −`tangent_q` (tangents point into the hidden part), so the outline is C¹
// where they meet the runs' visible continuations.
Polyline bezier_band(const Polyline& run_a, const Vec2& tangent_pa, const Vec2& tangent_qa,
                     const Polyline& run_b, const Vec2& tangent_pb, const Vec2& tangent_qb);

// The completed area of a join across the face: `bezier_band` of the two
// runs, tangents fitted to the pieces' outlines beyond the runs' ends.
Polyline face_join_patch(const Context& ctx, const FaceJoin& join);

}  // namespace hair25d::completion::detail
