// A picture of a layering result (paper §4, Fig. 1c): regions tinted, boundaries
// coloured by kind, and one arrow per related pair pointing from the occludee
// to the occluder ("=" for equal); pairs named as wrong are ringed in red.
#pragma once

#include <utility>
#include <vector>

#include "hair25d/core/image.h"
#include "hair25d/layering/layering.h"

namespace hair25d::layering {

// Draws over a copy of `image` (same size as the result's labels, else
// hair25d::Error). `wrong` lists (a, b) pairs, in either order, to mark: a
// red ring on the relation, or a red "?" where the two regions come closest
// when the result does not relate them at all.
Image render_overlay(const Image& image, const Result& result,
                     const std::vector<std::pair<int, int>>& wrong = {});

}  // namespace hair25d::layering
