#include "polygon_sampling.h"

#include <cmath>
#include <string>

#include "hair25d/core/error.h"

namespace hair25d::skeleton::detail {

Polyline clean_polygon(const Polyline& polygon, const char* what, std::vector<int>* source_index) {
  Polyline out;
  std::vector<int> index;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& p = polygon[i];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y())) {
      throw Error(std::string(what) + ": outline point " + std::to_string(i) +
                  " is not finite; coordinates must be finite pixels");
    }
    if (!out.empty() && (out.back() - p).norm() < 1e-9) continue;
    out.push_back(p);
    index.push_back(static_cast<int>(i));
  }
  while (out.size() > 1 && (out.back() - out.front()).norm() < 1e-9) {
    out.pop_back();
    index.pop_back();
  }
  if (out.size() < 3) {
    throw Error(std::string(what) + ": outline has " + std::to_string(out.size()) +
                " distinct points; a closed outline needs at least 3");
  }
  if (source_index != nullptr) *source_index = std::move(index);
  return out;
}

Polyline resample_closed(const Polyline& polygon, double spacing, std::vector<int>* source) {
  const std::size_t n = polygon.size();
  // A vertex is kept when the outline turns sharply there: resampling would
  // round off exactly the corners that become hair tips.
  std::vector<bool> keep(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = polygon[i] - polygon[(i + n - 1) % n];
    const Vec2 b = polygon[(i + 1) % n] - polygon[i];
    const double la = a.norm(), lb = b.norm();
    if (la > 0 && lb > 0 && a.dot(b) / (la * lb) < std::cos(30.0 * M_PI / 180.0)) keep[i] = true;
  }
  Polyline out;
  std::vector<int> src;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % n];
    const double len = (b - a).norm();
    const int pieces = std::max(1, static_cast<int>(std::round(len / spacing)));
    if (pieces == 1 && !keep[i] && !out.empty() && (a - out.back()).norm() < 0.5 * spacing) {
      continue;  // drop vertices closer than half a spacing unless they are corners
    }
    for (int k = 0; k < pieces; ++k) {
      const double t = static_cast<double>(k) / pieces;
      out.push_back(a + t * (b - a));
      src.push_back(t < 0.5 ? static_cast<int>(i) : static_cast<int>((i + 1) % n));
    }
  }
  if (out.size() < 3) {  // tiny polygon: keep it as it is
    out = polygon;
    src.resize(n);
    for (std::size_t i = 0; i < n; ++i) src[i] = static_cast<int>(i);
  }
  if (source != nullptr) *source = std::move(src);
  return out;
}

}  // namespace hair25d::skeleton::detail
