// Hand-built strand outlines for the skeleton tests.
#pragma once

#include <cmath>

#include "hair25d/core/geometry.h"

namespace hair25d::skeleton::test {

// A curved strand: flat root of half-width `w0` at `origin`, tapering to a
// sharp tip `length` pixels to the right, bending by `bend` pixels.
inline Polyline tapered_strand(Vec2 origin, double length, double w0, double bend, int n = 60) {
  Polyline left, right;
  for (int i = 0; i <= n; ++i) {
    const double s = static_cast<double>(i) / n;
    const Vec2 c = origin + Vec2(s * length, bend * std::sin(s * M_PI * 0.9));
    const Vec2 d(length, bend * M_PI * 0.9 * std::cos(s * M_PI * 0.9));
    const Vec2 normal = Vec2(-d.y(), d.x()).normalized();
    const double w = w0 * std::pow(1.0 - s, 0.8);
    left.push_back(c + w * normal);
    if (i < n) right.push_back(c - w * normal);
  }
  Polyline poly = left;  // root-left ... tip
  for (auto it = right.rbegin(); it != right.rend(); ++it) poly.push_back(*it);
  return poly;
}

// A Y-shaped strand: a trunk from x = 0 to 60 forking into two sharp arms.
inline Polyline forked_strand(Vec2 o) {
  return {o + Vec2(0, -15),  o + Vec2(60, -15), o + Vec2(160, -60), o + Vec2(90, 0),
          o + Vec2(160, 60), o + Vec2(60, 15),  o + Vec2(0, 15)};
}

}  // namespace hair25d::skeleton::test
