// A drawn line seen in colour where the grey levels miss it (paper §4.1, an
// addition): a black outline on very dark paint has almost the paint's grey
// level, yet it is plainly a line, because its colour lies off the paints'.
#pragma once

#include "hair25d/core/geometry.h"
#include "hair25d/core/image.h"
#include "line_response.h"

namespace hair25d::layering::detail {

// Paper at or under this grey level (a quarter of the range) is dark paint:
// black ink on it shows little in grey however plain it is (colour_line,
// and the per-boundary line threshold of layer_regions).
inline constexpr double kDarkPaper = 64.0;

// Along `curve` (pixel corners, `skip` pixels left out at each end, one
// sample per pixel, every other one on boundaries over 40 px, as
// LineResponse::measure samples), per sample: paper on each side is, as for
// the grey contrast, the colour of the brightest point (grey level) within
// 3 line widths + 2 px along the normal that lies in that side's region of
// `labels` (`left` / `right`); over the line's cross-section (half a line
// width + 1 px each side) the grey contrast of each side (its paper − the
// darkest point) and the largest distance from the image's colour to the
// segment between the two papers' colours (Euclidean RGB / √3: a line of
// any colour lies off it; a mix of the two paints — anti-aliasing, a tone
// step, JPEG's chroma — lies on it). The sample's value is the lower side's
// grey contrast lifted by that colour distance, at most up to the higher
// side's: ink is as visible against paint as dark as it as, in grey, against
// the other paint, never more; where both papers are dark (grey level 64
// or less: black hair, often one paint on both sides, so neither side sees
// the line in grey) the cap is instead the brighter paper's grey level, the
// most any ink could show in grey there, and each side's paper is the
// first point beyond the line's cross-section (grey ink on black paint may
// be brighter than the paint: the brightest point is then the line's rim
// or a thin strand's other outline). Colours
// are read bilinearly (paper: the pixel whose label is read), translucent
// pixels over white. Median (contrast) and lower quartile (contrast_low) of the values, but only
// where the median lifted value is at least twice the median lower-side grey contrast — the colour
// sees a line the grey levels miss; otherwise, and without samples with paper on both sides, 0.
// colour_difference is 0.
BoundaryLine colour_line(const Image& image, double line_width, const Polyline& curve, double skip,
                         const LabelMap& labels, int left, int right);

}  // namespace hair25d::layering::detail
