// Private: from traced pixel chains to the curve graph of the drawing: lines
// that stop just short of another line are joined to it, curves are split at
// junctions, chains through plain points are merged, stray bits are pruned.
#pragma once

#include <vector>

#include "curve_tracing.h"
#include "hair25d/core/segmentation.h"

namespace hair25d::segment::detail {

struct GraphOptions {
  double min_curve_length = 8.0;   // isolated curves shorter than this are dropped
  double spur_length = 3.0;        // free-ended side branches shorter than this are dropped
  double gap_length = 6.0;         // free ends are joined across gaps up to this long
  double border_gap_length = 3.0;  // free ends this close to the border are run into it
};

std::vector<Curve> link_curves(const TraceResult& traced, int width, int height,
                               const GraphOptions& options);

}  // namespace hair25d::segment::detail
