#include "hair25d/pipeline/eval_overlay.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "hair25d/core/error.h"
#include "label_layout.h"

namespace hair25d::pipeline {
namespace {

using detail::Box;
using detail::box_around;

// Output pixels on the long side a smaller drawing is scaled up to: a
// 640 x 480 case drawn at its own size leaves 10-px labels that dense
// junctions bury.
constexpr double kTargetLongSide = 1200.0;
constexpr double kMaxScale = 4.0;
const cv::Scalar kInk(30, 30, 30);
const cv::Scalar kRed(0, 0, 220);
const cv::Scalar kPaper(255, 255, 255);
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;

cv::Point to_cv(const Vec2& p) {
  return {static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y()))};
}

cv::Scalar tint_of(int label) {
  // A fixed hash of the id to a pale colour, so a region keeps its colour
  // from run to run (the same as layering's own overlay).
  const unsigned h = static_cast<unsigned>(label) * 2654435761u;
  return cv::Scalar(80 + (h & 0x7f), 80 + ((h >> 8) & 0x7f), 80 + ((h >> 16) & 0x7f));
}

bool has_label_near(const LabelMap& labels, const Vec2& p, int radius, int label) {
  const int cx = static_cast<int>(std::lround(p.x())), cy = static_cast<int>(std::lround(p.y()));
  for (int y = cy - radius; y <= cy + radius; ++y)
    for (int x = cx - radius; x <= cx + radius; ++x)
      if (labels.contains(x, y) && labels.at(x, y) == label) return true;
  return false;
}

// Per region: its edge pixels (to find where two regions come closest, for
// pairs without a boundary of their own) and its most inside pixel (where its
// id is written).
struct RegionPlaces {
  std::map<int, std::vector<Vec2>> edges;
  std::map<int, Vec2> inside;

  explicit RegionPlaces(const LabelMap& labels) {
    const int w = labels.width(), h = labels.height();
    cv::Mat not_edge(h, w, CV_8U, cv::Scalar(0));
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int l = labels.at(x, y);
        if (l <= 0) continue;
        const bool edge = x == 0 || y == 0 || x + 1 == w || y + 1 == h ||
                          labels.at(x - 1, y) != l || labels.at(x + 1, y) != l ||
                          labels.at(x, y - 1) != l || labels.at(x, y + 1) != l;
        if (edge)
          edges[l].emplace_back(x, y);
        else
          not_edge.at<uchar>(y, x) = 255;
      }
    cv::Mat depth;
    cv::distanceTransform(not_edge, depth, cv::DIST_L2, 3);
    std::map<int, float> best;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int l = labels.at(x, y);
        if (l <= 0) continue;
        const float d = depth.at<float>(y, x);
        if (auto it = best.find(l); it == best.end() || d > it->second) {
          best[l] = d;
          inside[l] = Vec2(x + 0.5, y + 0.5);
        }
      }
  }

  std::optional<layering::RelationAnchor> between(int a, int b) const {
    const auto ia = edges.find(a), ib = edges.find(b);
    if (ia == edges.end() || ib == edges.end()) return std::nullopt;
    // ~500 pixels a region: the closest pair within a few pixels, bounded cost.
    const std::size_t sa = std::max<std::size_t>(1, ia->second.size() / 500);
    const std::size_t sb = std::max<std::size_t>(1, ib->second.size() / 500);
    double best = std::numeric_limits<double>::infinity();
    Vec2 from = Vec2::Zero(), to = Vec2::Zero();
    for (std::size_t i = 0; i < ia->second.size(); i += sa)
      for (std::size_t j = 0; j < ib->second.size(); j += sb)
        if (const double d = (ia->second[i] - ib->second[j]).squaredNorm(); d < best)
          best = d, from = ia->second[i], to = ib->second[j];
    const Vec2 d = to - from;
    return layering::RelationAnchor{0.5 * (from + to) + Vec2(0.5, 0.5),
                                    d.squaredNorm() > 0 ? Vec2(d.normalized()) : Vec2(1, 0)};
  }
};

// One pair to draw: its mark at `at` (output pixels) and its label.
struct Mark {
  Vec2 at = Vec2::Zero();
  Vec2 normal = Vec2(1, 0);  // from a's side into b's
  int a = 0, b = 0;
  std::optional<Relation> relation;  // none: a wrong pair the layering did not relate
  cv::Scalar colour = kInk;
  bool wrong = false;
  double size = 0.0;  // arrow length
  bool dot = false;   // no room for an arrow: a dot, the label says the relation
  std::string text;
  Box label;
};

std::string pair_text(int a, int b, std::optional<Relation> r) {
  if (!r) return std::to_string(a) + "?" + std::to_string(b);
  if (*r == Relation::kEqual) return std::to_string(a) + "=" + std::to_string(b);
  // Always "upper>lower", whichever way round the pair is stored.
  return *r == Relation::kAbove ? std::to_string(a) + ">" + std::to_string(b)
                                : std::to_string(b) + ">" + std::to_string(a);
}

class Painter {
 public:
  Painter(cv::Mat& canvas, double font_px) : canvas_(canvas), font_px_(font_px) {}

  double scale() const { return font_px_ / 22.0; }  // SIMPLEX capitals are ~22 px at 1.0
  int weight() const { return std::max(1, static_cast<int>(std::lround(font_px_ / 14.0))); }

  cv::Size text_size(const std::string& text, double rel = 1.0) const {
    int base = 0;
    return cv::getTextSize(text, kFont, scale() * rel, weight(), &base);
  }

  // Text whose box's top-left corner is `corner`, on a white plate.
  void plate(const std::string& text, const Box& box, const cv::Scalar& colour, bool bold) {
    cv::Mat roi = canvas_(cv::Rect(cv::Point(static_cast<int>(box.x0), static_cast<int>(box.y0)),
                                   cv::Point(static_cast<int>(std::ceil(box.x1)),
                                             static_cast<int>(std::ceil(box.y1)))) &
                          cv::Rect(0, 0, canvas_.cols, canvas_.rows));
    roi = 0.15 * roi + 0.85 * cv::Mat(roi.size(), roi.type(), kPaper);
    cv::rectangle(canvas_, to_cv({box.x0, box.y0}), to_cv({box.x1, box.y1}), colour, 1,
                  cv::LINE_AA);
    const cv::Size s = text_size(text);
    const Vec2 origin(0.5 * (box.x0 + box.x1 - s.width), 0.5 * (box.y0 + box.y1 + s.height));
    cv::putText(canvas_, text, to_cv(origin), kFont, scale(), colour, weight() + (bold ? 1 : 0),
                cv::LINE_AA);
  }

  // Text with a white halo, its baseline's left end at `origin`.
  void halo(const std::string& text, const Vec2& origin, double rel, const cv::Scalar& colour) {
    const int w = std::max(1, static_cast<int>(std::lround(weight() * rel)));
    cv::putText(canvas_, text, to_cv(origin), kFont, scale() * rel, kPaper, w + 2, cv::LINE_AA);
    cv::putText(canvas_, text, to_cv(origin), kFont, scale() * rel, colour, w, cv::LINE_AA);
  }

 private:
  cv::Mat& canvas_;
  double font_px_;
};

}  // namespace

Image render_eval_overlay(const Image& image, const layering::Result& result,
                          const layering::CaseScore& score) {
  const LabelMap& labels = result.labels;
  if (image.width() != labels.width() || image.height() != labels.height() || image.empty())
    throw Error("eval-layering overlay: the drawing is " + std::to_string(image.width()) + "x" +
                std::to_string(image.height()) + " but the result's labels are " +
                std::to_string(labels.width()) + "x" + std::to_string(labels.height()) +
                "; they must match and not be empty");
  try {
    const int long_side = std::max(image.width(), image.height());
    const double k = std::clamp(kTargetLongSide / long_side, 1.0, kMaxScale);
    const double font_px = std::clamp(k * long_side / 75.0, 11.0, 28.0);
    const int line = std::max(2, static_cast<int>(std::lround(font_px / 8)));

    // The faded drawing over white paper (transparent = paper), hair regions tinted.
    cv::Mat small(image.height(), image.width(), CV_8UC3);
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) {
        const Rgba& p = image.at(x, y);
        const double a = p.a / 255.0;
        cv::Vec3d c(0.5 * (a * p.b + (1 - a) * 255) + 127, 0.5 * (a * p.g + (1 - a) * 255) + 127,
                    0.5 * (a * p.r + (1 - a) * 255) + 127);
        if (const int l = labels.at(x, y); l > 0) {
          const cv::Scalar t = tint_of(l);
          for (int ch = 0; ch < 3; ++ch) c[ch] = 0.55 * c[ch] + 0.45 * t[ch];
        }
        small.at<cv::Vec3b>(y, x) =
            cv::Vec3b(cv::saturate_cast<uchar>(c[0]), cv::saturate_cast<uchar>(c[1]),
                      cv::saturate_cast<uchar>(c[2]));
      }
    const int draw_w = static_cast<int>(std::lround(image.width() * k));
    const int draw_h = static_cast<int>(std::lround(image.height() * k));
    Painter measure_only(small, font_px);
    // The caption needs its width even under a thin drawing.
    const int out_w = std::max(draw_w, measure_only.text_size(std::string(34, 'm')).width);
    cv::Mat drawing(draw_h, out_w, CV_8UC3, kPaper);
    cv::Mat scaled;
    cv::resize(small, scaled, cv::Size(draw_w, draw_h), 0, 0,
               k > 1.0 ? cv::INTER_LINEAR : cv::INTER_NEAREST);
    scaled.copyTo(drawing(cv::Rect(0, 0, draw_w, draw_h)));
    Painter painter(drawing, font_px);
    const auto out_px = [k](const Vec2& p) -> Vec2 { return p * k; };

    // Boundaries: occluding dark blue, non-occluding (cusp-making) orange.
    const int thin = std::max(1, static_cast<int>(std::lround(k * result.line_width / 3)));
    for (std::size_t i = 0; i < result.graph.boundaries.size(); ++i) {
      const layering::Boundary& b = result.graph.boundaries[i];
      if (b.left == layering::kOutsideLabel || b.right == layering::kOutsideLabel ||
          b.points.size() < 2 || i >= result.boundaries.size())
        continue;
      const cv::Scalar colour =
          result.boundaries[i].occluding ? cv::Scalar(120, 40, 20) : cv::Scalar(0, 140, 255);
      std::vector<cv::Point> pts;
      for (const Vec2& p : b.points) pts.push_back(to_cv(out_px(p)));
      cv::polylines(drawing, pts, b.closed(), colour, thin, cv::LINE_AA);
    }
    for (const layering::Junction& j : result.graph.junctions)
      cv::circle(drawing, to_cv(out_px(j.position)), thin + 1, cv::Scalar(0, 160, 0), cv::FILLED);

    // Region ids, small and grey, at each region's most inside pixel.
    const RegionPlaces places(labels);
    std::vector<Box> taken;
    for (const auto& [id, at] : places.inside) {
      const std::string text = std::to_string(id);
      const cv::Size s = painter.text_size(text, 0.75);
      const Vec2 c = out_px(at);
      painter.halo(text, c + Vec2(-0.5 * s.width, 0.5 * s.height), 0.75, cv::Scalar(90, 90, 90));
      taken.push_back(box_around(c, 0.5 * s.width + 1, 0.5 * s.height + 1));
    }

    // One mark per relation, and one per wrong pair the layering left unrelated.
    std::map<std::pair<int, int>, const layering::PairOutcome*> wrong;
    for (const layering::PairOutcome& o : score.outcomes)
      if (!o.correct) wrong[{std::min(o.a, o.b), std::max(o.a, o.b)}] = &o;
    const int near = static_cast<int>(std::ceil(std::max(3.0, 2.0 * result.line_width)));
    std::vector<Mark> marks;
    std::set<std::pair<int, int>> related;
    for (std::size_t i = 0; i < result.relations.size(); ++i) {
      const RegionRelation& r = result.relations[i];
      related.emplace(std::min(r.a, r.b), std::max(r.a, r.b));
      layering::RelationAnchor an =
          i < result.anchors.size() ? result.anchors[i] : layering::RelationAnchor{};
      if (!has_label_near(labels, an.point, near, r.a) ||
          !has_label_near(labels, an.point, near, r.b)) {
        const auto found = places.between(r.a, r.b);
        if (!found) continue;
        an = *found;
      }
      Mark m;
      m.at = out_px(an.point);
      m.normal = an.normal;
      m.a = r.a, m.b = r.b;
      m.relation = r.relation;
      m.wrong = wrong.contains({std::min(r.a, r.b), std::max(r.a, r.b)});
      m.colour = m.wrong        ? kRed
                 : r.overridden ? cv::Scalar(200, 0, 200)
                 : r.user_fixed ? cv::Scalar(200, 120, 0)
                                : kInk;
      m.text = pair_text(r.a, r.b, r.relation);
      marks.push_back(m);
    }
    for (const auto& [pair, outcome] : wrong) {
      if (related.contains(pair)) continue;
      const auto at = places.between(pair.first, pair.second);
      if (!at) continue;
      Mark m;
      m.at = out_px(at->point);
      m.a = pair.first, m.b = pair.second;
      m.wrong = true;
      m.colour = kRed;
      m.text = pair_text(pair.first, pair.second, std::nullopt);
      marks.push_back(m);
    }
    // Arrows as long as the text is high; where a neighbour is closer than
    // that (dense junctions) a dot instead, tied to its label by a leader
    // line: arrows squeezed there could not be told apart.
    const double full = 1.5 * font_px;
    for (Mark& m : marks) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const Mark& o : marks)
        if (&o != &m) nearest = std::min(nearest, (o.at - m.at).norm());
      m.dot = nearest < 1.1 * full;
      m.size = m.dot ? std::max(5.0, 0.4 * font_px) : full;
    }
    std::vector<detail::LabelRequest> requests;
    const double pad = std::max(2.0, font_px / 5);
    for (const Mark& m : marks) {
      const cv::Size s = painter.text_size(m.text);
      requests.push_back({m.at, m.wrong ? (m.dot ? 1.0 : 0.7) * m.size + 2 : 0.5 * m.size,
                          0.5 * s.width + pad, 0.5 * s.height + pad, m.wrong});
    }
    const std::vector<Box> label_boxes = detail::place_labels(
        requests, taken, Box{0, 0, static_cast<double>(draw_w), static_cast<double>(draw_h)},
        0.5 * font_px);
    for (std::size_t i = 0; i < marks.size(); ++i) marks[i].label = label_boxes[i];

    for (const Mark& m : marks) {
      // Leader line from the mark to a label that had to move away from it,
      // on a white halo so that it shows over dark outlines.
      const Vec2 end = m.label.closest_to(m.at);
      if ((end - m.at).norm() > (m.dot ? 0.9 : 0.75) * m.size) {
        const Vec2 from = m.at + (end - m.at).normalized() * 0.5 * m.size;
        cv::line(drawing, to_cv(from), to_cv(end), kPaper, 3, cv::LINE_AA);
        cv::line(drawing, to_cv(from), to_cv(end), m.colour, 1, cv::LINE_AA);
      }
    }
    for (const Mark& m : marks) {
      const int w = std::max(line, static_cast<int>(std::lround(m.size / 8)));
      if (m.dot && m.relation) {
        cv::circle(drawing, to_cv(m.at), static_cast<int>(std::lround(0.5 * m.size)) + 1, kPaper,
                   cv::FILLED, cv::LINE_AA);
        cv::circle(drawing, to_cv(m.at), static_cast<int>(std::lround(0.5 * m.size)), m.colour,
                   cv::FILLED, cv::LINE_AA);
      } else if (!m.relation) {
        const cv::Size s = painter.text_size("?", 1.2);
        painter.halo("?", m.at + Vec2(-0.5 * s.width, 0.5 * s.height), 1.2, kRed);
      } else if (*m.relation == Relation::kEqual) {
        const Vec2 t(-m.normal.y(), m.normal.x());
        for (double off : {-0.18, 0.18}) {
          const Vec2 c = m.at + off * m.size * m.normal;
          cv::line(drawing, to_cv(c - 0.4 * m.size * t), to_cv(c + 0.4 * m.size * t), m.colour, w,
                   cv::LINE_AA);
        }
      } else {
        // Occludee -> occluder: from b's side into a's when a is above.
        const Vec2 dir = *m.relation == Relation::kAbove ? Vec2(-m.normal) : m.normal;
        cv::arrowedLine(drawing, to_cv(m.at - 0.5 * m.size * dir), to_cv(m.at + 0.5 * m.size * dir),
                        m.colour, w, cv::LINE_AA, 0, 0.45);
      }
      if (m.wrong)  // a small ring round a dot: one red dot among black ones is easy to miss
        cv::circle(drawing, to_cv(m.at),
                   static_cast<int>(std::lround(m.dot ? m.size : 0.7 * m.size + w)), kRed,
                   m.dot ? std::max(1, w / 2) : w, cv::LINE_AA);
    }
    for (const Mark& m : marks) painter.plate(m.text, m.label, m.colour, m.wrong);

    // The caption: case and accuracy, the legend, then every wrong pair.
    std::vector<std::vector<std::string>> paragraphs;
    char head[160];
    std::snprintf(head, sizeof head, "%s: %d of %d judged pairs right (%.1f%%)", score.name.c_str(),
                  score.correct, score.pairs, 100.0 * score.accuracy());
    paragraphs.push_back({head});
    paragraphs.push_back({"arrow: lower region -> upper;", "a>b: region a above b;",
                          "a=b: same depth;", "dot: see label;", "red: wrong pair;",
                          "magenta: flipped to fit the depth order;", "?: pair not related"});
    std::vector<std::string> wrong_words{"wrong:"};
    for (const auto& [pair, o] : wrong)
      wrong_words.push_back(pair_text(o->a, o->b, o->predicted) + " (annotated " +
                            pair_text(o->a, o->b, o->truth) + ");");
    if (!wrong.empty()) wrong_words.back().pop_back();
    if (wrong.empty()) wrong_words.push_back("none");
    paragraphs.push_back(wrong_words);
    const double caption_scale = 0.9;
    const int line_h =
        static_cast<int>(std::lround(1.6 * painter.text_size("Ag", caption_scale).height));
    const int margin = static_cast<int>(std::lround(0.6 * font_px));
    std::vector<std::pair<std::string, bool>> lines;  // text, red
    for (std::size_t p = 0; p < paragraphs.size(); ++p) {
      const bool red = p + 1 == paragraphs.size() && !wrong.empty();
      std::string current;
      for (const std::string& word : paragraphs[p]) {
        const std::string tried = current.empty() ? word : current + " " + word;
        if (!current.empty() &&
            painter.text_size(tried, caption_scale).width > out_w - 2 * margin) {
          lines.emplace_back(current, red);
          current = word;
        } else {
          current = tried;
        }
      }
      lines.emplace_back(current, red);
    }
    cv::Mat caption(line_h * static_cast<int>(lines.size()) + margin, out_w, CV_8UC3, kPaper);
    Painter caption_painter(caption, font_px);
    for (std::size_t i = 0; i < lines.size(); ++i)
      cv::putText(caption, lines[i].first, cv::Point(margin, line_h * static_cast<int>(i + 1)),
                  kFont, caption_painter.scale() * caption_scale, lines[i].second ? kRed : kInk,
                  caption_painter.weight(), cv::LINE_AA);
    cv::line(caption, {0, 0}, {out_w - 1, 0}, cv::Scalar(160, 160, 160), 1);
    cv::Mat canvas;
    cv::vconcat(drawing, caption, canvas);

    Image out(canvas.cols, canvas.rows);
    for (int y = 0; y < canvas.rows; ++y)
      for (int x = 0; x < canvas.cols; ++x) {
        const cv::Vec3b& c = canvas.at<cv::Vec3b>(y, x);
        out.at(x, y) = Rgba{c[2], c[1], c[0], 255};
      }
    return out;
  } catch (const cv::Exception& e) {
    throw Error(std::string("eval-layering overlay: OpenCV failed: ") + e.what());
  }
}

}  // namespace hair25d::pipeline
