// Private: the Hessian line response of a drawing at several scales (the first
// step of the curve extraction after Cheng 2009) and its non-maximum suppression.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "hair25d/core/image.h"

namespace hair25d::segment::detail {

struct LineField {
  cv::Mat response;  // CV_32F: line strength in grey levels, 0 where no dark line
  cv::Mat nx, ny;    // CV_32F: unit normal across the line
  cv::Mat offset;    // CV_32F: sub-pixel position of the centre along the normal, in [-0.5, 0.5]
  cv::Mat sigma;     // CV_32F: the scale that answered best
};

// Grey levels 0-255 of ink: half luminance, half the brightest channel (a
// black line on a dark but saturated fill stands out), transparent pixels
// composited over white.
cv::Mat grey_image(const Image& image);

// Replaces isolated dark specks no larger than max_size × max_size pixels and
// at least `contrast` grey levels darker than their surroundings (screentone
// dots, dirt) by the surrounding tone from `closed` (a morphological closing
// of grey wider than max_size), in place.
void remove_dots(cv::Mat& grey, const cv::Mat& closed, int max_size, float contrast);

// Strength of dark lines at the best of `scales`: the scale-normalised largest
// Hessian eigenvalue less blob_weight × the second eigenvalue (dots, screentone,
// give none), gated at each scale by how much darker the centre is than both
// sides (the edge between two flat tones, cel shading, gives no line). The
// best scale is the best after the gate: beside light paper a coarse scale
// sees a step where a finer one still sees the line (dark hair's outline).
LineField compute_line_field(const cv::Mat& grey, const std::vector<double>& scales,
                             float low_threshold, float blob_weight);

// CV_8U 1 where the response is above `low_threshold` and not smaller than
// its two neighbours across the line.
cv::Mat suppress_non_maxima(const LineField& field, float low_threshold);

}  // namespace hair25d::segment::detail
