#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>

#include "hair25d/core/error.h"
#include "hair25d/segment/mesh.h"

namespace hair25d::segment {
namespace {

// Calls put(x, y) for every pixel of rows [top, bottom) whose centre lies in
// the triangle (closed: pixels on a shared edge go to whichever triangle comes
// later).
template <class Put>
void scan_triangle(const Vec2& a, const Vec2& b, const Vec2& c, int width, int top, int bottom,
                   Put put) {
  const double ymin = std::min({a.y(), b.y(), c.y()}), ymax = std::max({a.y(), b.y(), c.y()});
  const int y0 = std::max(top, static_cast<int>(std::ceil(ymin - 0.5)));
  const int y1 = std::min(bottom - 1, static_cast<int>(std::floor(ymax - 0.5)));
  const Vec2 v[3] = {a, b, c};
  for (int y = y0; y <= y1; ++y) {
    const double yc = y + 0.5;
    double xl = 1e300, xr = -1e300;
    for (int k = 0; k < 3; ++k) {
      const Vec2& p = v[k];
      const Vec2& q = v[(k + 1) % 3];
      if ((p.y() - yc) * (q.y() - yc) > 0) continue;
      if (p.y() == q.y()) {
        xl = std::min({xl, p.x(), q.x()});
        xr = std::max({xr, p.x(), q.x()});
        continue;
      }
      const double x = p.x() + (yc - p.y()) / (q.y() - p.y()) * (q.x() - p.x());
      xl = std::min(xl, x);
      xr = std::max(xr, x);
    }
    if (xl > xr) continue;
    const int x0 = std::max(0, static_cast<int>(std::ceil(xl - 0.5)));
    const int x1 = std::min(width - 1, static_cast<int>(std::floor(xr - 0.5)));
    for (int x = x0; x <= x1; ++x) put(x, y);
  }
}

void check(const TriMesh2& mesh, int width, int height, const char* what) {
  if (width < 0 || height < 0)
    throw Error(std::string(what) + ": size " + std::to_string(width) + "x" +
                std::to_string(height) + "; must not be negative");
  mesh.validate(what);
}

// Every triangle in order, put(t, x, y) for its pixels: bands of rows on the
// cores, each band's pixels written in the triangles' order (the same map).
template <class Put>
void scan_mesh(const TriMesh2& mesh, int width, int height, Put put) {
  constexpr int kBandRows = 128;
  const int bands = (height + kBandRows - 1) / kBandRows;
  cv::parallel_for_(cv::Range(0, bands), [&](const cv::Range& range) {
    for (int band = range.start; band < range.end; ++band) {
      const int top = band * kBandRows, bottom = std::min(height, top + kBandRows);
      for (int t = 0; t < mesh.triangle_count(); ++t)
        scan_triangle(mesh.V.row(mesh.F(t, 0)).transpose(), mesh.V.row(mesh.F(t, 1)).transpose(),
                      mesh.V.row(mesh.F(t, 2)).transpose(), width, top, bottom,
                      [&](int x, int y) { put(t, x, y); });
    }
  });
}

}  // namespace

LabelMap rasterize_triangles(const TriMesh2& mesh, int width, int height) {
  check(mesh, width, height, "segment::rasterize_triangles");
  LabelMap out(width, height, -1);
  scan_mesh(mesh, width, height, [&](int t, int x, int y) { out.at(x, y) = t; });
  return out;
}

LabelMap rasterize_triangle_values(const TriMesh2& mesh, const std::vector<int>& values, int width,
                                   int height, int fill) {
  check(mesh, width, height, "segment::rasterize_triangle_values");
  if (values.size() != static_cast<std::size_t>(mesh.triangle_count()))
    throw Error("segment::rasterize_triangle_values: " + std::to_string(values.size()) +
                " values for " + std::to_string(mesh.triangle_count()) +
                " triangles; must be one per triangle");
  LabelMap out(width, height, fill);
  scan_mesh(mesh, width, height, [&](int t, int x, int y) { out.at(x, y) = values[t]; });
  return out;
}

}  // namespace hair25d::segment
