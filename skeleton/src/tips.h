// Tip corners on a uniformly sampled closed outline (paper §6: "sharp corners
// ... locally above the neighbouring regions").
#pragma once

#include <vector>

#include "hair25d/core/geometry.h"
#include "hair25d/skeleton/strand_skeleton.h"

namespace hair25d::skeleton::detail {

// Indices of sharp convex corners of `samples`, sharpest first, at least
// `separation` pixels apart along the outline; `covered` (#samples or empty)
// removes hidden corners.
std::vector<int> sharp_corners(const Polyline& samples, const std::vector<bool>& covered,
                               const Options& options);

// Whether a covered sample lies within `reach` pixels of sample i along the
// closed outline (either way): the corner at i then touches an occluder.
bool near_covered(const Polyline& samples, const std::vector<bool>& covered, int i, double reach);

}  // namespace hair25d::skeleton::detail
