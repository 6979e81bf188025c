// Outlines of shapes lying on the hair (private; paper §5.4, the background
// behind the hair): which lines between the hair and a drawn shape are the
// shape's own outline, read from the T-junctions at the ends of their border.
#pragma once

#include <opencv2/core.hpp>

#include "hair25d/core/image.h"

namespace hair25d::completion::detail {

// A closed shape drawn over the hair (wikipe-tan's puzzle-piece clip over her
// twin tail, a shirt over the back hair) shares a line with the hair; the
// outline assignment gives that line to the hair, and with it gone the
// shape's colour flooded the hole. At both ends of the border the shape's
// outline runs on smoothly past the hair while the hair's outline turns away
// from it (the stem of a T-junction): the shape is on top and the line is
// its own. Where the hair lies on top, the hair's outline runs on and the
// shape's turns, and the line stays the hair's.
//
// `image`: the drawing; `drawn`: the hair regions as given (0 on outlines);
// `labels`: the regions with the outline pixels assigned; `dark` (CV_8U,
// image size, non-zero on dark opaque pixels); `head` (CV_8U, image size,
// or empty): the head, where the bangs lie on the face; `face` (CV_8U, image
// size, or empty): find_face's, left to the head's rules. Returns CV_8U, image size:
// 255 on the pixels between such shapes and the hair (their outline, its
// anti-aliased and light inner bands), which belong to the background.
cv::Mat front_outlines(const Image& image, const LabelMap& drawn, const LabelMap& labels,
                       const cv::Mat& dark, const cv::Mat& head, const cv::Mat& face);

}  // namespace hair25d::completion::detail
