#include "hair25d/completion/bezier.h"

namespace hair25d::completion {

Vec2 CubicBezier::point(double t) const {
  const double u = 1.0 - t;
  return u * u * u * control[0] + 3 * u * u * t * control[1] + 3 * u * t * t * control[2] +
         t * t * t * control[3];
}

Vec2 CubicBezier::derivative(double t) const {
  const double u = 1.0 - t;
  return 3 * u * u * (control[1] - control[0]) + 6 * u * t * (control[2] - control[1]) +
         3 * t * t * (control[3] - control[2]);
}

Polyline CubicBezier::sample(int segments) const {
  Polyline out;
  segments = std::max(1, segments);
  out.reserve(segments + 1);
  for (int i = 0; i <= segments; ++i) out.push_back(point(static_cast<double>(i) / segments));
  return out;
}

CubicBezier join_bezier(const Vec2& start, const Vec2& start_tangent, const Vec2& end,
                        const Vec2& end_tangent, double handle_scale) {
  const double h = handle_scale * (end - start).norm() / 3.0;
  return {{start, start + h * start_tangent, end - h * end_tangent, end}};
}

CubicBezier join_bezier_arms(const Vec2& start, const Vec2& start_tangent, const Vec2& end,
                             const Vec2& end_tangent, double start_share, double end_share) {
  const double chord = (end - start).norm();
  return {{start, start + start_share * chord * start_tangent,
           end - end_share * chord * end_tangent, end}};
}

}  // namespace hair25d::completion
