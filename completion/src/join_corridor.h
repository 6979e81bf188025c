// Whether some strand, not only the patch of join_patch's two Béziers, may
// run hidden from one piece's cut to the other's (paper §5: the completed
// part lies under the occluders). Private to the case-1 joins.
#pragma once

#include <opencv2/core.hpp>

#include "context.h"

namespace hair25d::completion::detail {

// True when a corridor `width` px wide runs from a's cut to b's through
// pixels under an occluder of a or b (a region above either, the face in
// `face` (CV_8U over the image, may be empty) behind back hair, the drawn
// ink across a cut of ink only when `ink`), within `reach` px of `patch`'s
// box. The pieces themselves are open ground for the distance but no
// corridor runs through them: it leaves a's cut and reaches b's.
bool corridor_under_occluders(const Context& ctx, const Edge& a, const Edge& b,
                              const Polyline& patch, const cv::Mat& face, bool ink, double width,
                              double reach);

}  // namespace hair25d::completion::detail
