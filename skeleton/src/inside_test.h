// Point-in-polygon against one polygon many times (the branch smoothing asks
// ~20 times per skeleton point): the edges binned by height, so a query looks
// only at the edges that can cross its horizontal line. Same answers as core's
// point_in_polygon (the same crossing rule and arithmetic per edge).
#pragma once

#include <vector>

#include "hair25d/core/geometry.h"

namespace hair25d::skeleton::detail {

class InsideTest {
 public:
  explicit InsideTest(const Polyline& polygon);
  bool contains(const Vec2& p) const;

 private:
  struct Edge {
    Vec2 a, b;  // as point_in_polygon pairs them: a = polygon[i], b = polygon[i - 1]
  };
  int bin(double y) const;

  double y0_ = 0.0, scale_ = 0.0;
  int bins_ = 0;
  std::vector<int> start_;  // bins_ + 1 offsets into edges_
  std::vector<Edge> edges_;
};

}  // namespace hair25d::skeleton::detail
