// The background behind the hair (paper §5.4): the drawing with the hair
// removed and the hole filled at full resolution so that moving hair uncovers
// face, skin or paper. Cel drawings are flat colours bounded by ink, so: ink
// lines that enter the hole are continued, flat colours fill up to them, and
// the exemplar pass of Criminisi et al. runs only where the surroundings are
// textured.
#include "hair25d/completion/background.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "background_internal.h"
#include "hair25d/core/error.h"
#include "head_fill.h"
#include "hole_rules.h"
#include "inpaint_internal.h"
#include "raster.h"
#include "strand_assembly.h"

namespace hair25d::completion {

bool BackgroundOptions::is_valid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error != nullptr) *error = "completion::BackgroundOptions::" + m;
    return false;
  };
  auto num = [](double v) { return std::to_string(v); };
  if (!(max_join_angle_deg > 0 && max_join_angle_deg <= 90))
    return fail("max_join_angle_deg = " + num(max_join_angle_deg) + "; must be in (0, 90]");
  if (!(max_join_length >= 1))
    return fail("max_join_length = " + num(max_join_length) + "; must be >= 1");
  if (!(min_width_ratio >= 0 && min_width_ratio <= 1))
    return fail("min_width_ratio = " + num(min_width_ratio) + "; must be in [0, 1]");
  if (!(max_colour_distance > 0))
    return fail("max_colour_distance = " + num(max_colour_distance) + "; must be > 0");
  if (!(min_inside_share >= 0 && min_inside_share <= 1))
    return fail("min_inside_share = " + num(min_inside_share) + "; must be in [0, 1]");
  if (!(tangent_arm >= 4 && tangent_arm <= 64))
    return fail("tangent_arm = " + num(tangent_arm) + "; must be in [4, 64]");
  if (!(max_extension >= 0))
    return fail("max_extension = " + num(max_extension) + "; must be >= 0");
  if (seam_radius < 0 || seam_radius > 8)
    return fail("seam_radius = " + std::to_string(seam_radius) + "; must be in [0, 8]");
  if (!(texture_threshold >= 0))
    return fail("texture_threshold = " + num(texture_threshold) + "; must be >= 0");
  std::string inner;
  if (!inpaint.is_valid(&inner)) return fail("inpaint: " + inner);
  return true;
}

namespace {

using detail::Mask;

// Mean |luma − its 3×3 median| over the known ink-free pixels of a 9×9
// window: 0 on flat cel regions and along straight borders between them,
// large on hatching, noise or painted texture.
cv::Mat texture_measure(const Image& crop, const Mask& hole, const Mask& ink) {
  const int w = crop.width(), h = crop.height();
  cv::Mat grey(h, w, CV_8U), med, resid(h, w, CV_32F), valid(h, w, CV_32F);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) grey.at<std::uint8_t>(y, x) = detail::luma(crop.at(x, y));
  cv::medianBlur(grey, med, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      const bool ok = !hole[i] && !ink[i];
      valid.at<float>(y, x) = ok ? 1.0f : 0.0f;
      resid.at<float>(y, x) = ok ? std::abs(static_cast<float>(grey.at<std::uint8_t>(y, x)) -
                                            med.at<std::uint8_t>(y, x))
                                 : 0.0f;
    }
  cv::boxFilter(resid, resid, CV_32F, {9, 9}, {-1, -1}, false);
  cv::boxFilter(valid, valid, CV_32F, {9, 9}, {-1, -1}, false);
  return resid / cv::max(valid, 1.0f);
}

// The exemplar pass on the hole pixels whose colour came from a textured
// place, guided by the flat fill.
InpaintResult add_texture(Image& crop, const Mask& hole, const Mask& ink,
                          const std::vector<int>& seed, const BackgroundOptions& o) {
  const int w = crop.width(), h = crop.height();
  const cv::Mat texture = texture_measure(crop, hole, ink);
  cv::Rect box;
  Mask textured(hole.size(), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      const int s = seed[i];
      if (!hole[i] || s < 0 || texture.at<float>(s / w, s % w) <= o.texture_threshold) continue;
      textured[i] = 1;
      box = box.area() == 0 ? cv::Rect(x, y, 1, 1) : box | cv::Rect(x, y, 1, 1);
    }
  if (box.area() == 0) return {};
  const int pad = o.inpaint.patch_radius + o.inpaint.search_radius;
  box = cv::Rect(box.x - pad, box.y - pad, box.width + 2 * pad, box.height + 2 * pad) &
        cv::Rect(0, 0, w, h);
  Image sub(box.width, box.height);
  LabelMap fill(box.width, box.height), source(box.width, box.height);
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y + box.y) * w + (x + box.x);
      sub.at(x, y) = crop.data()[i];
      fill.at(x, y) = textured[i];
      source.at(x, y) = hole[i] ? 0 : 1;
    }
  const Image guide = sub;
  const InpaintResult r = detail::run_exemplar(sub, fill, source, o.inpaint, &guide);
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x)
      if (fill.at(x, y)) crop.at(x + box.x, y + box.y) = sub.at(x, y);
  return r;
}

}  // namespace

BackgroundResult fill_background(const Image& image, const LabelMap& hole,
                                 const BackgroundOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw Error(why);
  detail::require_image_size("completion::fill_background", "hole mask is", hole, image);
  BackgroundResult result;
  result.image = image;
  const int w = image.width(), h = image.height();
  int x0 = w, y0 = h, x1 = -1, y1 = -1;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (hole.at(x, y) != 0)
        x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
  if (x1 < 0) return result;
  // Work on the hole's box plus what the tangents and seeds look at.
  const int pad = static_cast<int>(std::ceil(options.tangent_arm)) + 12;
  const cv::Rect box =
      cv::Rect(cv::Point(x0 - pad, y0 - pad), cv::Point(x1 + pad + 1, y1 + pad + 1)) &
      cv::Rect(0, 0, w, h);
  const int cw = box.width, ch = box.height;
  const std::size_t n = static_cast<std::size_t>(cw) * ch;
  Image crop(cw, ch);
  Mask in_hole(n, 0);
  for (int y = 0; y < ch; ++y)
    for (int x = 0; x < cw; ++x) {
      crop.at(x, y) = image.at(x + box.x, y + box.y);
      in_hole[static_cast<std::size_t>(y) * cw + x] = hole.at(x + box.x, y + box.y) != 0;
    }
  Mask ink = detail::ink_mask(crop, options.inpaint);
  for (std::size_t i = 0; i < n; ++i)
    if (in_hole[i]) ink[i] = 0;

  std::vector<detail::Stroke> strokes;
  std::vector<detail::LineEnd> ends;
  if (options.continue_lines || options.ink_seams)
    ends = detail::find_line_ends(crop, in_hole, ink, options);
  if (options.continue_lines) {
    result.line_ends = static_cast<int>(ends.size());
    strokes = detail::continue_lines(ends, in_hole, ink, cw, ch, options, &result.joined_lines,
                                     &result.extended_lines);
  }
  Mask barrier = detail::stroke_barrier(strokes, cw, ch);
  for (std::size_t i = 0; i < n; ++i) barrier[i] &= in_hole[i];
  std::vector<int> seed;
  const Image original = crop;
  const int edges = (box.x == 0 ? detail::kLeftEdge : 0) | (box.y == 0 ? detail::kTopEdge : 0) |
                    (box.x + cw == w ? detail::kRightEdge : 0) |
                    (box.y + ch == h ? detail::kBottomEdge : 0);
  result.unreached =
      detail::flat_fill(crop, in_hole, ink, barrier, options.seam_radius, &seed, edges);
  if (options.ink_seams) {
    // The seam line looks like the lines that enter the hole.
    Rgba colour{40, 30, 30, 255};
    double width = 2.0;
    if (!ends.empty()) {
      std::vector<const detail::LineEnd*> sorted;
      for (const detail::LineEnd& e : ends) sorted.push_back(&e);
      std::sort(sorted.begin(), sorted.end(), [](auto* a, auto* b) { return a->width < b->width; });
      width = std::clamp(sorted[sorted.size() / 2]->width, 1.0, 4.0);
      std::sort(sorted.begin(), sorted.end(),
                [](auto* a, auto* b) { return detail::luma(a->colour) < detail::luma(b->colour); });
      colour = sorted[sorted.size() / 2]->colour;
    }
    result.seam_pixels = detail::ink_seams(crop, original, in_hole, ink, barrier, colour, width);
  }
  result.texture = add_texture(crop, in_hole, ink, seed, options);
  detail::draw_strokes(crop, in_hole, strokes);
  for (int y = 0; y < ch; ++y)
    for (int x = 0; x < cw; ++x)
      if (in_hole[static_cast<std::size_t>(y) * cw + x]) {
        result.image.at(x + box.x, y + box.y) = crop.at(x, y);
        ++result.filled;
      }
  result.filled -= result.unreached;
  return result;
}

namespace detail {

Image fill_background(const Context& ctx, const BackgroundHole& taken, InpaintResult* inpainted) {
  const Options& o = *ctx.options;
  const Image& image = *ctx.image;
  const int w = image.width(), h = image.height();
  const Head& head = taken.head;
  cv::Mat holes = taken.holes.clone();
  // The head: under the hair it is skin, filled from the face first; the
  // rest of the hole is filled around it, the head's outline drawn where it
  // meets the rest, so that no other colour runs into the head and the skin
  // does not run out of it.
  Image work = image;
  InpaintResult skin;
  if (!head.mask.empty()) {
    skin = fill_head(work, holes, head, o.background.inpaint, o.background.texture_threshold);
    cv::Mat rest = holes & (head.mask == 0);
    cv::Mat rim;
    cv::dilate(head.mask, rim, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(5, 5)));
    rim &= rest;
    const Rgba line = head_line_colour(image, *ctx.original, holes, head.mask, o);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (rim.at<std::uint8_t>(y, x)) work.at(x, y) = line;
    holes = rest & ~rim;
  }
  LabelMap hole(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) hole.at(x, y) = holes.at<std::uint8_t>(y, x) != 0;
  BackgroundResult r = completion::fill_background(work, hole, o.background);
  inpainted->filled = r.filled + skin.filled;
  inpainted->patches = r.texture.patches + skin.patches;
  inpainted->unfilled = r.unreached + skin.unfilled;
  return std::move(r.image);
}

}  // namespace detail
}  // namespace hair25d::completion
