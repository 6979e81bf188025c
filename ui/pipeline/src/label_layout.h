// Label placement for the eval-layering overlay (eval_overlay.cpp): each label
// goes to the nearest free spot round its mark, so that labels stay readable
// where many regions meet. Private to the pipeline; tested on its own.
#pragma once

#include <algorithm>
#include <vector>

#include "hair25d/core/geometry.h"

namespace hair25d::pipeline::detail {

struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double overlap(const Box& o) const {
    const double w = std::min(x1, o.x1) - std::max(x0, o.x0);
    const double h = std::min(y1, o.y1) - std::max(y0, o.y0);
    return w > 0 && h > 0 ? w * h : 0.0;
  }
  Vec2 closest_to(const Vec2& p) const {
    return {std::clamp(p.x(), x0, x1), std::clamp(p.y(), y0, y1)};
  }
};

inline Box box_around(const Vec2& c, double half_w, double half_h) {
  return {c.x() - half_w, c.y() - half_h, c.x() + half_w, c.y() + half_h};
}

struct LabelRequest {
  Vec2 at = Vec2::Zero();             // the mark the label belongs to
  double mark_radius = 0.0;           // the mark's half size: kept clear of labels
  double half_w = 0.0, half_h = 0.0;  // the label's half size
  bool first = false;                 // placed before the others (wrong pairs)
};

// One box per request, inside `area`, overlapping none of `taken`, the marks
// or the boxes placed before it where a spot within 32 `step`s of the mark
// allows; else the spot of least overlap. Marks with many neighbours (within
// 8 steps) choose first, after the `first` ones.
std::vector<Box> place_labels(const std::vector<LabelRequest>& requests, std::vector<Box> taken,
                              const Box& area, double step);

}  // namespace hair25d::pipeline::detail
