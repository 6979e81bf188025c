// A drawn line seen in colour where the grey levels miss it (paper §4.1, an
// addition): a black outline on very dark paint has almost the paint's grey
// level, yet it is plainly a line, because its colour lies off the paints'.
#pragma once

#include "hair25d/core/geometry.h"
#include "hair25d/core/image.h"
#include "line_response.h"

namespace hair25d::layering::detail {

// Along `curve` (pixel corners, `skip` pixels left out at each end, one
// sample per pixel, every other one on boundaries over 40 px, as
// LineResponse::measure samples), per sample: the largest distance, over the
// line's cross-section (half a line width + 1 px each side), from the
// image's colour there to the segment between the two sides' paper colours,
// Euclidean RGB / √3. Paper on a side is, as for the grey contrast, the
// colour of the brightest point (grey level) within 3 line widths + 2 px
// along the normal that lies in that side's region of `labels` (`left` /
// `right`). Colours are read bilinearly, translucent pixels over white. A
// line of any colour answers; a mix of the two paints (anti-aliasing, a
// tone step, JPEG's chroma) lies on the segment and does not. Median
// (contrast) and lower quartile (contrast_low) over the samples;
// colour_difference is left 0. Samples without paper on both sides are
// left out; none at all gives 0.
BoundaryLine colour_line(const Image& image, double line_width, const Polyline& curve, double skip,
                         const LabelMap& labels, int left, int right);

}  // namespace hair25d::layering::detail
