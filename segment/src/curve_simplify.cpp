#include <algorithm>
#include <cmath>
#include <sstream>

#include "hair25d/core/error.h"
#include "hair25d/segment/curves.h"

namespace hair25d::segment {

bool SimplifyOptions::is_valid(std::string* error) const {
  std::ostringstream o;
  if (!(smoothing_sigma >= 0.0 && smoothing_sigma <= 50.0))
    o << "segment::SimplifyOptions::smoothing_sigma = " << smoothing_sigma
      << "; must be in [0, 50]";
  else if (!(tolerance >= 0.0 && tolerance <= 100.0))
    o << "segment::SimplifyOptions::tolerance = " << tolerance << "; must be in [0, 100]";
  if (o.str().empty()) return true;
  if (error) *error = o.str();
  return false;
}

namespace {

void dp_recurse(const Polyline& line, int first, int last, double tol2, std::vector<char>& keep) {
  // An explicit stack: long curves would recurse thousands deep.
  std::vector<std::pair<int, int>> stack{{first, last}};
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    if (b <= a + 1) continue;
    const Vec2 p = line[a], d = line[b] - line[a];
    const double len2 = d.squaredNorm();
    int best = -1;
    double best_d2 = tol2;
    for (int i = a + 1; i < b; ++i) {
      const Vec2 v = line[i] - p;
      double d2;
      if (len2 < 1e-18) {
        d2 = v.squaredNorm();
      } else {
        const double t = std::clamp(v.dot(d) / len2, 0.0, 1.0);
        d2 = (v - t * d).squaredNorm();
      }
      if (d2 > best_d2) best_d2 = d2, best = i;
    }
    if (best < 0) continue;
    keep[best] = 1;
    stack.push_back({a, best});
    stack.push_back({best, b});
  }
}

// Gaussian along the curve by arc-length index (points about 1 px apart);
// ends of open curves stay put and their neighbours are pulled less.
Polyline smooth(const Polyline& pts, bool closed, double sigma) {
  const int n = static_cast<int>(pts.size());
  if (sigma <= 0.0 || n < 3) return pts;
  const int r = static_cast<int>(std::ceil(3.0 * sigma));
  std::vector<double> w(r + 1);
  for (int k = 0; k <= r; ++k) w[k] = std::exp(-0.5 * k * k / (sigma * sigma));
  Polyline out(pts.size());
  for (int i = 0; i < n; ++i) {
    if (!closed && (i == 0 || i == n - 1)) {
      out[i] = pts[i];
      continue;
    }
    // Open curves: a symmetric window that shrinks near the ends keeps the
    // smoothed curve anchored to its fixed end points.
    const int rr = closed ? r : std::min({r, i, n - 1 - i});
    Vec2 s = w[0] * pts[i];
    double ws = w[0];
    for (int k = 1; k <= rr; ++k) {
      const Vec2 a = pts[closed ? (i - k + n) % n : i - k];
      const Vec2 b = pts[closed ? (i + k) % n : i + k];
      s += w[k] * (a + b);
      ws += 2.0 * w[k];
    }
    out[i] = s / ws;
  }
  return out;
}

}  // namespace

Polyline douglas_peucker(const Polyline& line, double tolerance) {
  if (line.size() <= 2) return line;
  std::vector<char> keep(line.size(), 0);
  keep.front() = keep.back() = 1;
  dp_recurse(line, 0, static_cast<int>(line.size()) - 1, tolerance * tolerance, keep);
  Polyline out;
  for (std::size_t i = 0; i < line.size(); ++i)
    if (keep[i]) out.push_back(line[i]);
  return out;
}

std::vector<Curve> smooth_and_simplify(const std::vector<Curve>& curves,
                                       const SimplifyOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw Error(why);
  std::vector<Curve> out;
  out.reserve(curves.size());
  for (const Curve& c : curves) {
    for (const Vec2& p : c.points)
      if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
        throw Error("segment::smooth_and_simplify: a curve holds a non-finite point");
    if (c.points.size() < 2) continue;
    Curve s = c;
    s.points = smooth(c.points, c.closed, options.smoothing_sigma);
    if (c.closed) {
      // Split the loop at its point farthest from the start so both halves
      // keep their shape, then simplify each half.
      const int n = static_cast<int>(s.points.size());
      int far = 0;
      double fd = -1.0;
      for (int i = 0; i < n; ++i) {
        const double d = (s.points[i] - s.points[0]).squaredNorm();
        if (d > fd) fd = d, far = i;
      }
      if (n < 4 || far == 0) {
        if (n >= 3) out.push_back(std::move(s));
        continue;
      }
      Polyline a(s.points.begin(), s.points.begin() + far + 1);
      Polyline b(s.points.begin() + far, s.points.end());
      b.push_back(s.points[0]);
      a = douglas_peucker(a, options.tolerance);
      b = douglas_peucker(b, options.tolerance);
      Polyline loop = a;
      loop.insert(loop.end(), b.begin() + 1, b.end() - 1);
      if (loop.size() < 3) continue;
      s.points = std::move(loop);
    } else {
      s.points = douglas_peucker(s.points, options.tolerance);
      if ((s.points.front() - s.points.back()).norm() < 1e-9 && s.points.size() <= 2) continue;
    }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace hair25d::segment
