// The head centre a user gives (strokes.json head_center, --head): it tells
// occluded roots from occluded tips (paper §5.2-5.3).
#pragma once

#include <string>

#include "hair25d/core/geometry.h"

namespace hair25d::pipeline {

// How far outside the drawing the head centre may lie, in drawing sizes: a
// head cropped off the top is fine, a value thousands of drawings away is a
// typo (and overflows the distances measured to it).
inline constexpr double kHeadReach = 10.0;

// Throws hair25d::Error naming `what` (e.g. "--head") and the value when the
// centre is not finite or lies more than kHeadReach drawing widths (heights)
// beyond the drawing's left or right (top or bottom) edge.
void check_head_center(const Vec2& head, int width, int height, const std::string& what);

}  // namespace hair25d::pipeline
