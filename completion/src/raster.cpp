#include "raster.h"

#include <algorithm>
#include <cstdlib>
#include <opencv2/imgproc.hpp>
#include <utility>
#include <vector>

namespace hair25d::completion::detail {

void fill_polygon(cv::Mat& mask, const Polyline& polygon, const cv::Point& origin, int value) {
  if (polygon.size() < 3) return;
  constexpr int kShift = 4;  // sub-pixel vertices: 1/16 pixel
  std::vector<cv::Point> pts;
  pts.reserve(polygon.size());
  for (const Vec2& p : polygon) {
    pts.emplace_back(static_cast<int>(std::lround((p.x() - origin.x - 0.5) * (1 << kShift))),
                     static_cast<int>(std::lround((p.y() - origin.y - 0.5) * (1 << kShift))));
  }
  // A run of equal whole-pixel steps along an axis or a diagonal (an
  // outline's pixel centres, most of a join patch's cut edges) is drawn and
  // filled by cv::fillPoly alike as one edge or as many, and its cost goes
  // by the vertices (session 40: a quarter of a join patch's). The run's
  // inner vertices are left out.
  const std::size_t n = pts.size();
  std::vector<cv::Point> kept;
  kept.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const cv::Point in = pts[i] - pts[(i + n - 1) % n], out = pts[(i + 1) % n] - pts[i];
    const bool whole = in.x % (1 << kShift) == 0 && in.y % (1 << kShift) == 0;
    const bool straight = in.x == 0 || in.y == 0 || std::abs(in.x) == std::abs(in.y);
    if (!(in == out && whole && straight)) kept.push_back(pts[i]);
  }
  if (kept.size() < 3) kept = std::move(pts);  // a degenerate polygon as it was
  const cv::Point* data = kept.data();
  const int count = static_cast<int>(kept.size());
  cv::fillPoly(mask, &data, &count, 1, cv::Scalar(value), cv::LINE_8, kShift);
}

cv::Rect polygon_box(const Polyline& polygon) {
  if (polygon.empty()) return {};
  double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18;
  for (const Vec2& p : polygon) {
    x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y());
    x1 = std::max(x1, p.x()), y1 = std::max(y1, p.y());
  }
  const cv::Point origin(static_cast<int>(std::floor(x0)) - 1,
                         static_cast<int>(std::floor(y0)) - 1);
  const int w = static_cast<int>(std::ceil(x1)) - origin.x + 2;
  const int h = static_cast<int>(std::ceil(y1)) - origin.y + 2;
  if (w <= 0 || h <= 0 || static_cast<double>(w) * h > kMaxPolygonBoxPixels) return {};
  return {origin.x, origin.y, w, h};
}

std::vector<std::vector<cv::Point>> outer_contours(const cv::Mat& mask8) {
  std::vector<std::vector<cv::Point>> contours;
  cv::Mat copy = mask8.clone();
  cv::findContours(copy, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  std::sort(contours.begin(), contours.end(),
            [](const auto& a, const auto& b) { return a.size() > b.size(); });
  return contours;
}

}  // namespace hair25d::completion::detail
