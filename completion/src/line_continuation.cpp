// Ink lines continued across the background's hole: ends found on the hole's
// rim, paired and joined by C¹ cubics as the case-1 joins of paper §5.1,
// unpaired ends between two flat colours (a face outline against the paper)
// continued with their own curvature.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>

#include "background_internal.h"
#include "hair25d/completion/bezier.h"
#include "raster.h"

namespace hair25d::completion::detail {
namespace {

Vec2 rotate(const Vec2& v, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {v.x() * c - v.y() * s, v.x() * s + v.y() * c};
}

double angle_between(const Vec2& a, const Vec2& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
}

struct Raster {
  int w, h;
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < w && y < h; }
  std::size_t at(int x, int y) const { return static_cast<std::size_t>(y) * w + x; }
};

// A flat pixel (known, not ink, no ink next to it) near `q`, searched outward
// along `dir` up to a few pixels.
bool flat_colour(const Image& image, const Mask& hole, const Mask& ink, const Raster& r,
                 const Vec2& q, const Vec2& dir, Rgba* out) {
  for (double s = 0; s <= 4; s += 1) {
    const Vec2 t = q + s * dir;
    const int x = static_cast<int>(std::floor(t.x())), y = static_cast<int>(std::floor(t.y()));
    if (!r.inside(x, y) || hole[r.at(x, y)]) return false;
    bool flat = true;
    for (int dy = -1; dy <= 1 && flat; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (r.inside(x + dx, y + dy) && ink[r.at(x + dx, y + dy)]) {
          flat = false;
          break;
        }
    if (flat) {
      *out = image.at(x, y);
      return true;
    }
  }
  return false;
}

}  // namespace

std::vector<LineEnd> find_line_ends(const Image& image, const Mask& hole, const Mask& ink,
                                    const BackgroundOptions& o) {
  const Raster r{image.width(), image.height()};
  const std::size_t n = static_cast<std::size_t>(r.w) * r.h;
  Mask rim(n, 0);
  for (int y = 0; y < r.h; ++y)
    for (int x = 0; x < r.w; ++x) {
      if (!ink[r.at(x, y)]) continue;
      for (int dy = -1; dy <= 1 && !rim[r.at(x, y)]; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if (r.inside(x + dx, y + dy) && hole[r.at(x + dx, y + dy)]) {
            rim[r.at(x, y)] = 1;
            break;
          }
    }
  const int arm = std::max(4, static_cast<int>(std::lround(o.tangent_arm)));
  std::vector<int> depth(n, -1);
  std::vector<int> visited, queue;
  std::vector<LineEnd> ends;
  for (std::size_t start = 0; start < n; ++start) {
    if (!rim[start]) continue;
    // One end = one 8-connected run of rim ink; its line = the ink reached
    // from it within `arm` steps.
    queue.assign(1, static_cast<int>(start));
    rim[start] = 0;
    for (std::size_t k = 0; k < queue.size(); ++k) {
      const int x = queue[k] % r.w, y = queue[k] / r.w;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if (r.inside(x + dx, y + dy) && rim[r.at(x + dx, y + dy)]) {
            rim[r.at(x + dx, y + dy)] = 0;
            queue.push_back(static_cast<int>(r.at(x + dx, y + dy)));
          }
    }
    const std::size_t rim_count = queue.size();
    for (int i : queue) depth[static_cast<std::size_t>(i)] = 0;
    visited = queue;
    for (std::size_t k = 0; k < visited.size(); ++k) {
      const int i = visited[k], d = depth[static_cast<std::size_t>(i)];
      if (d >= arm) continue;
      const int x = i % r.w, y = i / r.w;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if (!r.inside(x + dx, y + dy)) continue;
          const std::size_t j = r.at(x + dx, y + dy);
          if (!ink[j] || hole[j] || depth[j] >= 0) continue;
          depth[j] = d + 1;
          visited.push_back(static_cast<int>(j));
        }
    }
    int reach = 0;
    for (int i : visited) reach = std::max(reach, depth[static_cast<std::size_t>(i)]);
    auto centroid = [&](int lo, int hi, int* count) {
      Vec2 s(0, 0);
      *count = 0;
      for (int i : visited) {
        const int d = depth[static_cast<std::size_t>(i)];
        if (d >= lo && d <= hi) s += Vec2(i % r.w + 0.5, i / r.w + 0.5), ++*count;
      }
      return *count > 0 ? Vec2(s / *count) : s;
    };
    LineEnd e;
    int c0 = 0, c1 = 0, c2 = 0;
    e.p = centroid(0, 0, &c0);
    const Vec2 far = centroid((reach * 7 + 9) / 10, reach, &c2);
    const Vec2 mid = centroid(reach / 2 - 1, reach / 2 + 1, &c1);
    int body = 0;
    for (int i : visited) body += depth[static_cast<std::size_t>(i)] >= 1;
    e.width = reach > 0 ? static_cast<double>(body) / reach : 0.0;
    const Vec2 chord = e.p - far;
    // A line, not a dot or a blob: visible for the whole arm, not too wide.
    bool ok = reach >= arm && chord.norm() > 0.5 * arm && e.width <= 8.0 &&
              static_cast<double>(rim_count) <= 3.0 * e.width + 6.0;
    if (ok) {
      e.d = chord.normalized();
      // The line must enter the hole, not run along its rim.
      Vec2 into(0, 0);
      const int px = static_cast<int>(e.p.x()), py = static_cast<int>(e.p.y());
      for (int dy = -4; dy <= 4; ++dy)
        for (int dx = -4; dx <= 4; ++dx)
          if (r.inside(px + dx, py + dy) && hole[r.at(px + dx, py + dy)]) into += Vec2(dx, dy);
      ok = into.norm() > 0 && e.d.dot(into.normalized()) > 0.3;
    }
    if (ok) {
      const Vec2 a = mid - far, b = e.p - mid;
      const double denom = a.norm() * b.norm() * (e.p - far).norm();
      e.curvature = denom > 1e-9 ? 2.0 * (a.x() * b.y() - a.y() * b.x()) / denom : 0.0;
      // The chord from `far` lags the tangent at p by half the turn between.
      e.d = rotate(e.d, 0.5 * e.curvature * (e.p - far).norm()).normalized();
      // The line's colour: its darkest pixels (the anti-aliased rim is paler).
      int darkest = 255;
      for (int i : visited) darkest = std::min(darkest, luma(image.data()[i]));
      long sr = 0, sg = 0, sb = 0, sa = 0, cnt = 0;
      for (int i : visited) {
        const Rgba& c = image.data()[i];
        if (luma(c) > darkest + 30) continue;
        sr += c.r, sg += c.g, sb += c.b, sa += c.a, ++cnt;
      }
      e.colour = {static_cast<std::uint8_t>(sr / cnt), static_cast<std::uint8_t>(sg / cnt),
                  static_cast<std::uint8_t>(sb / cnt), static_cast<std::uint8_t>(sa / cnt)};
      const Vec2 left(e.d.y(), -e.d.x()), right(-e.d.y(), e.d.x());
      bool found_left = false, found_right = false;
      for (double back = 2; back <= 8 && !(found_left && found_right); back += 2) {
        const Vec2 base = e.p - back * e.d;
        if (!found_left)
          found_left =
              flat_colour(image, hole, ink, r, base + (0.5 * e.width + 1) * left, left, &e.left);
        if (!found_right)
          found_right =
              flat_colour(image, hole, ink, r, base + (0.5 * e.width + 1) * right, right, &e.right);
      }
      e.sides = found_left && found_right;
      ends.push_back(e);
    }
    for (int i : visited) depth[static_cast<std::size_t>(i)] = -1;
  }
  return ends;
}

std::vector<Stroke> continue_lines(const std::vector<LineEnd>& ends, const Mask& hole,
                                   const Mask& ink, int width, int height,
                                   const BackgroundOptions& o, int* joined, int* extended) {
  const Raster r{width, height};
  const double max_angle = o.max_join_angle_deg * std::numbers::pi / 180.0;
  auto in_hole = [&](const Vec2& q) {
    const int x = static_cast<int>(std::floor(q.x())), y = static_cast<int>(std::floor(q.y()));
    return r.inside(x, y) && hole[r.at(x, y)] != 0;
  };
  struct Candidate {
    double cost;
    std::size_t a, b;
    Polyline curve;
  };
  std::vector<Candidate> candidates;
  for (std::size_t a = 0; a < ends.size(); ++a)
    for (std::size_t b = a + 1; b < ends.size(); ++b) {
      const LineEnd &ea = ends[a], &eb = ends[b];
      const Vec2 chord = eb.p - ea.p;
      const double length = chord.norm();
      if (length < 2.0 || length > o.max_join_length) continue;
      const double angle_a = angle_between(ea.d, chord), angle_b = angle_between(eb.d, -chord);
      if (angle_a > max_angle || angle_b > max_angle) continue;
      const double ratio = std::min(ea.width, eb.width) / std::max(ea.width, eb.width);
      if (ratio < o.min_width_ratio) continue;
      const double colour = colour_distance(ea.colour, eb.colour);
      if (colour > o.max_colour_distance) continue;
      // Travelling from a to b, a's left side is b's right side.
      // Both ends must be lines between known flat colours, the same ones.
      if (!ea.sides || !eb.sides) continue;
      const double sides =
          0.5 * (colour_distance(ea.left, eb.right) + colour_distance(ea.right, eb.left)) /
          o.max_colour_distance;
      if (sides > 0.7) continue;
      // Handles of a circular arc turning by θ are chord / (3 cos²(θ/4)).
      const double turn = angle_between(ea.d, -eb.d);
      const double scale = 1.0 / std::pow(std::cos(turn / 4.0), 2);
      const CubicBezier curve = join_bezier(ea.p, ea.d, eb.p, -eb.d, scale);
      const Polyline points = curve.sample(std::max(8, static_cast<int>(length / 2)));
      int inside = 0, counted = 0;
      for (const Vec2& q : points) {
        if ((q - ea.p).norm() < 3 || (q - eb.p).norm() < 3) continue;
        ++counted;
        inside += in_hole(q);
      }
      if (counted > 0 && inside < o.min_inside_share * counted) continue;
      const double cost = 0.5 * (angle_a + angle_b) / max_angle + std::abs(std::log(ratio)) +
                          colour / o.max_colour_distance + sides + 0.3 * length / o.max_join_length;
      candidates.push_back({cost, a, b, points});
    }
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& x, const Candidate& y) { return x.cost < y.cost; });
  std::vector<std::uint8_t> used(ends.size(), 0);
  std::vector<Stroke> strokes;
  for (Candidate& c : candidates) {
    if (used[c.a] || used[c.b]) continue;
    used[c.a] = used[c.b] = 1;
    const LineEnd &ea = ends[c.a], &eb = ends[c.b];
    Stroke s;
    // Start and end a little inside the visible lines: no gap at the rim.
    s.points.push_back(ea.p - 1.5 * ea.d);
    for (const Vec2& q : c.curve) s.points.push_back(q);
    s.points.push_back(eb.p - 1.5 * eb.d);
    const double length = std::max(1e-9, polyline_length(s.points));
    double along = 0.0;
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      if (i > 0) along += (s.points[i] - s.points[i - 1]).norm();
      const double t = along / length;
      s.widths.push_back((1 - t) * ea.width + t * eb.width);
    }
    s.colour = {static_cast<std::uint8_t>((ea.colour.r + eb.colour.r) / 2),
                static_cast<std::uint8_t>((ea.colour.g + eb.colour.g) / 2),
                static_cast<std::uint8_t>((ea.colour.b + eb.colour.b) / 2),
                static_cast<std::uint8_t>((ea.colour.a + eb.colour.a) / 2)};
    strokes.push_back(std::move(s));
    ++*joined;
  }

  // Unpaired ends between two different flat colours: continue them, so the
  // two colours stay apart along a drawn line, when they reach ink, a line
  // already drawn or the drawing's edge.
  Mask drawn = stroke_barrier(strokes, width, height);
  for (std::size_t a = 0; a < ends.size(); ++a) {
    const LineEnd& e = ends[a];
    // Only a line seen between two different flat colours: one with the
    // hole on a side may be the hair's own outline or a strand of dark hair.
    if (used[a] || !e.sides || colour_distance(e.left, e.right) < 40.0) continue;
    const double kappa = std::clamp(e.curvature, -1.0 / 40.0, 1.0 / 40.0);
    Stroke s;
    s.colour = e.colour;
    Vec2 q = e.p - 1.5 * e.d, dir = e.d;
    bool entered = false, met_line = false;
    double turned = 0.0;
    for (double len = 0; len < o.max_extension; len += 1.0) {
      s.points.push_back(q);
      q += dir;
      dir = rotate(dir, kappa);
      turned += std::abs(kappa);
      const int x = static_cast<int>(std::floor(q.x())), y = static_cast<int>(std::floor(q.y()));
      if (!r.inside(x, y)) {
        // The hole runs off the crop only where it reaches the drawing's
        // edge (the crop is the hole's box and a margin): the line runs on
        // off the drawing, as the body under hair hanging off its edge.
        met_line = entered;
        break;
      }
      if (turned > std::numbers::pi / 2) break;
      const std::size_t i = r.at(x, y);
      if (!hole[i]) {
        if (!entered && len < 4) continue;
        met_line = ink[i] != 0;
        if (met_line) s.points.push_back(q);
        break;
      }
      entered = true;
      if (drawn[i] && len > e.width + 3) {
        met_line = true;
        s.points.push_back(q);
        break;
      }
    }
    // A continuation that meets nothing is a guess that shows as a stray
    // line; the ink on the fill's seams separates the colours instead.
    if (!entered || !met_line || s.points.size() < 4) continue;
    s.widths.assign(s.points.size(), e.width);
    const Mask mine = stroke_barrier({s}, width, height);
    for (std::size_t i = 0; i < drawn.size(); ++i) drawn[i] |= mine[i];
    strokes.push_back(std::move(s));
    ++*extended;
  }
  return strokes;
}

Mask stroke_barrier(const std::vector<Stroke>& strokes, int width, int height) {
  cv::Mat m(height, width, CV_8U, cv::Scalar(0));
  for (const Stroke& s : strokes)
    for (std::size_t i = 1; i < s.points.size(); ++i) {
      const int t = std::max(2, static_cast<int>(std::lround(s.widths[i])));
      cv::line(
          m,
          cv::Point(static_cast<int>(s.points[i - 1].x()), static_cast<int>(s.points[i - 1].y())),
          cv::Point(static_cast<int>(s.points[i].x()), static_cast<int>(s.points[i].y())), 1, t,
          cv::LINE_8);
    }
  return Mask(m.datastart, m.dataend);
}

void draw_strokes(Image& image, const Mask& hole, const std::vector<Stroke>& strokes) {
  const int w = image.width(), h = image.height();
  constexpr int kShift = 3;  // sub-pixel bits
  constexpr double kScale = 1 << kShift;
  for (const Stroke& s : strokes) {
    if (s.points.size() < 2) continue;
    double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18, wmax = 1;
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      x0 = std::min(x0, s.points[i].x()), y0 = std::min(y0, s.points[i].y());
      x1 = std::max(x1, s.points[i].x()), y1 = std::max(y1, s.points[i].y());
      wmax = std::max(wmax, s.widths[i]);
    }
    const int pad = static_cast<int>(std::ceil(wmax)) + 2;
    const cv::Rect box =
        cv::Rect(cv::Point(static_cast<int>(x0) - pad, static_cast<int>(y0) - pad),
                 cv::Point(static_cast<int>(x1) + pad + 1, static_cast<int>(y1) + pad + 1)) &
        cv::Rect(0, 0, w, h);
    if (box.area() == 0) continue;
    cv::Mat cover(box.size(), CV_8U, cv::Scalar(0));
    // Pixel centres are at +0.5: OpenCV draws at integer coordinates.
    auto pt = [&](const Vec2& p) {
      return cv::Point(static_cast<int>(std::lround((p.x() - 0.5 - box.x) * kScale)),
                       static_cast<int>(std::lround((p.y() - 0.5 - box.y) * kScale)));
    };
    for (std::size_t i = 1; i < s.points.size(); ++i) {
      const int t = std::max(1, static_cast<int>(std::lround(s.widths[i])));
      cv::line(cover, pt(s.points[i - 1]), pt(s.points[i]), 255, t, cv::LINE_AA, kShift);
    }
    for (int y = 0; y < box.height; ++y)
      for (int x = 0; x < box.width; ++x) {
        const int c = cover.at<std::uint8_t>(y, x);
        const std::size_t i = static_cast<std::size_t>(y + box.y) * w + (x + box.x);
        if (c == 0 || !hole[i]) continue;
        // Premultiplied "over": a line on a transparent sheet is opaque ink.
        Rgba& d = image.data()[i];
        const double a = c / 255.0 * s.colour.a / 255.0, da = d.a / 255.0;
        const double oa = a + da * (1 - a);
        auto mix = [&](double line, double under) {
          return static_cast<std::uint8_t>(std::clamp(
              std::lround((line * a + under * da * (1 - a)) / std::max(oa, 1e-9)), 0L, 255L));
        };
        d = {mix(s.colour.r, d.r), mix(s.colour.g, d.g), mix(s.colour.b, d.b),
             static_cast<std::uint8_t>(std::lround(oa * 255))};
      }
  }
}

}  // namespace hair25d::completion::detail
