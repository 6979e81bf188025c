// Ground truth read off the owner map: visible hair regions (connected pieces of
// one strand's fill between lines), the pairs of regions that meet across a line
// with their depth relation, and strokes placed well inside every region.
#pragma once

#include <opencv2/core.hpp>

#include "hair25d/core/annotation.h"
#include "scene.h"

namespace hair25d::generator {

struct GroundTruth {
  LabelMap regions;  // region ids 1..n, 0 elsewhere
  std::vector<AnnotatedRegion> region_list;
  std::vector<AnnotatedPair> pairs;
  Strokes strokes;
};

// `owner` as made by render_owner(scene). Pieces too thin to hold a width-3
// stroke away from their outline are not regions (left 0, like a line).
GroundTruth make_ground_truth(const Scene& scene, const cv::Mat& owner);

}  // namespace hair25d::generator
