// The hidden part of a case-1 strand join (paper §5.1: two C¹ Bézier curves
// from the cuts' ends, the completed part under the occluders) and, where
// Options::join_arm_shares asks, other smooth shapes of it: the same two
// curves with tangent arms of other lengths (private).
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "context.h"

namespace hair25d::completion::detail {

// The completed area between two pieces: Bézier p_a → q_b, b's edge back to
// p_b, Bézier p_b → q_a, a's edge back to p_a; the handles at a's cut are
// `share_a` of their chord long, those at b's `share_b` (join_bezier's are
// a third).
Polyline join_patch(const Edge& a, const Edge& b, double share_a = 1.0 / 3.0,
                    double share_b = 1.0 / 3.0);

struct JoinShape {
  double share_a = 1.0 / 3.0, share_b = 1.0 / 3.0;  // arms at a's and b's cuts
  double cover = -1.0;  // share of the patch under the occluders; -1: none measured
};

// Of the patches with arms (share_a, share_b) from `shares` × `shares`, the
// one lying most under the occluders of a or b, by match_edges' coverage
// rule: a pixel outside both pieces is under when a region above a or b
// holds it, the face (`face`, CV_8U over the image, may be empty) behind
// back hair, or drawn ink across a cut of ink only (`ink`). The first of
// equals wins. A cover map of the patches' box is made once and each shape
// only filled over it (several shapes cost little more than one).
// `known`, when given, is a shape of `shares` whose cover was measured
// already (match_edges' patch of a third's arms, by `coverage`): it is not
// measured again.
JoinShape best_join_shape(const Context& ctx, const Edge& a, const Edge& b, const cv::Mat& face,
                          bool ink, const std::vector<double>& shares,
                          const std::optional<JoinShape>& known = std::nullopt);

}  // namespace hair25d::completion::detail
