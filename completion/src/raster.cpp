#include "raster.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

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
  const cv::Point* data = pts.data();
  const int count = static_cast<int>(pts.size());
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
