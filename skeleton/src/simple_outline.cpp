#include "simple_outline.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace hair25d::skeleton::detail {

namespace {

// A traced boundary passes a cell twice where the shape is pinched to one
// cell or two cells touch only diagonally: a polygon that touches itself.
// Cutting the trace into loops at every repeated cell leaves loops that each
// visit a cell once (the lobes either side of the pinch).
std::vector<std::vector<cv::Point>> split_at_repeats(const std::vector<cv::Point>& contour) {
  std::vector<std::vector<cv::Point>> loops;
  std::vector<cv::Point> stack;
  std::map<std::pair<int, int>, std::size_t> position;  // cell -> index in stack
  for (const cv::Point& p : contour) {
    const auto key = std::make_pair(p.x, p.y);
    auto it = position.find(key);
    if (it == position.end()) {
      position.emplace(key, stack.size());
      stack.push_back(p);
      continue;
    }
    // The cells since the first visit close a loop; the cell stays for the rest.
    const std::size_t from = it->second;
    loops.emplace_back(stack.begin() + static_cast<std::ptrdiff_t>(from), stack.end());
    for (std::size_t k = from + 1; k < stack.size(); ++k)
      position.erase(std::make_pair(stack[k].x, stack[k].y));
    stack.resize(from + 1);
  }
  loops.push_back(std::move(stack));
  return loops;
}

}  // namespace

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
  for (const auto& contour : contours)
    for (const std::vector<cv::Point>& cells : split_at_repeats(contour)) {
      // Specks left by the opening, and the out-and-back trace of a spur,
      // are below a pixel: no strand part.
      if (cells.size() < 3 || std::abs(cv::contourArea(cells)) < kScale * kScale) continue;
      Polyline loop;
      for (std::size_t i = 0; i < cells.size(); ++i) {
        // Only corners of the staircase: points on a straight run add nothing.
        const cv::Point& prev = cells[(i + cells.size() - 1) % cells.size()];
        const cv::Point& next = cells[(i + 1) % cells.size()];
        if (cells[i] - prev == next - cells[i]) continue;
        loop.emplace_back((cells[i].x - kMargin) / kScale + x0,
                          (cells[i].y - kMargin) / kScale + y0);
      }
      if (loop.size() >= 3) loops.push_back(std::move(loop));
    }
  return loops;
}

}  // namespace hair25d::skeleton::detail
