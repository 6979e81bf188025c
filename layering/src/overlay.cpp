#include "hair25d/layering/overlay.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <set>

#include "hair25d/core/error.h"

namespace hair25d::layering {
namespace {

cv::Scalar tint_of(int label) {
  // A fixed hash of the id to a pale colour, so the same region keeps its colour.
  const unsigned h = static_cast<unsigned>(label) * 2654435761u;
  return cv::Scalar(80 + (h & 0x7f), 80 + ((h >> 8) & 0x7f), 80 + ((h >> 16) & 0x7f));
}

cv::Point to_cv(const Vec2& p) {
  return cv::Point(static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y())));
}

bool has_label_near(const LabelMap& labels, const Vec2& p, int radius, int label) {
  const int cx = static_cast<int>(std::lround(p.x())), cy = static_cast<int>(std::lround(p.y()));
  for (int y = cy - radius; y <= cy + radius; ++y)
    for (int x = cx - radius; x <= cx + radius; ++x)
      if (labels.contains(x, y) && labels.at(x, y) == label) return true;
  return false;
}

// Where two regions come closest, for relations that carry no anchor of their
// own (neighbours across a sliver, pairs the user fixed, pairs the tool missed):
// the middle of the closest pair of their edge pixels, normal from a to b.
class MeetingPoints {
 public:
  explicit MeetingPoints(const LabelMap& labels) {
    for (int y = 0; y < labels.height(); ++y)
      for (int x = 0; x < labels.width(); ++x) {
        const int l = labels.at(x, y);
        if (l <= 0) continue;
        const bool edge = x == 0 || y == 0 || x + 1 == labels.width() || y + 1 == labels.height() ||
                          labels.at(x - 1, y) != l || labels.at(x + 1, y) != l ||
                          labels.at(x, y - 1) != l || labels.at(x, y + 1) != l;
        if (edge) edges_[l].emplace_back(x, y);
      }
  }

  std::optional<RelationAnchor> between(int a, int b) const {
    const auto ia = edges_.find(a), ib = edges_.find(b);
    if (ia == edges_.end() || ib == edges_.end()) return std::nullopt;
    const std::vector<Vec2> pa = sample(ia->second), pb = sample(ib->second);
    double best = std::numeric_limits<double>::infinity();
    Vec2 from = Vec2::Zero(), to = Vec2::Zero();
    for (const Vec2& p : pa)
      for (const Vec2& q : pb)
        if (const double d = (p - q).squaredNorm(); d < best) best = d, from = p, to = q;
    const Vec2 d = to - from;
    return RelationAnchor{0.5 * (from + to),
                          d.squaredNorm() > 0 ? Vec2(d.normalized()) : Vec2(1, 0)};
  }

 private:
  // At most ~500 pixels per region: the closest pair is then found within a
  // few pixels for any region, at a bounded cost per pair.
  static std::vector<Vec2> sample(const std::vector<Vec2>& all) {
    const std::size_t step = std::max<std::size_t>(1, all.size() / 500);
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < all.size(); i += step) out.push_back(all[i]);
    return out;
  }
  std::map<int, std::vector<Vec2>> edges_;
};

}  // namespace

Image render_overlay(const Image& image, const Result& result,
                     const std::vector<std::pair<int, int>>& wrong) {
  const LabelMap& labels = result.labels;
  if (image.width() != labels.width() || image.height() != labels.height())
    throw Error("layering::render_overlay: image is " + std::to_string(image.width()) + "x" +
                std::to_string(image.height()) + " but the result's labels are " +
                std::to_string(labels.width()) + "x" + std::to_string(labels.height()) +
                "; they must match");
  try {
    cv::Mat canvas(image.height(), image.width(), CV_8UC3);
    for (int y = 0; y < image.height(); ++y) {
      for (int x = 0; x < image.width(); ++x) {
        const Rgba& p = image.at(x, y);
        cv::Vec3b& c = canvas.at<cv::Vec3b>(y, x);
        const int l = labels.at(x, y);
        // Faded drawing over white paper (transparent = paper); hair regions
        // tinted so pieces can be told apart.
        const double a = p.a / 255.0;
        double r = 0.5 * (a * p.r + (1 - a) * 255) + 127;
        double g = 0.5 * (a * p.g + (1 - a) * 255) + 127;
        double b = 0.5 * (a * p.b + (1 - a) * 255) + 127;
        if (l > 0) {
          const cv::Scalar t = tint_of(l);
          r = 0.55 * r + 0.45 * t[2];
          g = 0.55 * g + 0.45 * t[1];
          b = 0.55 * b + 0.45 * t[0];
        }
        c = cv::Vec3b(cv::saturate_cast<uchar>(b), cv::saturate_cast<uchar>(g),
                      cv::saturate_cast<uchar>(r));
      }
    }
    const int thick = std::max(1, static_cast<int>(std::lround(result.line_width / 3)));
    for (std::size_t i = 0; i < result.graph.boundaries.size(); ++i) {
      const Boundary& b = result.graph.boundaries[i];
      const BoundaryReport& rep = result.boundaries[i];
      if (b.left == kOutsideLabel || b.right == kOutsideLabel || b.points.size() < 2) continue;
      // Occluding: dark blue; non-occluding (cusp-making): orange.
      const cv::Scalar colour = rep.occluding ? cv::Scalar(120, 40, 20) : cv::Scalar(0, 140, 255);
      std::vector<cv::Point> pts;
      for (const Vec2& p : b.points) pts.push_back(to_cv(p));
      cv::polylines(canvas, pts, b.closed(), colour, thick, cv::LINE_AA);
    }
    for (const Junction& j : result.graph.junctions)
      cv::circle(canvas, to_cv(j.position), thick + 1, cv::Scalar(0, 160, 0), cv::FILLED);

    std::set<std::pair<int, int>> bad;
    for (auto [a, b] : wrong) bad.emplace(std::min(a, b), std::max(a, b));
    const double size = std::max(10.0, 3.0 * result.line_width);
    const int near = static_cast<int>(std::ceil(std::max(3.0, 2.0 * result.line_width)));
    const MeetingPoints meeting(labels);
    std::set<std::pair<int, int>> drawn;
    for (std::size_t k = 0; k < result.relations.size(); ++k) {
      const RegionRelation& r = result.relations[k];
      drawn.emplace(std::min(r.a, r.b), std::max(r.a, r.b));
      RelationAnchor an = k < result.anchors.size() ? result.anchors[k] : RelationAnchor{};
      if (!has_label_near(labels, an.point, near, r.a) ||
          !has_label_near(labels, an.point, near, r.b)) {
        const std::optional<RelationAnchor> found = meeting.between(r.a, r.b);
        if (!found) continue;
        an = *found;
      }
      const bool is_bad = bad.contains({std::min(r.a, r.b), std::max(r.a, r.b)});
      const cv::Scalar colour = r.overridden   ? cv::Scalar(200, 0, 200)
                                : r.user_fixed ? cv::Scalar(200, 120, 0)
                                               : cv::Scalar(20, 20, 20);
      if (r.relation == Relation::kEqual) {
        const Vec2 t(-an.normal.y(), an.normal.x());
        for (double off : {-0.25, 0.25}) {
          const Vec2 c = an.point + off * size * an.normal;
          cv::line(canvas, to_cv(c - 0.4 * size * t), to_cv(c + 0.4 * size * t), colour,
                   std::max(2, thick), cv::LINE_AA);
        }
      } else {
        // Occludee → occluder: from b's side into a's when a is above.
        const Vec2 dir = r.relation == Relation::kAbove ? Vec2(-an.normal) : an.normal;
        cv::arrowedLine(canvas, to_cv(an.point - 0.6 * size * dir),
                        to_cv(an.point + 0.6 * size * dir), colour, std::max(2, thick), cv::LINE_AA,
                        0, 0.4);
      }
      if (is_bad)
        cv::circle(canvas, to_cv(an.point), static_cast<int>(size), cv::Scalar(0, 0, 255),
                   std::max(2, thick), cv::LINE_AA);
      cv::putText(canvas, std::to_string(r.a) + "/" + std::to_string(r.b),
                  to_cv(an.point + Vec2(0.7 * size, -0.3 * size)), cv::FONT_HERSHEY_PLAIN,
                  std::max(0.8, size / 20.0), cv::Scalar(90, 30, 90), 1, cv::LINE_AA);
    }
    // Wrong pairs the tool did not relate at all: a red "?" where they meet.
    for (const auto& [a, b] : bad) {
      if (drawn.contains({a, b})) continue;
      const std::optional<RelationAnchor> at = meeting.between(a, b);
      if (!at) continue;
      cv::circle(canvas, to_cv(at->point), static_cast<int>(size), cv::Scalar(0, 0, 255),
                 std::max(2, thick), cv::LINE_AA);
      cv::putText(canvas, "?", to_cv(at->point + Vec2(-0.3 * size, 0.4 * size)),
                  cv::FONT_HERSHEY_PLAIN, std::max(0.8, size / 12.0), cv::Scalar(0, 0, 255),
                  std::max(1, thick), cv::LINE_AA);
      cv::putText(canvas, std::to_string(a) + "/" + std::to_string(b),
                  to_cv(at->point + Vec2(0.7 * size, -0.3 * size)), cv::FONT_HERSHEY_PLAIN,
                  std::max(0.8, size / 20.0), cv::Scalar(90, 30, 90), 1, cv::LINE_AA);
    }
    Image out(image.width(), image.height());
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) {
        const cv::Vec3b& c = canvas.at<cv::Vec3b>(y, x);
        out.at(x, y) = Rgba{c[2], c[1], c[0], 255};
      }
    return out;
  } catch (const cv::Exception& e) {
    throw Error(std::string("layering::render_overlay: OpenCV failed: ") + e.what());
  }
}

}  // namespace hair25d::layering
