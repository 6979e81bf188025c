#include "strand_shape.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hair25d::generator {

namespace {

constexpr double kPi = std::numbers::pi;

double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

Vec2 unit_or(const Vec2& v, const Vec2& fallback) {
  const double n = v.norm();
  return n > 1e-12 ? Vec2(v / n) : fallback;
}

// The width profile: from the root it swells to the widest point, then tapers
// to the tip, faster near the tip as in drawn locks.
double width_at(const StrandSpec& s, double t) {
  if (t < s.peak_at) {
    return s.max_width * (s.root_ratio + (1.0 - s.root_ratio) * smoothstep(t / s.peak_at));
  }
  const double u = (t - s.peak_at) / std::max(1e-9, 1.0 - s.peak_at);
  return s.max_width * (s.tip_ratio + (1.0 - s.tip_ratio) * std::pow(1.0 - u, 0.85));
}

Vec2 normal_at(const StrandGeometry& g, std::size_t i) {
  const std::size_t a = i == 0 ? 0 : i - 1;
  const std::size_t b = std::min(i + 1, g.centre.size() - 1);
  const Vec2 d = unit_or(g.centre[b] - g.centre[a], Vec2(0, 1));
  return {-d.y(), d.x()};
}

Vec2 tangent_at(const StrandGeometry& g, std::size_t i) {
  const Vec2 n = normal_at(g, i);
  return {n.y(), -n.x()};
}

}  // namespace

Vec2 bezier_point(const Vec2 (&p)[4], double t) {
  const double u = 1.0 - t;
  return u * u * u * p[0] + 3 * u * u * t * p[1] + 3 * u * t * t * p[2] + t * t * t * p[3];
}

Vec2 bezier_tangent(const Vec2 (&p)[4], double t) {
  const double u = 1.0 - t;
  return 3 * u * u * (p[1] - p[0]) + 6 * u * t * (p[2] - p[1]) + 3 * t * t * (p[3] - p[2]);
}

Polyline ellipse_polygon(const Vec2& centre, const Vec2& radii, double angle, int n) {
  Polyline out;
  out.reserve(static_cast<std::size_t>(n));
  const double c = std::cos(angle), s = std::sin(angle);
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * kPi * i / n;
    const double x = radii.x() * std::cos(a), y = radii.y() * std::sin(a);
    out.emplace_back(centre.x() + c * x - s * y, centre.y() + s * x + c * y);
  }
  return out;
}

StrandGeometry sample_strand(const StrandSpec& spec) {
  const double rough_length = (spec.control[1] - spec.control[0]).norm() +
                              (spec.control[2] - spec.control[1]).norm() +
                              (spec.control[3] - spec.control[2]).norm();
  const int n = std::clamp(static_cast<int>(rough_length / 3.0), 24, 200);
  StrandGeometry g;
  for (int i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / (n - 1);
    g.t.push_back(t);
    Vec2 c = bezier_point(spec.control, t);
    if (spec.wave_amplitude > 0.0) {
      // Waves grow from nothing at the root, where the strand leaves the head.
      const Vec2 d = unit_or(bezier_tangent(spec.control, t), Vec2(0, 1));
      const double wave =
          std::sin(2.0 * kPi * spec.wave_cycles * t + spec.wave_phase) - std::sin(spec.wave_phase);
      c += Vec2(-d.y(), d.x()) * spec.wave_amplitude * smoothstep(t / 0.35) * wave;
    }
    g.centre.push_back(c);
    g.width.push_back(width_at(spec, t));
  }
  for (int i = 0; i < n; ++i) {
    // Normals of the sampled (possibly waved) centre line, not of the Bézier.
    const int a = std::max(0, i - 1), b = std::min(n - 1, i + 1);
    const Vec2 d = unit_or(g.centre[b] - g.centre[a], Vec2(0, 1));
    const Vec2 nrm(-d.y(), d.x());
    g.left.push_back(g.centre[i] + nrm * g.width[i] / 2);
    g.right.push_back(g.centre[i] - nrm * g.width[i] / 2);
  }
  return g;
}

Polyline strand_outline(const StrandGeometry& g) {
  const std::size_t n = g.centre.size();
  Polyline out(g.left.begin(), g.left.end());
  const double tip_radius = g.width[n - 1] / 2;
  if (tip_radius > 0.5) {
    const Vec2 nl = normal_at(g, n - 1), tg = tangent_at(g, n - 1);
    for (int k = 1; k < 16; ++k) {
      const double phi = kPi * k / 16;
      out.push_back(g.centre[n - 1] + tip_radius * (std::cos(phi) * nl + std::sin(phi) * tg));
    }
    out.push_back(g.right[n - 1]);
  }
  for (std::size_t i = n - 1; i-- > 0;) out.push_back(g.right[i]);
  const double root_radius = g.width[0] / 2;
  const Vec2 nl = normal_at(g, 0), tg = tangent_at(g, 0);
  for (int k = 1; k < 20; ++k) {
    const double phi = kPi * k / 20;
    out.push_back(g.centre[0] + root_radius * (-std::cos(phi) * nl - std::sin(phi) * tg));
  }
  return out;
}

Polyline band_polygon(const StrandGeometry& g, int side, double t0, double t1, double depth) {
  Polyline edge, inner;
  for (std::size_t i = 0; i < g.centre.size(); ++i) {
    if (g.t[i] < t0 || g.t[i] > t1) continue;
    const double u = (g.t[i] - t0) / std::max(1e-9, t1 - t0);
    const Vec2 nl = normal_at(g, i) * (side > 0 ? 1.0 : -1.0);
    // The very points of the side, so the band meets the outline without a
    // sliver of base colour and never pokes out of the strand.
    edge.push_back(side > 0 ? g.left[i] : g.right[i]);
    inner.push_back(g.centre[i] + nl * (g.width[i] / 2) * (1.0 - 2.0 * depth * std::sin(kPi * u)));
  }
  Polyline out = edge;
  out.insert(out.end(), inner.rbegin(), inner.rend());
  return out;
}

Polyline fork_line(const StrandGeometry& g, int side, double t_split) {
  constexpr double kBend = 0.12;  // curve parameter span over which the line leaves
  Polyline out;
  const std::size_t n = g.centre.size();
  out.push_back(g.centre[n - 1] + tangent_at(g, n - 1) * (g.width[n - 1] / 2 + 4.0));
  for (std::size_t i = n; i-- > 0;) {
    const double t = g.t[i];
    if (t < t_split - kBend) break;
    const double bend = t >= t_split ? 0.0 : 1.5 * smoothstep((t_split - t) / kBend);
    const Vec2 nl = normal_at(g, i) * (side > 0 ? 1.0 : -1.0);
    out.push_back(g.centre[i] + nl * (g.width[i] / 2) * bend);
  }
  return out;
}

}  // namespace hair25d::generator
