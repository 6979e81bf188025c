// A picture to check a segmentation at a glance (paper §3, Fig. 2): regions
// tinted by label over the drawing, the mesh in thin lines, curves in red,
// endpoints and junctions as dots.
#pragma once

#include "hair25d/core/image.h"
#include "hair25d/core/segmentation.h"

namespace hair25d::segment {

// A colour for a region id: distinct hues for neighbouring ids, grey for 0.
Rgba label_colour(int id);

// The overlay, same size as `image`. `regions` is the per-pixel label map of
// the segmentation (same size). Throws hair25d::Error if sizes differ.
Image draw_overlay(const Image& image, const Segmentation& segmentation, const LabelMap& regions);

}  // namespace hair25d::segment
