#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "curve_graph.h"
#include "curve_tracing.h"
#include "hair25d/core/error.h"
#include "hair25d/segment/curves.h"
#include "line_response.h"

namespace hair25d::segment {

bool CurveOptions::is_valid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = "segment::CurveOptions::" + m;
    return false;
  };
  if (scales.empty()) return fail("scales is empty; must list at least one scale");
  if (scales.size() > 8)
    return fail("scales has " + std::to_string(scales.size()) + " entries; must be at most 8");
  for (double s : scales) {
    if (!(s >= 0.5 && s <= 16.0)) {
      std::ostringstream o;
      o << "scales holds " << s << "; each must be in [0.5, 16] pixels";
      return fail(o.str());
    }
  }
  if (!(low_threshold > 0.0 && std::isfinite(low_threshold)))
    return fail("low_threshold = " + std::to_string(low_threshold) + "; must be > 0");
  if (!(high_threshold >= low_threshold && std::isfinite(high_threshold)))
    return fail("high_threshold = " + std::to_string(high_threshold) +
                "; must be finite and >= low_threshold (" + std::to_string(low_threshold) + ")");
  if (speck_size < 0 || speck_size > 32)
    return fail("speck_size = " + std::to_string(speck_size) + "; must be in [0, 32]");
  if (!(blob_weight >= 0.0 && blob_weight <= 2.0))
    return fail("blob_weight = " + std::to_string(blob_weight) + "; must be in [0, 2]");
  if (!(min_curve_length >= 0.0 && std::isfinite(min_curve_length)))
    return fail("min_curve_length = " + std::to_string(min_curve_length) + "; must be >= 0");
  if (!(spur_factor >= 0.0 && std::isfinite(spur_factor)))
    return fail("spur_factor = " + std::to_string(spur_factor) + "; must be >= 0");
  if (!(gap_factor >= 0.0 && gap_factor <= 20.0))
    return fail("gap_factor = " + std::to_string(gap_factor) + "; must be in [0, 20]");
  return true;
}

CurveResult extract_curves(const Image& image, const CurveOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw Error(why);
  CurveResult result;
  result.line_mask = LabelMap(image.width(), image.height(), 0);
  // The Hessian needs a few pixels of context; smaller images have no lines.
  if (image.width() < 4 || image.height() < 4) return result;
  try {
    cv::Mat grey = detail::grey_image(image);
    // One closing (a square is much cheaper than a disk) serves twice: what
    // it fills are specks to remove, and ink is what it lightens.
    const double smax = *std::max_element(options.scales.begin(), options.scales.end());
    const int k =
        std::max(2 * options.speck_size + 1, 2 * static_cast<int>(std::ceil(2.5 * smax)) + 1);
    cv::Mat closed;
    cv::morphologyEx(grey, closed, cv::MORPH_CLOSE,
                     cv::getStructuringElement(cv::MORPH_RECT, cv::Size(k, k)), cv::Point(-1, -1),
                     1, cv::BORDER_REPLICATE);
    detail::remove_dots(grey, closed, options.speck_size,
                        static_cast<float>(3.0 * options.high_threshold));
    const float low = static_cast<float>(options.low_threshold);
    detail::LineField field = detail::compute_line_field(grey, options.scales, low,
                                                         static_cast<float>(options.blob_weight));
    // Centre lines run on ink only: large scales also answer a few pixels
    // past a line's end and beside its round cap, where the paper is blank.
    field.response.setTo(0.0f, (closed - grey) < low);
    const cv::Mat ridge = detail::suppress_non_maxima(field, low);
    result.ridge_pixels = cv::countNonZero(ridge);
    if (result.ridge_pixels == 0) return result;

    // Typical line width: the best scale answers a line of width w at w / 2.
    std::vector<float> sigmas;
    sigmas.reserve(result.ridge_pixels);
    for (int y = 0; y < ridge.rows; ++y)
      for (int x = 0; x < ridge.cols; ++x)
        if (ridge.at<std::uint8_t>(y, x) && field.response.at<float>(y, x) > options.high_threshold)
          sigmas.push_back(field.sigma.at<float>(y, x));
    if (sigmas.empty()) return result;
    std::nth_element(sigmas.begin(), sigmas.begin() + sigmas.size() / 2, sigmas.end());
    result.line_width = 2.0 * sigmas[sigmas.size() / 2];

    const detail::TraceResult traced =
        detail::trace_curves(field, ridge, static_cast<float>(options.high_threshold));
    detail::GraphOptions g;
    g.min_curve_length = options.min_curve_length;
    g.spur_length = options.spur_factor * result.line_width;
    g.gap_length = std::max(2.0, options.gap_factor * result.line_width);
    g.border_gap_length = std::max(2.0, result.line_width);
    result.curves = detail::link_curves(traced, image.width(), image.height(), g);

    // Line pixels: ink within the line width of a traced centre line. Gaps
    // that the linking closed are paper, not ink, and stay out.
    cv::Mat centre = cv::Mat::zeros(ridge.size(), CV_8U);
    for (std::size_t i = 0; i < traced.owner.size(); ++i)
      if (traced.owner[i] >= 0) centre.data[i] = 1;
    const int r = std::max(1, static_cast<int>(std::ceil(result.line_width / 2.0))) + 1;
    cv::Mat near_centre;
    cv::dilate(centre, near_centre,
               cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * r + 1, 2 * r + 1)));
    const cv::Mat mask = near_centre & ((closed - grey) > low);
    for (int y = 0; y < mask.rows; ++y)
      for (int x = 0; x < mask.cols; ++x) result.line_mask.at(x, y) = mask.at<std::uint8_t>(y, x);
  } catch (const cv::Exception& e) {
    throw Error(std::string("segment::extract_curves: OpenCV failed: ") + e.what());
  }
  return result;
}

}  // namespace hair25d::segment
