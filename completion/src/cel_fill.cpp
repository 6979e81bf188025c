// Coarse fill for cel art (inpaint_cel): every hole pixel continues the flat
// region nearest to it, so the exemplar pass only has to add texture.
#include <opencv2/imgproc.hpp>
#include <vector>

#include "inpaint_internal.h"
#include "raster.h"

namespace hair25d::completion::detail {

Image coarse_fill(const Image& image, const LabelMap& fill, const LabelMap& source,
                  const InpaintOptions& options) {
  const int w = image.width(), h = image.height();
  const std::vector<std::uint8_t> ink = ink_mask(image, options);
  auto idx = [w](int x, int y) { return static_cast<std::size_t>(y) * w + x; };
  auto usable = [&](int x, int y) {
    return fill.at(x, y) == 0 && (source.empty() || source.at(x, y) != 0);
  };
  // Flat pixels: usable, not ink and not next to ink (the anti-aliased rim of
  // a line is neither line nor region colour). distanceTransform measures the
  // distance to the nearest zero, so flat pixels are the zeros.
  cv::Mat not_flat(h, w, CV_8U, cv::Scalar(255));
  int flat_count = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!usable(x, y)) continue;
      bool near_ink = false;
      for (int dy = -1; dy <= 1 && !near_ink; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx >= 0 && ny >= 0 && nx < w && ny < h && ink[idx(nx, ny)]) {
            near_ink = true;
            break;
          }
        }
      if (!near_ink) not_flat.at<std::uint8_t>(y, x) = 0, ++flat_count;
    }
  if (flat_count == 0) {
    // No flat pixel: fall back to every usable pixel.
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (usable(x, y)) not_flat.at<std::uint8_t>(y, x) = 0, ++flat_count;
  }
  Image guide = image;
  if (flat_count == 0) return guide;
  cv::Mat dist, labels;
  cv::distanceTransform(not_flat, dist, labels, cv::DIST_L2, cv::DIST_MASK_5, cv::DIST_LABEL_PIXEL);
  // Label → colour of that zero pixel.
  std::vector<Rgba> colour_of(static_cast<std::size_t>(flat_count) + 1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (not_flat.at<std::uint8_t>(y, x) == 0) {
        const int l = labels.at<int>(y, x);
        if (l >= 0 && static_cast<std::size_t>(l) < colour_of.size())
          colour_of[static_cast<std::size_t>(l)] = image.at(x, y);
      }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (fill.at(x, y) != 0) {
        const int l = labels.at<int>(y, x);
        if (l >= 0 && static_cast<std::size_t>(l) < colour_of.size())
          guide.at(x, y) = colour_of[static_cast<std::size_t>(l)];
      }
  // Nearest-pixel fill leaves ragged Voronoi seams; a median keeps the flat
  // colours and straightens the seams. Only hole pixels take it.
  cv::Mat smooth;
  cv::medianBlur(view(guide), smooth, 5);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (fill.at(x, y) != 0) {
        const cv::Vec4b& v = smooth.at<cv::Vec4b>(y, x);
        guide.at(x, y) = {v[0], v[1], v[2], v[3]};
      }
  return guide;
}

}  // namespace hair25d::completion::detail
