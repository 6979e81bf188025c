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

std::vector<std::vector<cv::Point>> outer_contours(const cv::Mat& mask8) {
  std::vector<std::vector<cv::Point>> contours;
  cv::Mat copy = mask8.clone();
  cv::findContours(copy, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  std::sort(contours.begin(), contours.end(),
            [](const auto& a, const auto& b) { return a.size() > b.size(); });
  return contours;
}

}  // namespace hair25d::completion::detail
