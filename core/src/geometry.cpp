#include "hair25d/core/geometry.h"

#include <cmath>

namespace hair25d {

double signed_area(const Polyline& polygon) {
  double twice = 0.0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % n];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice;
}

bool point_in_polygon(const Polyline& polygon, const Vec2& p) {
  bool inside = false;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

double polyline_length(const Polyline& line) {
  double length = 0.0;
  for (std::size_t i = 1; i < line.size(); ++i) length += (line[i] - line[i - 1]).norm();
  return length;
}

Polyline resample_polyline(const Polyline& line, double spacing) {
  if (line.size() < 2 || !(spacing > 0.0)) return line;
  const double total = polyline_length(line);
  const int segments = std::max(1, static_cast<int>(std::round(total / spacing)));
  const double step = total / segments;
  Polyline out;
  out.reserve(segments + 1);
  out.push_back(line.front());
  std::size_t i = 1;
  double walked = 0.0;  // arc length at line[i - 1]
  for (int k = 1; k < segments; ++k) {
    const double target = k * step;
    while (i < line.size() - 1 && walked + (line[i] - line[i - 1]).norm() < target) {
      walked += (line[i] - line[i - 1]).norm();
      ++i;
    }
    const double seg = (line[i] - line[i - 1]).norm();
    const double t = seg > 0.0 ? (target - walked) / seg : 0.0;
    out.push_back(line[i - 1] + std::clamp(t, 0.0, 1.0) * (line[i] - line[i - 1]));
  }
  out.push_back(line.back());
  return out;
}

}  // namespace hair25d
