#include "inside_test.h"

#include <algorithm>
#include <cmath>

namespace hair25d::skeleton::detail {

InsideTest::InsideTest(const Polyline& polygon) {
  const std::size_t n = polygon.size();
  if (n == 0) return;
  double y1 = polygon[0].y();
  y0_ = y1;
  for (const Vec2& p : polygon) y0_ = std::min(y0_, p.y()), y1 = std::max(y1, p.y());
  // About two edges a bin on a smooth outline.
  bins_ = static_cast<int>(std::clamp<std::size_t>(n / 2, 1, 4096));
  scale_ = y1 > y0_ ? bins_ / (y1 - y0_) : 0.0;
  // An edge can cross the line y = p.y only if min(a.y, b.y) <= p.y < max:
  // it goes in every bin between those of its two ends (bin() is monotone).
  std::vector<int> count(bins_ + 1, 0);
  auto range = [&](std::size_t i, std::size_t j) {
    const double lo = std::min(polygon[i].y(), polygon[j].y());
    const double hi = std::max(polygon[i].y(), polygon[j].y());
    return std::pair(bin(lo), bin(hi));
  };
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const auto [first, last] = range(i, j);
    for (int k = first; k <= last; ++k) ++count[k + 1];
  }
  start_.assign(bins_ + 1, 0);
  for (int k = 0; k < bins_; ++k) start_[k + 1] = start_[k] + count[k + 1];
  edges_.resize(start_[bins_]);
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const auto [first, last] = range(i, j);
    for (int k = first; k <= last; ++k) edges_[fill[k]++] = {polygon[i], polygon[j]};
  }
}

int InsideTest::bin(double y) const {
  return std::clamp(static_cast<int>(std::floor((y - y0_) * scale_)), 0, bins_ - 1);
}

bool InsideTest::contains(const Vec2& p) const {
  if (bins_ == 0 || !(p.y() >= y0_)) return false;
  const int k = bin(p.y());
  bool inside = false;
  for (int e = start_[k]; e < start_[k + 1]; ++e) {
    const Vec2& a = edges_[e].a;
    const Vec2& b = edges_[e].b;
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

}  // namespace hair25d::skeleton::detail
