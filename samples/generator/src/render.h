// Rasterises a Scene twice from the same polygons: the anti-aliased picture
// (drawn at a multiple of the size, then area-averaged) and the owner map that
// the ground truth is read from (which shape's fill or which line each pixel
// centre shows).
#pragma once

#include <opencv2/core.hpp>

#include "hair25d/core/image.h"
#include "scene.h"

namespace hair25d::generator {

inline constexpr int kLineOwner = -1;

// RGB, 8 bits a channel, scene.width × scene.height.
cv::Mat render_picture(const Scene& scene, int supersample);

// CV_32S: 0 background, k the fill of scene.shapes[k - 1], kLineOwner where an
// outline or inner line covers the pixel centre.
cv::Mat render_owner(const Scene& scene);

// The whole shape, hidden parts included: 1 inside, 0 outside.
LabelMap shape_mask(const Scene& scene, const Shape& shape);

}  // namespace hair25d::generator
