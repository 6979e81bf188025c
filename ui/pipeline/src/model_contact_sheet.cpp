// The contact sheet of a model run: four panels for a person to check the
// completion (light blue, as the paper's Fig. 1d), the depth order and the
// skeletons.
#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <span>
#include <string>
#include <vector>

#include "hair25d/core/error.h"
#include "hair25d/pipeline/model_stage.h"

namespace hair25d::pipeline {
namespace {

// Integer alpha blending (alpha in 0..255, rounded to nearest): the panels
// are drawn at full resolution, so this runs a few million times.
void blend(Image& img, int x, int y, Rgba c, int alpha) {
  if (!img.contains(x, y)) return;
  Rgba& d = img.at(x, y);
  const int keep = 255 - alpha;
  auto mix = [&](std::uint8_t a, std::uint8_t b) {
    return static_cast<std::uint8_t>((a * keep + b * alpha + 127) / 255);
  };
  d = {mix(d.r, c.r), mix(d.g, c.g), mix(d.b, c.b), 255};
}

// Every pixel of `img` blended towards `c`.
void wash(Image& img, Rgba c, int alpha) {
  const int keep = 255 - alpha;
  for (Rgba& d : std::span(img.data(), static_cast<std::size_t>(img.width()) * img.height())) {
    d.r = static_cast<std::uint8_t>((d.r * keep + c.r * alpha + 127) / 255);
    d.g = static_cast<std::uint8_t>((d.g * keep + c.g * alpha + 127) / 255);
    d.b = static_cast<std::uint8_t>((d.b * keep + c.b * alpha + 127) / 255);
    d.a = 255;
  }
}

void disc(Image& img, const Vec2& p, double r, Rgba c) {
  const int x0 = std::max(0, static_cast<int>(p.x() - r));
  const int x1 = std::min(img.width() - 1, static_cast<int>(p.x() + r));
  const int y0 = std::max(0, static_cast<int>(p.y() - r));
  const int y1 = std::min(img.height() - 1, static_cast<int>(p.y() + r));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
      if ((Vec2(x + 0.5, y + 0.5) - p).squaredNorm() <= r * r) img.at(x, y) = {c.r, c.g, c.b, 255};
}

void line(Image& img, const Vec2& a, const Vec2& b, double width, Rgba c) {
  const int steps = std::max(1, static_cast<int>((b - a).norm() * 2));
  for (int i = 0; i <= steps; ++i)
    disc(img, a + (b - a) * (static_cast<double>(i) / steps), width / 2, c);
}

// Strand indices back to front.
std::vector<int> back_to_front(const HairModel& m) {
  std::vector<int> order(m.strands.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return m.strands[a].depth < m.strands[b].depth; });
  return order;
}

// Background, then every strand's texture back to front.
Image composite(const HairModel& m, const std::vector<int>& order) {
  Image out = m.background.empty() ? m.image : m.background;
  for (int i : order) {
    const Strand& s = m.strands[i];
    for (int y = 0; y < s.texture.height(); ++y)
      for (int x = 0; x < s.texture.width(); ++x) {
        const Rgba t = s.texture.at(x, y);
        if (t.a != 0) blend(out, x + s.texture_origin.x(), y + s.texture_origin.y(), t, t.a);
      }
  }
  return out;
}

// Completed parts lie under other strands by construction: tint them on top
// so they can be seen at all.
void tint_completed(Image& img, const ModelRun& run) {
  const HairModel& m = run.model;
  for (std::size_t i = 0; i < m.strands.size() && i < run.strands.size(); ++i) {
    const LabelMap& mask = run.strands[i].mask;
    const Eigen::Vector2i o = m.strands[i].texture_origin;
    for (int y = 0; y < mask.height(); ++y)
      for (int x = 0; x < mask.width(); ++x)
        if (mask.at(x, y) == 2) blend(img, x + o.x(), y + o.y(), {150, 200, 255, 255}, 153);
  }
}

Rgba depth_colour(int depth, int max_depth) {
  const double t = max_depth > 0 ? static_cast<double>(depth) / max_depth : 0.0;
  return {static_cast<std::uint8_t>(40 + 215 * t),
          static_cast<std::uint8_t>(60 + 80 * (1 - std::abs(2 * t - 1))),
          static_cast<std::uint8_t>(255 - 215 * t), 255};
}

// The box {x, y, w, h} of `in`, shrunk by a whole factor so that its longer
// side is at most max_side (each output pixel the mean of its source pixels).
Image shrink(const Image& in, const std::array<int, 4>& box, int max_side) {
  const auto [bx, by, bw, bh] = box;
  const int factor = std::max(1, (std::max(bw, bh) + max_side - 1) / max_side);
  Image out((bw + factor - 1) / factor, (bh + factor - 1) / factor);
  for (int y = 0; y < out.height(); ++y)
    for (int x = 0; x < out.width(); ++x) {
      int r = 0, g = 0, b = 0, n = 0;
      for (int sy = y * factor; sy < std::min(bh, (y + 1) * factor); ++sy)
        for (int sx = x * factor; sx < std::min(bw, (x + 1) * factor); ++sx) {
          const Rgba c = in.at(bx + sx, by + sy);
          r += c.r, g += c.g, b += c.b, ++n;
        }
      out.at(x, y) = {static_cast<std::uint8_t>(r / n), static_cast<std::uint8_t>(g / n),
                      static_cast<std::uint8_t>(b / n), 255};
    }
  return out;
}

}  // namespace

std::array<int, 4> contact_sheet_box(const ModelRun& run) {
  const HairModel& m = run.model;
  const int width = m.image.width(), height = m.image.height();
  // A drawing is mostly body, clothes and background: the hair alone, with
  // room round it, is what a person checks, at the largest size that fits.
  double x0 = width, y0 = height, x1 = 0, y1 = 0;
  auto take = [&](double ax, double ay, double bx, double by) {
    x0 = std::min(x0, ax), y0 = std::min(y0, ay), x1 = std::max(x1, bx), y1 = std::max(y1, by);
  };
  for (const Strand& s : m.strands) {
    if (!s.texture.empty())
      take(s.texture_origin.x(), s.texture_origin.y(), s.texture_origin.x() + s.texture.width(),
           s.texture_origin.y() + s.texture.height());
    for (const Vec2& p : s.skeleton.nodes)
      if (p.allFinite()) take(p.x(), p.y(), p.x(), p.y());
  }
  if (!(x1 > x0 && y1 > y0)) return {0, 0, width, height};
  const double margin = std::max(16.0, std::max(x1 - x0, y1 - y0) / 8);
  const int bx0 = std::clamp(static_cast<int>(std::floor(x0 - margin)), 0, width - 1);
  const int by0 = std::clamp(static_cast<int>(std::floor(y0 - margin)), 0, height - 1);
  const int bx1 = std::clamp(static_cast<int>(std::ceil(x1 + margin)), bx0 + 1, width);
  const int by1 = std::clamp(static_cast<int>(std::ceil(y1 + margin)), by0 + 1, height);
  return {bx0, by0, bx1 - bx0, by1 - by0};
}

Image render_contact_sheet(const ModelRun& run, int panel_max_side) {
  const HairModel& m = run.model;
  if (panel_max_side < 1)
    throw Error("render_contact_sheet: panel_max_side = " + std::to_string(panel_max_side) +
                "; must be at least 1");
  if (m.image.empty()) return {};
  const std::array<int, 4> box = contact_sheet_box(run);
  const std::vector<int> order = back_to_front(m);
  // The depth panel (and the drawing's) are drawn beside the other two: the
  // sheet is drawn at full resolution, a serial step of the model command.
  auto depth_panels = std::async(std::launch::async, [&] {
    Image depth = m.background.empty() ? m.image : m.background;
    wash(depth, {255, 255, 255, 255}, 153);
    int max_depth = 0;
    for (const Strand& s : m.strands) max_depth = std::max(max_depth, s.depth);
    for (int i : order) {
      const Strand& s = m.strands[i];
      const Rgba c = depth_colour(s.depth, max_depth);
      for (int y = 0; y < s.texture.height(); ++y)
        for (int x = 0; x < s.texture.width(); ++x)
          if (s.texture.at(x, y).a)
            blend(depth, x + s.texture_origin.x(), y + s.texture_origin.y(), c, 217);
      for (std::size_t k = 0; k < s.outline.size(); ++k)
        line(depth, s.outline[k], s.outline[(k + 1) % s.outline.size()], 1.5, {30, 30, 30, 255});
    }
    return std::array<Image, 2>{shrink(m.image, box, panel_max_side),
                                shrink(depth, box, panel_max_side)};
  });
  Image skeletons = composite(m, order);
  Image completed = skeletons;
  tint_completed(completed, run);

  wash(skeletons, {255, 255, 255, 255}, 115);
  const double w = std::max(2.0, std::max(box[2], box[3]) / 300.0);
  for (const Strand& s : m.strands) {
    const Skeleton& k = s.skeleton;
    for (std::size_t i = 0; i < k.nodes.size(); ++i)
      if (k.parent[i] >= 0)
        line(skeletons, k.nodes[k.parent[i]], k.nodes[i], w, {220, 20, 20, 255});
    for (int t : k.tips) disc(skeletons, k.nodes[t], 1.5 * w, {20, 170, 40, 255});
    if (!k.nodes.empty()) disc(skeletons, k.nodes[0], 2.0 * w, {30, 60, 230, 255});
  }

  Image shrunk_completed = shrink(completed, box, panel_max_side);
  Image shrunk_skeletons = shrink(skeletons, box, panel_max_side);
  std::array<Image, 2> drawing_and_depth = depth_panels.get();
  const Image panels[4] = {std::move(drawing_and_depth[0]), std::move(shrunk_completed),
                           std::move(drawing_and_depth[1]), std::move(shrunk_skeletons)};
  const int pw = panels[0].width(), ph = panels[0].height(), gap = 8;
  Image sheet(2 * pw + 3 * gap, 2 * ph + 3 * gap, {255, 255, 255, 255});
  for (int p = 0; p < 4; ++p) {
    const int ox = gap + (p % 2) * (pw + gap), oy = gap + (p / 2) * (ph + gap);
    for (int y = 0; y < panels[p].height(); ++y)
      for (int x = 0; x < panels[p].width(); ++x) sheet.at(ox + x, oy + y) = panels[p].at(x, y);
  }
  return sheet;
}

}  // namespace hair25d::pipeline
