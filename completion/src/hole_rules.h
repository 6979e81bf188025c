// Rules of what the background takes for hair (private; background_hole.cpp,
// paper §5.4): the colours the hair and the head are drawn in, and the dark
// pieces beside the hair that go with it or stay. All rasters are CV_8U, the
// drawing's size, non-zero where set.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "context.h"
#include "head_fill.h"
#include "inpaint_internal.h"

namespace hair25d::completion::detail {

// Pixels less opaque than this are the sheet (or its anti-aliased rim), not
// a dark colour of the drawing.
constexpr int kOpaque = 128;

// The colour of the head's outline round the hole `holes` (`head`: the
// head's mask; `regions`: the hair regions as given).
Rgba head_line_colour(const Image& image, const LabelMap& regions, const cv::Mat& holes,
                      const cv::Mat& head, const Options& o);

// The colours the hair regions are painted in.
CommonColours hair_colours(const Context& ctx);

// Adds to `holes` the small pieces of the drawing it encloses.
void take_islands(cv::Mat& holes);

// The pixels on the head of the pieces of `dark` that hold a pixel not `own`
// more than `reach` px from `hair`.
cv::Mat face_lines(const cv::Mat& dark, const cv::Mat& own, const cv::Mat& hair,
                   const cv::Mat& head, int reach);

// Dark pixels hanging along the hair off the head, within `near`.
cv::Mat hanging_spurs(const cv::Mat& dark, const cv::Mat& own, const cv::Mat& near,
                      const cv::Mat& head);

// The points of locks lying over thin face lines of their own colour.
cv::Mat points_over_lines(const cv::Mat& own, const cv::Mat& hair, const cv::Mat& near,
                          const cv::Mat& features, const cv::Mat& pieces,
                          const std::vector<std::uint8_t>& mixed, const cv::Mat& fill_coloured,
                          const cv::Mat& line);

// Shaded slivers of skin between the bangs' points on the forehead.
cv::Mat shaded_slivers(const Image& image, const cv::Mat& holes, const cv::Mat& dark,
                       const Head& head);

}  // namespace hair25d::completion::detail
