// OpenCV views of the core rasters and small raster helpers (private).
#pragma once

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "hair25d/core/error.h"
#include "hair25d/core/geometry.h"
#include "hair25d/core/image.h"

namespace hair25d::completion::detail {

// Non-owning CV_32S view of a label map / CV_8UC4 view of an image.
inline cv::Mat view(const LabelMap& m) {
  return cv::Mat(m.height(), m.width(), CV_32S, const_cast<int*>(m.data()));
}
inline cv::Mat view(const Image& m) {
  return cv::Mat(m.height(), m.width(), CV_8UC4, const_cast<std::uint8_t*>(m.bytes()));
}

// Throws "<where>: <what> W×H, the image W×H; they must be the same size<or>"
// unless `map` has the image's size.
inline void require_image_size(const std::string& where, const std::string& what,
                               const LabelMap& map, const Image& image, const char* or_else = "") {
  if (map.width() == image.width() && map.height() == image.height()) return;
  throw Error(where + ": " + what + " " + std::to_string(map.width()) + "x" +
              std::to_string(map.height()) + ", the image " + std::to_string(image.width()) + "x" +
              std::to_string(image.height()) + "; they must be the same size" + or_else);
}

inline int luma(const Rgba& c) { return (299 * c.r + 587 * c.g + 114 * c.b) / 1000; }

// Euclidean distance of two colours in RGB (alpha ignored).
inline double colour_distance(const Rgba& a, const Rgba& b) {
  const double dr = a.r - b.r, dg = a.g - b.g, db = a.b - b.b;
  return std::sqrt(dr * dr + dg * dg + db * db);
}

// Index i of a closed contour of n points, wrapped into [0, n).
inline int wrap(int i, int n) { return ((i % n) + n) % n; }

// The angle (radians) between two directions; pi when either is zero.
inline double angle(const Vec2& a, const Vec2& b) {
  const double la = a.norm(), lb = b.norm();
  if (la <= 0 || lb <= 0) return M_PI;
  return std::acos(std::clamp(a.dot(b) / (la * lb), -1.0, 1.0));
}

// Distance from `x` to the segment p q (to p when they coincide).
inline double segment_distance(const Vec2& x, const Vec2& p, const Vec2& q) {
  const Vec2 d = q - p;
  const double n = d.squaredNorm();
  const double t = n > 0 ? std::clamp((x - p).dot(d) / n, 0.0, 1.0) : 0.0;
  return (x - (p + t * d)).norm();
}

// A contour point's pixel centre.
inline Vec2 centre(const cv::Point& p) { return {p.x + 0.5, p.y + 0.5}; }

// The line fitted to `points` by total least squares: their mean, the
// principal axis (sign as the solver gives it) and the points' root mean
// square distance off the line. At least two points.
struct TotalFit {
  Vec2 mean;
  Vec2 axis;
  double across = 0.0;
};
inline TotalFit total_least_squares(const Polyline& points) {
  TotalFit f;
  f.mean = Vec2::Zero();
  for (const Vec2& p : points) f.mean += p;
  f.mean /= static_cast<double>(points.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const Vec2& p : points) cov += (p - f.mean) * (p - f.mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
  f.axis = eig.eigenvectors().col(1);
  f.across = std::sqrt(std::max(0.0, eig.eigenvalues()(0) / static_cast<double>(points.size())));
  return f;
}

// The direction of the line fitted to `points` by total least squares (their
// principal axis), pointing the way of `towards`. At least two points.
inline Vec2 principal_axis(const Polyline& points, const Vec2& towards) {
  const Vec2 axis = total_least_squares(points).axis;
  return axis.dot(towards) < 0 ? Vec2(-axis) : axis;
}

// Zeroed bytes for a raster, in a buffer the caller keeps per thread
// (`thread_local`) from call to call: allocated afresh, the join patches'
// megabytes came back from the kernel a page fault at a time (session 40).
// Over kMaxKeptBytes the buffer is freed again when done, so that a thread
// that lives on (the studio's) keeps no more than that.
class ScratchBytes {
 public:
  static constexpr std::size_t kMaxKeptBytes = std::size_t{16} << 20;
  ScratchBytes(std::vector<std::uint8_t>& kept, std::size_t bytes) : kept_(kept) {
    kept_.assign(bytes, 0);
  }
  ~ScratchBytes() {
    if (kept_.capacity() > kMaxKeptBytes) std::vector<std::uint8_t>().swap(kept_);
  }
  ScratchBytes(const ScratchBytes&) = delete;
  ScratchBytes& operator=(const ScratchBytes&) = delete;
  std::uint8_t* data() { return kept_.data(); }

 private:
  std::vector<std::uint8_t>& kept_;
};

// Fills a closed polygon (pixel centres at integer + 0.5) into `mask` (CV_8U)
// with `value`, offset by -origin.
void fill_polygon(cv::Mat& mask, const Polyline& polygon, const cv::Point& origin, int value);

// The pixels `fill_polygon` may set for `polygon` (its bounding box with a
// pixel's margin), or an empty rect for no polygon or one over
// kMaxPolygonBoxPixels (a patch that long is no join's).
inline constexpr double kMaxPolygonBoxPixels = 4e6;
cv::Rect polygon_box(const Polyline& polygon);

// Contour points (pixel centres) of the outer boundaries of a binary mask,
// largest first. Orientation: as OpenCV returns them (all the same way).
std::vector<std::vector<cv::Point>> outer_contours(const cv::Mat& mask8);

}  // namespace hair25d::completion::detail
