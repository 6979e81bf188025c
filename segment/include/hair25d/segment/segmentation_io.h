// segmentation.json ("hair25d-segmentation/1"): the curves with their end
// kinds, the mesh with curve-edge flags, a region per triangle and the region
// adjacency (paper §3 output), so later stages and the studio can reload it.
#pragma once

#include <filesystem>
#include <string>

#include "hair25d/core/segmentation.h"

namespace hair25d::segment {

std::string segmentation_to_json(const Segmentation& segmentation);
// Strict: throws hair25d::Error naming `source`, the key and what was expected;
// the mesh is validated and the region list must have one entry per triangle.
Segmentation segmentation_from_json(const std::string& text, const std::string& source);

void write_segmentation(const std::filesystem::path& path, const Segmentation& segmentation);
Segmentation read_segmentation(const std::filesystem::path& path);

}  // namespace hair25d::segment
