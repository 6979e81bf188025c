#include "simple_outline.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace hair25d::skeleton::detail {

std::vector<Polyline> simple_outline(const Polyline& polygon) {
  constexpr double kScale = 2.0;  // raster cells per pixel
  constexpr int kMargin = 4;
  double x0 = polygon[0].x(), y0 = polygon[0].y(), x1 = x0, y1 = y0;
  for (const Vec2& p : polygon) {
    x0 = std::min(x0, p.x());
    y0 = std::min(y0, p.y());
    x1 = std::max(x1, p.x());
    y1 = std::max(y1, p.y());
  }
  const int width = static_cast<int>(std::ceil((x1 - x0) * kScale)) + 2 * kMargin;
  const int height = static_cast<int>(std::ceil((y1 - y0) * kScale)) + 2 * kMargin;
  std::vector<cv::Point> ring;
  ring.reserve(polygon.size());
  for (const Vec2& p : polygon)
    ring.emplace_back(static_cast<int>(std::lround((p.x() - x0) * kScale)) + kMargin,
                      static_cast<int>(std::lround((p.y() - y0) * kScale)) + kMargin);
  cv::Mat mask = cv::Mat::zeros(height, width, CV_8U);
  cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{ring}, cv::Scalar(255));
  // Opening drops necks and spurs one cell wide, whose traced boundary would
  // visit a cell twice (not a simple polygon); closing first keeps parts that
  // merely come close together in one piece.
  const cv::Mat cross = cv::getStructuringElement(cv::MORPH_CROSS, cv::Size(3, 3));
  cv::morphologyEx(mask, mask, cv::MORPH_CLOSE, cross);
  cv::morphologyEx(mask, mask, cv::MORPH_OPEN, cross);

  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  std::vector<Polyline> loops;
  for (const auto& contour : contours) {
    // Specks left by the opening are below a pixel: no strand part.
    if (std::abs(cv::contourArea(contour)) < kScale * kScale) continue;
    std::vector<cv::Point> simplified;
    cv::approxPolyDP(contour, simplified, 0.25 * kScale, true);
    if (simplified.size() < 3) continue;
    Polyline loop;
    loop.reserve(simplified.size());
    for (const cv::Point& q : simplified)
      loop.emplace_back((q.x - kMargin) / kScale + x0, (q.y - kMargin) / kScale + y0);
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace hair25d::skeleton::detail
