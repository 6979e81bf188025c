#include "hair25d/core/strokes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "hair25d/core/atomic_file.h"
#include "json_read.h"

namespace hair25d {

namespace jr = json_read;
using nlohmann::json;

inline constexpr const char* kStrokesFormat = "hair25d-strokes/1";

std::vector<int> Strokes::labels() const {
  std::vector<int> out;
  for (const Stroke& s : strokes) {
    if (s.label > 0) out.push_back(s.label);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

Strokes parse_strokes(const std::string& text, const std::string& source) {
  const json doc = jr::parse(text, source);
  jr::expect_object(doc, source, "");
  const std::string format = jr::as_string(jr::member(doc, source, "", "format"), source, "format");
  if (format != kStrokesFormat) {
    jr::fail(source, "format", std::string("\"") + kStrokesFormat + "\"", &doc["format"]);
  }
  Strokes out;
  out.source = source;
  if (const json* head = jr::optional_member(doc, source, "", "head_center")) {
    out.head_center = jr::as_point(*head, source, "head_center");
  }
  const json& list = jr::member(doc, source, "", "strokes");
  jr::expect_array(list, source, "strokes");
  if (list.size() > kMaxStrokes) {
    jr::fail(source, "strokes", "at most " + std::to_string(kMaxStrokes) + " strokes", &list);
  }
  std::size_t total_points = 0;
  std::set<int> labels;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string at = jr::index("strokes", i);
    const json& item = list[i];
    jr::expect_object(item, source, at);
    Stroke s;
    s.label = jr::as_int(jr::member(item, source, at, "label"), source, jr::join(at, "label"));
    if (s.label < 0) jr::fail(source, jr::join(at, "label"), "an integer >= 0", &item["label"]);
    s.width = jr::as_number(jr::member(item, source, at, "width"), source, jr::join(at, "width"));
    if (s.width < 1.0) jr::fail(source, jr::join(at, "width"), "a number >= 1", &item["width"]);
    const std::string pkey = jr::join(at, "points");
    const json& points = jr::member(item, source, at, "points");
    jr::expect_array(points, source, pkey);
    if (points.empty()) jr::fail(source, pkey, "at least one point", &points);
    total_points += points.size();
    if (total_points > kMaxStrokePoints) {
      jr::fail(source, pkey,
               "at most " + std::to_string(kMaxStrokePoints) + " points in all strokes together",
               &points);
    }
    if (s.label > 0 && labels.insert(s.label).second && labels.size() > kMaxStrokeLabels) {
      jr::fail(source, jr::join(at, "label"),
               "at most " + std::to_string(kMaxStrokeLabels) + " different labels in all strokes",
               &item["label"]);
    }
    for (std::size_t k = 0; k < points.size(); ++k) {
      s.points.push_back(jr::as_point(points[k], source, jr::index(pkey, k)));
    }
    out.strokes.push_back(std::move(s));
  }
  return out;
}

Strokes read_strokes(const std::filesystem::path& path) {
  return parse_strokes(read_text_file(path), path.string());
}

void write_strokes(const std::filesystem::path& path, const Strokes& strokes) {
  json doc;
  doc["format"] = kStrokesFormat;
  if (strokes.head_center)
    doc["head_center"] = {strokes.head_center->x(), strokes.head_center->y()};
  json list = json::array();
  for (const Stroke& s : strokes.strokes) {
    json points = json::array();
    for (const Vec2& p : s.points) points.push_back({p.x(), p.y()});
    list.push_back({{"label", s.label}, {"width", s.width}, {"points", points}});
  }
  doc["strokes"] = list;
  write_text_atomically(path, doc.dump(1) + "\n");
}

namespace {

// Clips segment a-b to the box [lo, hi] (Liang-Barsky, in double): the part
// that can reach a pixel when the box is the image grown by the brush radius.
// False when nothing of it lies in the box, or a point is not finite.
bool clip_to_box(Vec2& a, Vec2& b, const Vec2& lo, const Vec2& hi) {
  if (!a.allFinite() || !b.allFinite()) return false;
  // Half the direction, so that points near +-1e308 cannot overflow it;
  // the segment is a + t h for t in [0, 2].
  const Vec2 h = 0.5 * b - 0.5 * a;
  double t0 = 0.0, t1 = 2.0;
  int axis0 = -1, axis1 = -1;  // the axis whose side cut the segment at t0, t1
  double bound0 = 0.0, bound1 = 0.0;
  for (int axis = 0; axis < 2; ++axis) {
    // a + t h within [lo, hi] on this axis.
    for (const bool low : {true, false}) {
      const double p = low ? -h[axis] : h[axis];
      const double bound = low ? lo[axis] : hi[axis];
      const double q = low ? a[axis] - bound : bound - a[axis];
      if (p == 0.0) {
        if (q < 0.0) return false;  // parallel to this side and outside it
      } else if (p < 0.0 && q / p > t0) {
        t0 = q / p, axis0 = axis, bound0 = bound;
      } else if (p > 0.0 && q / p < t1) {
        t1 = q / p, axis1 = axis, bound1 = bound;
      }
    }
  }
  if (t0 > t1) return false;
  // A cut end point takes the side's coordinate exactly and the other one
  // from the slope: a + t h would lose the image in rounding when both ends
  // lie ~1e308 away. The clamp keeps what rounding remains inside the box.
  const Vec2 start = a;
  auto cut = [&](int axis, double bound) {
    const int other = 1 - axis;
    Vec2 out;
    out[axis] = bound;
    out[other] = start[other] + (bound - start[axis]) * (h[other] / h[axis]);
    return Vec2(out.cwiseMax(lo).cwiseMin(hi));
  };
  if (axis0 >= 0) a = cut(axis0, bound0);
  if (axis1 >= 0) b = cut(axis1, bound1);
  return true;
}

// The pixels a round brush of radius r along segment a-b may paint: the
// segment's box grown by r, within the image. False when none.
struct Box {
  int x0 = 0, x1 = -1, y0 = 0, y1 = -1;
  double area() const { return double(x1 - x0 + 1) * double(y1 - y0 + 1); }
};
bool segment_box(int width, int height, Vec2& a, Vec2& b, double r, Box* box) {
  // Only the part of the segment within r of the image can paint a pixel:
  // for a pixel p in the image, the segment's point nearest p lies within r of
  // p, so inside the grown box, and so on the clipped part too. Clipping in
  // double keeps the casts below in int range for points far outside.
  const Vec2 lo(-r, -r), hi(width - 1 + r, height - 1 + r);
  if (!clip_to_box(a, b, lo, hi)) return false;
  box->x0 = std::max(0, static_cast<int>(std::floor(std::min(a.x(), b.x()) - r)));
  box->x1 = std::min(width - 1, static_cast<int>(std::ceil(std::max(a.x(), b.x()) + r)));
  box->y0 = std::max(0, static_cast<int>(std::floor(std::min(a.y(), b.y()) - r)));
  box->y1 = std::min(height - 1, static_cast<int>(std::ceil(std::max(a.y(), b.y()) + r)));
  return box->x0 <= box->x1 && box->y0 <= box->y1;
}

// Paints a round brush of radius r along segment a-b (inclusive) into labels.
void paint_segment(LabelMap& labels, Vec2 a, Vec2 b, double r, int value) {
  Box box;
  if (!segment_box(labels.width(), labels.height(), a, b, r, &box)) return;
  const int x0 = box.x0, x1 = box.x1, y0 = box.y0, y1 = box.y1;
  const Vec2 d = b - a;
  const double len2 = d.squaredNorm();
  const double r2 = r * r;
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      // Pixel (x, y) is sampled at its centre; coordinates name the pixel, so
      // stroke points are centred too.
      const Vec2 p(x, y);
      double t = len2 > 0.0 ? (p - a).dot(d) / len2 : 0.0;
      t = std::clamp(t, 0.0, 1.0);
      if ((p - (a + t * d)).squaredNorm() <= r2) labels.at(x, y) = value;
    }
  }
}

// The brush radius of a stroke: at least kMinBrushRadius, so that any brush
// marks the pixels it passes through. A radius beyond the image's diagonal is clamped to it: from
// any point in the image such a brush already covers the whole image, and the
// clamp keeps absurd widths (1e300) from overflowing the pixel arithmetic.
double brush_radius(const Stroke& s, int width, int height) {
  const double diagonal = std::hypot(double(width), double(height));
  return std::min(std::max(kMinBrushRadius, s.width / 2.0), diagonal);
}

// The segments of a stroke (a dot is one of zero length), a-b in order.
template <typename Visit>
void for_each_segment(const Stroke& s, Visit visit) {
  if (s.points.size() == 1) {
    visit(s.points[0], s.points[0]);
    return;
  }
  for (std::size_t i = 1; i < s.points.size(); ++i) visit(s.points[i - 1], s.points[i]);
}

}  // namespace

LabelMap rasterize_strokes(const Strokes& strokes, int width, int height) {
  // Every segment tests the pixels of its box: measured before painting, so
  // that wide brushes along many points (3000 points of width 1e6 took 52 s
  // on a 1-megapixel drawing) are refused instead of running for hours.
  double work = 0.0;
  for (const Stroke& s : strokes.strokes) {
    const double r = brush_radius(s, width, height);
    for_each_segment(s, [&](Vec2 a, Vec2 b) {
      Box box;
      if (segment_box(width, height, a, b, r, &box)) work += box.area();
    });
  }
  if (work > kMaxBrushWork) {
    char shown[32], limit[32];
    std::snprintf(shown, sizeof shown, "%.3g", work);
    std::snprintf(limit, sizeof limit, "%.3g", kMaxBrushWork);
    throw Error((strokes.source.empty() ? std::string("strokes") : strokes.source) +
                ": painting the strokes would test " + shown + " pixels (each segment's box, " +
                "grown by the brush radius); at most " + limit +
                " are allowed: use fewer points or narrower brushes");
  }
  LabelMap labels(width, height, kNoStroke);
  for (const Stroke& s : strokes.strokes) {
    const double r = brush_radius(s, width, height);
    for_each_segment(s, [&](Vec2 a, Vec2 b) { paint_segment(labels, a, b, r, s.label); });
  }
  return labels;
}

}  // namespace hair25d
