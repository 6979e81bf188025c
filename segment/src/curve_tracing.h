// Private: linking centre-line pixels into curves along the line direction
// (curve extraction after Cheng 2009): hysteresis, one-pixel gap bridging,
// and where a traced line runs into another one.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "hair25d/core/geometry.h"
#include "line_response.h"

namespace hair25d::segment::detail {

struct TracedCurve {
  std::vector<int> pixels;  // pixel indices y * width + x, in order along the curve
  Polyline points;          // sub-pixel centre-line points, one per pixel
  bool closed = false;
};

// End `end` (0 = first point, 1 = last) of curve `curve` ran into the pixel
// `target` that belongs to another curve (or to a distant part of its own).
struct Attachment {
  int curve = 0;
  int end = 0;
  int target = 0;
};

struct TraceResult {
  std::vector<TracedCurve> curves;
  std::vector<Attachment> attachments;
  std::vector<int> owner;        // per pixel: curve id or -1
  std::vector<int> owner_point;  // per pixel: index of the nearest point of that curve
};

// Traces curves through `ridge` (CV_8U centre-line pixels) starting from the
// strongest pixels above `high_threshold`.
TraceResult trace_curves(const LineField& field, const cv::Mat& ridge, float high_threshold);

}  // namespace hair25d::segment::detail
