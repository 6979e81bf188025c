// The pixel box of the boundaries between two regions (outside-the-image
// boundaries left out): the window layer_regions measures lines in, before
// LineResponse::window_margin() is added.
#pragma once

#include <algorithm>
#include <array>

#include "hair25d/layering/boundary_graph.h"

namespace hair25d::layering::test {

// {x0, y0, x1, y1}; x0 > x1 when there is no such boundary.
inline std::array<int, 4> inner_boundary_box(const BoundaryGraph& graph, int width, int height) {
  int x0 = width, y0 = height, x1 = 0, y1 = 0;
  for (const Boundary& b : graph.boundaries) {
    if (b.left == kOutsideLabel || b.right == kOutsideLabel) continue;
    for (const Vec2& p : b.points) {
      x0 = std::min(x0, static_cast<int>(p.x()));
      y0 = std::min(y0, static_cast<int>(p.y()));
      x1 = std::max(x1, static_cast<int>(p.x()));
      y1 = std::max(y1, static_cast<int>(p.y()));
    }
  }
  return {x0, y0, x1, y1};
}

}  // namespace hair25d::layering::test
