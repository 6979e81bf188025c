// Signs that the "hair" a user marked is not hair: a region that covers most
// of the drawing or reaches all four of its sides is almost always the paper
// (a --hair-colour near the paper's colour, strokes on a blank image).
#pragma once

#include <string>
#include <vector>

#include "hair25d/core/image.h"

namespace hair25d::pipeline {

// A region covering more than this share of the drawing is called out.
inline constexpr double kMostOfTheDrawing = 0.5;

// One warning per hair region (label > 0) that covers more than
// kMostOfTheDrawing of the drawing or touches all four of its sides, naming
// the region, its share and the sides; `source` says where the regions came
// from (e.g. "--hair-colour #d8d8dc"). Empty when nothing looks wrong. The
// model is still built: a close-up may be all hair.
std::vector<std::string> hair_region_warnings(const LabelMap& regions, const std::string& source);

}  // namespace hair25d::pipeline
