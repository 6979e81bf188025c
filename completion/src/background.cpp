// The background behind the hair (paper §5.4): the drawing with the hair
// removed and the hole filled so that moving hair uncovers face, skin or paper.
#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "hair25d/completion/inpaint.h"
#include "raster.h"
#include "strand_assembly.h"

namespace hair25d::completion::detail {

Image fill_background(const Context& ctx, InpaintResult* inpainted) {
  const Options& o = *ctx.options;
  const Image& image = *ctx.image;
  const int w = image.width(), h = image.height();
  // Hair plus a 2-pixel margin: the anti-aliased rim of the outline is not
  // dark enough to be assigned to a region but is still hair.
  cv::Mat hair = view(ctx.labels) != 0;
  cv::Mat near;
  cv::dilate(hair, near, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(17, 17)));
  cv::dilate(hair, hair, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(5, 5)));
  // Where outlines converge (sharp tips) the drawn line is wider than the
  // outline reach: dark pixels close to the hair are hair too.
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (near.at<std::uint8_t>(y, x) && luma(image.at(x, y)) < o.dark_luma)
        hair.at<std::uint8_t>(y, x) = 255;
  // The hair covers much of the drawing: fill a reduced copy (an integer
  // factor, so every reduced pixel is a whole block) and upscale the fill.
  const int factor =
      std::max(1, (std::max(w, h) + o.background_max_side - 1) / o.background_max_side);
  const int sw = (w + factor - 1) / factor, sh = (h + factor - 1) / factor;
  Image small(sw, sh);
  LabelMap hole(sw, sh), source(sw, sh);
  for (int sy = 0; sy < sh; ++sy)
    for (int sx = 0; sx < sw; ++sx) {
      int r = 0, g = 0, b = 0, a = 0, n = 0;
      bool any = false;
      for (int y = sy * factor; y < std::min(h, (sy + 1) * factor); ++y)
        for (int x = sx * factor; x < std::min(w, (sx + 1) * factor); ++x) {
          const Rgba& c = image.at(x, y);
          r += c.r, g += c.g, b += c.b, a += c.a, ++n;
          any = any || hair.at<std::uint8_t>(y, x) != 0;
        }
      small.at(sx, sy) = {static_cast<std::uint8_t>(r / n), static_cast<std::uint8_t>(g / n),
                          static_cast<std::uint8_t>(b / n), static_cast<std::uint8_t>(a / n)};
      hole.at(sx, sy) = any ? 1 : 0;
      source.at(sx, sy) = any ? 0 : 1;
    }
  *inpainted = inpaint_cel(small, hole, source, o.inpaint);
  Image out = image;
  cv::Mat big;
  cv::resize(view(small), big, cv::Size(sw * factor, sh * factor), 0, 0, cv::INTER_LINEAR);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!hair.at<std::uint8_t>(y, x)) continue;
      const cv::Vec4b& v = big.at<cv::Vec4b>(y, x);
      out.at(x, y) = {v[0], v[1], v[2], v[3]};  // transparent sheets stay transparent
    }
  return out;
}

}  // namespace hair25d::completion::detail
