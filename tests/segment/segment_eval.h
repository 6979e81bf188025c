// Test helpers: region IoU against an annotated regions.png, with the drawn
// outlines left out (they belong to no region in the annotation).
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "hair25d/core/image.h"

namespace hair25d::segment::testing {

// 1 where the annotation is 0 and a region pixel lies within `line_width`
// (Euclidean, pixel centres): the outline pixels no one can be blamed for.
inline LabelMap outline_exclusion(const LabelMap& truth, double line_width) {
  const int W = truth.width(), H = truth.height();
  const int r = static_cast<int>(std::ceil(line_width));
  constexpr int kFar = 1 << 20;
  // Horizontal distance to the nearest region pixel in each row, then the
  // vertical window: exact Euclidean within the radius.
  std::vector<int> row_dist(static_cast<std::size_t>(W) * H, kFar);
  for (int y = 0; y < H; ++y) {
    int last = -kFar;
    for (int x = 0; x < W; ++x) {
      if (truth.at(x, y) > 0) last = x;
      row_dist[static_cast<std::size_t>(y) * W + x] = x - last;
    }
    last = 2 * kFar;
    for (int x = W - 1; x >= 0; --x) {
      if (truth.at(x, y) > 0) last = x;
      auto& d = row_dist[static_cast<std::size_t>(y) * W + x];
      d = std::min(d, last - x);
    }
  }
  LabelMap out(W, H, 0);
  const double r2 = line_width * line_width;
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      if (truth.at(x, y) != 0) continue;
      for (int dy = -r; dy <= r; ++dy) {
        const int yy = y + dy;
        if (yy < 0 || yy >= H) continue;
        const double dx = row_dist[static_cast<std::size_t>(yy) * W + x];
        if (dx * dx + dy * dy <= r2) {
          out.at(x, y) = 1;
          break;
        }
      }
    }
  }
  return out;
}

struct RegionScore {
  int label = 0;
  double iou = 0.0;
  long truth_pixels = 0;
};

// IoU of every label > 0 of the annotation, over pixels not excluded.
inline std::vector<RegionScore> region_ious(const LabelMap& truth, const LabelMap& predicted,
                                            const LabelMap& excluded) {
  std::map<int, long> inter, in_truth, in_pred;
  for (int y = 0; y < truth.height(); ++y) {
    for (int x = 0; x < truth.width(); ++x) {
      if (excluded.at(x, y)) continue;
      const int t = truth.at(x, y), p = predicted.at(x, y);
      if (t > 0) ++in_truth[t];
      if (p > 0) ++in_pred[p];
      if (t > 0 && t == p) ++inter[t];
    }
  }
  std::vector<RegionScore> out;
  for (const int label : truth.labels()) {
    const long i = inter[label], u = in_truth[label] + in_pred[label] - i;
    out.push_back({label, u > 0 ? double(i) / double(u) : 1.0, in_truth[label]});
  }
  return out;
}

inline double mean_iou(const std::vector<RegionScore>& scores) {
  if (scores.empty()) return 1.0;
  double s = 0.0;
  for (const auto& r : scores) s += r.iou;
  return s / static_cast<double>(scores.size());
}

}  // namespace hair25d::segment::testing
