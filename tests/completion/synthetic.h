// Hand-built drawings for completion tests: flat-colour bands with black
// outlines, occluded by other bands, on non-square canvases.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>

#include "hair25d/completion/completion.h"
#include "hair25d/core/hair_model.h"
#include "hair25d/core/image.h"

namespace hair25d::completion::test {

struct Drawing {
  Image image;
  LabelMap regions;
  std::vector<RegionRelation> relations;
};

// Paints `inside(x, y)` pixels with `colour` and `label`, and a black outline
// `line` pixels wide just inside its border (label 0 there, as annotated).
inline void paint(Drawing& d, const std::function<bool(double, double)>& inside, Rgba colour,
                  int label, int line = 2) {
  const int w = d.image.width(), h = d.image.height();
  auto in = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < w && y < h && inside(x + 0.5, y + 0.5);
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!in(x, y)) continue;
      bool border = false;
      for (int dy = -line; dy <= line && !border; ++dy)
        for (int dx = -line; dx <= line; ++dx)
          if (!in(x + dx, y + dy)) {
            border = true;
            break;
          }
      d.image.at(x, y) = border ? Rgba{20, 15, 10, 255} : colour;
      d.regions.at(x, y) = border ? 0 : label;
    }
}

inline Drawing blank(int w, int h) {
  return {Image(w, h, Rgba{230, 240, 250, 255}), LabelMap(w, h, 0), {}};
}

// Non-hair paint (label 0: face, neck, clothes) with a 3 px ink outline just
// inside `inside`; the image's edge is no outline (the body runs on below it).
inline void paint_skin(Drawing& d, const std::function<bool(double, double)>& inside, Rgba colour) {
  const int w = d.image.width(), h = d.image.height();
  const auto in = [&](int x, int y) {
    x = std::clamp(x, 0, w - 1), y = std::clamp(y, 0, h - 1);
    return inside(x + 0.5, y + 0.5);
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!in(x, y)) continue;
      bool border = false;
      for (int dy = -3; dy <= 3 && !border; ++dy)
        for (int dx = -3; dx <= 3 && !border; ++dx) border = !in(x + dx, y + dy);
      d.image.at(x, y) = border ? Rgba{20, 15, 10, 255} : colour;
      d.regions.at(x, y) = 0;
    }
}

// Repaints the drawn (labelled) pixels of `region` where `where(x, y)`
// holds with colour(x, y).
inline void repaint(
    Drawing& d, int region, const std::function<Rgba(int, int)>& colour,
    const std::function<bool(int, int)>& where = [](int, int) { return true; }) {
  for (int y = 0; y < d.image.height(); ++y)
    for (int x = 0; x < d.image.width(); ++x)
      if (d.regions.at(x, y) == region && where(x, y)) d.image.at(x, y) = colour(x, y);
}

// A horizontal gradient through `base` at x = `x0`, `slope` RGB a px on
// every channel.
inline Rgba along_x(Rgba base, double x0, double slope, double x) {
  const auto c = [&](std::uint8_t v) {
    return static_cast<std::uint8_t>(std::clamp(std::lround(v + slope * (x - x0)), 0L, 255L));
  };
  return Rgba{c(base.r), c(base.g), c(base.b), 255};
}

// Screentone as the generator draws it: the share of pixel (x, y) covered by
// round dots of `radius` periods on a square lattice of `period` px turned by
// `angle` rad (4 x 4 samples a pixel, so 0, 1/16, ..., 1).
inline double dot_cover(int x, int y, double period, double radius, double angle) {
  const double c = std::cos(angle) / period, s = std::sin(angle) / period;
  int in = 0;
  for (int sy = 0; sy < 4; ++sy)
    for (int sx = 0; sx < 4; ++sx) {
      const double px = x + (sx + 0.5) / 4 - 0.5, py = y + (sy + 0.5) / 4 - 0.5;
      const double u = c * px + s * py, v = -s * px + c * py;
      const double fu = u - std::round(u), fv = v - std::round(v);
      in += fu * fu + fv * fv < radius * radius;
    }
  return in / 16.0;
}

// Drawn relations, as certain as the user's (a weak measured one would not
// keep two pieces out of one strand: completion.cpp kFirmRelationScore).
inline RegionRelation below(int a, int b) { return {a, b, Relation::kBelow, 1.0, true, false}; }

// A vertical strand over a wide lowest region 4 (x 20..230, y 20..280, in
// `back`), cut in two by a band 3 lying over it (x 40..210, y 118..162):
// the upper piece 1 (x 100..140, y 70..140) and the lower one 2 (y
// 140..210), both in `strand`, as is the band. The pieces lie above a region,
// so no mass join takes them, and are too shallow for the banks: only a
// strand join (or a path join) can.
inline Drawing strand_under_band(Rgba back, Rgba strand) {
  Drawing d = blank(250, 300);
  paint(
      d, [](double x, double y) { return x > 20 && x < 230 && y > 20 && y < 280; }, back, 4);
  paint(
      d, [](double x, double y) { return x > 100 && x < 140 && y > 70 && y < 140; }, strand, 1);
  paint(
      d, [](double x, double y) { return x > 100 && x < 140 && y >= 140 && y < 210; }, strand, 2);
  paint(
      d, [](double x, double y) { return x > 40 && x < 210 && y > 118 && y < 162; }, strand, 3);
  d.relations = {below(4, 1), below(4, 2), below(4, 3), below(1, 3), below(2, 3)};
  return d;
}

// The back hair's and the fan's paint of back_hair_under_fan's tests.
inline constexpr Rgba kBack{120, 80, 50, 255};
inline constexpr Rgba kFan{200, 150, 110, 255};

// Back hair (regions 1 left, 2 right) behind a fan of three overlapping
// vertical strands 3 < 4 < 5 that covers x 112..205: 90 px across, more than
// the 0.6 edge lengths (~40 px) a single edge's bank rays reach.
inline Drawing back_hair_under_fan(Rgba left, Rgba right, Rgba fan) {
  Drawing d = blank(340, 200);
  paint(
      d, [](double x, double y) { return x > 20 && x < 120 && y > 60 && y < 130; }, left, 1);
  paint(
      d, [](double x, double y) { return x > 195 && x < 320 && y > 66 && y < 128; }, right, 2);
  paint(
      d, [](double x, double y) { return x > 112 && x < 145 && y > 10 && y < 190; }, fan, 3);
  paint(
      d, [](double x, double y) { return x > 140 && x < 172 && y > 5 && y < 185; }, fan, 4);
  paint(
      d, [](double x, double y) { return x > 168 && x < 205 && y > 15 && y < 195; }, fan, 5);
  d.relations = {below(1, 3), below(2, 5), below(3, 4), below(4, 5)};
  return d;
}

// The completion input for drawing `d` (which must outlive it).
inline Input input_of(const Drawing& d, std::optional<Vec2> head_center) {
  Input in;
  in.image = &d.image;
  in.regions = &d.regions;
  in.relations = d.relations;
  in.head_center = head_center;
  return in;
}

// Completion where only the region-level joins (mass and path joins) can
// join: strand joins ruled out (tangents within 0.5°, cut widths within
// 1 %), no background fill, no face (the paper near the head would pass for
// one); the head at (170, 20).
inline Result run_region_joins(const Drawing& d) {
  Options o;
  o.max_join_angle_deg = 0.5;
  o.min_width_ratio = 0.99;
  o.inpaint_background = false;
  o.face_joins = false;
  return complete_strands(input_of(d, Vec2(170, 20)), o);
}

// The completed strand that holds `region`, or null.
inline const CompletedStrand* strand_with(const Result& r, int region) {
  for (const CompletedStrand& s : r.strands)
    if (std::find(s.regions.begin(), s.regions.end(), region) != s.regions.end()) return &s;
  return nullptr;
}

// The regions of the completed strand that holds `region`; empty if none.
inline std::vector<int> regions_with(const Result& r, int region) {
  const CompletedStrand* s = strand_with(r, region);
  return s != nullptr ? s->regions : std::vector<int>{};
}

// The regions completed in one strand with region 1 (the upper piece of
// strand_under_band) under a join cost limit of `max_join_cost`: no
// background fill, no face joins, the head above the strand at (125, 10).
inline std::vector<int> joined_with_1(const Drawing& d, double max_join_cost) {
  Options o;
  o.max_join_cost = max_join_cost;
  o.inpaint_background = false;
  o.face_joins = false;
  return regions_with(complete_strands(input_of(d, Vec2(125, 10)), o), 1);
}

}  // namespace hair25d::completion::test
