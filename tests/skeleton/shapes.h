// Hand-built strand outlines for the skeleton tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

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

// A curved strand like tapered_strand whose half-width narrows linearly from
// `w0` to `w_end` and ends in a half circle of radius `w_end`: a rounded tip
// at `rounded_tip_end(...)`.
inline Polyline rounded_strand(Vec2 origin, double length, double w0, double w_end, double bend,
                               int n = 60) {
  auto centre = [&](double s) -> Vec2 {
    return origin + Vec2(s * length, bend * std::sin(s * M_PI * 0.9));
  };
  auto normal = [&](double s) -> Vec2 {
    const Vec2 d(length, bend * M_PI * 0.9 * std::cos(s * M_PI * 0.9));
    return Vec2(-d.y(), d.x()).normalized();
  };
  Polyline left, right;
  for (int i = 0; i <= n; ++i) {
    const double s = static_cast<double>(i) / n;
    const double w = w0 + (w_end - w0) * s;
    left.push_back(centre(s) + w * normal(s));
    right.push_back(centre(s) - w * normal(s));
  }
  Polyline poly = left;
  // The cap: from the left side round the front to the right side.
  const Vec2 nrm = normal(1.0), ahead(nrm.y(), -nrm.x());
  for (int k = 1; k < 12; ++k) {
    const double a = M_PI * k / 12;
    poly.push_back(centre(1.0) + w_end * (std::cos(a) * nrm + std::sin(a) * ahead));
  }
  for (auto it = right.rbegin(); it != right.rend(); ++it) poly.push_back(*it);
  return poly;
}

inline Vec2 rounded_strand_end(Vec2 origin, double length, double w_end, double bend) {
  const Vec2 d(length, bend * M_PI * 0.9 * std::cos(M_PI * 0.9));
  return origin + Vec2(length, bend * std::sin(M_PI * 0.9)) + w_end * d.normalized();
}

// A Y-shaped strand: a trunk from x = 0 to 60 forking into two sharp arms.
inline Polyline forked_strand(Vec2 o) {
  return {o + Vec2(0, -15),  o + Vec2(60, -15), o + Vec2(160, -60), o + Vec2(90, 0),
          o + Vec2(160, 60), o + Vec2(60, 15),  o + Vec2(0, 15)};
}

// `poly` with its corner `index` replaced by a circular arc of `radius`
// tangent to both sides (`steps` + 1 points): a blunt, rounded tip.
inline Polyline round_corner(const Polyline& poly, std::size_t index, double radius,
                             int steps = 12) {
  const std::size_t n = poly.size();
  const Vec2 p = poly[index];
  const Vec2 u = (poly[(index + n - 1) % n] - p).normalized();
  const Vec2 v = (poly[(index + 1) % n] - p).normalized();
  const double half = 0.5 * std::acos(std::clamp(u.dot(v), -1.0, 1.0));
  const Vec2 centre = p + (u + v).normalized() * (radius / std::sin(half));
  const Vec2 from = p + u * (radius / std::tan(half)) - centre;
  const Vec2 to = p + v * (radius / std::tan(half)) - centre;
  double a0 = std::atan2(from.y(), from.x()), a1 = std::atan2(to.y(), to.x());
  // The arc bulges towards the corner: the short way round through it.
  double sweep = a1 - a0;
  while (sweep > M_PI) sweep -= 2 * M_PI;
  while (sweep < -M_PI) sweep += 2 * M_PI;
  Polyline out(poly.begin(), poly.begin() + static_cast<std::ptrdiff_t>(index));
  for (int k = 0; k <= steps; ++k) {
    const double a = a0 + sweep * k / steps;
    out.push_back(centre + radius * Vec2(std::cos(a), std::sin(a)));
  }
  out.insert(out.end(), poly.begin() + static_cast<std::ptrdiff_t>(index) + 1, poly.end());
  return out;
}

// The point of a rounded corner (round_corner) farthest out: where its arc
// meets the corner's bisector.
inline Vec2 rounded_apex(const Polyline& poly, std::size_t index, double radius) {
  const std::size_t n = poly.size();
  const Vec2 p = poly[index];
  const Vec2 u = (poly[(index + n - 1) % n] - p).normalized();
  const Vec2 v = (poly[(index + 1) % n] - p).normalized();
  const double half = 0.5 * std::acos(std::clamp(u.dot(v), -1.0, 1.0));
  const Vec2 inward = (u + v).normalized();
  return p + inward * (radius / std::sin(half) - radius);
}

}  // namespace hair25d::skeleton::test
