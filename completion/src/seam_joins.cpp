#include "seam_joins.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <set>

#include "bank_crossings.h"
#include "join_paint.h"

namespace hair25d::completion::detail {
namespace {

// The boundaries are followed this far (px) from a meeting point; their
// directions are the mean offsets of the boundary points from kSeamNear on.
constexpr double kSeamReach = 12.0;
constexpr double kSeamNear = 3.0;
// The drawn line's light rim, left unlabelled by the outline assignment, is
// closed by growing the labels this many pixels into label 0.
constexpr int kRimClose = 2;
// A point of the a–b boundary with a pixel of a third label X within this
// (px, in x and y) marks a meeting point of a, b and X; points within
// kEndMerge of a meeting point's mean are one.
constexpr double kMeetNear = 2.0;
constexpr double kEndMerge = 5.0;
// The angles of a seam (degrees).
constexpr double kMinSeamSides = 140.0;
constexpr double kMaxSeamThrough = 150.0;

struct Edgel {
  Vec2 at;
  int kind;   // 0: a–b, 1: a–X, 2: b–X
  int other;  // X (kind 1, 2)
};

double angle_deg(const Vec2& u, const Vec2& v) {
  const double c = std::clamp(u.dot(v), -1.0, 1.0);
  return std::acos(c) * 180.0 / M_PI;
}

// Mean direction (unit) from `at` of the edgels of `pick` (all within
// kSeamReach of it) connected to it; none (zero) with too few.
Vec2 boundary_direction_near(const std::vector<Edgel>& edgels, const std::vector<int>& pick,
                             const Vec2& at) {
  std::vector<char> seen(pick.size(), 0);
  std::deque<int> queue;
  for (std::size_t i = 0; i < pick.size(); ++i)
    if ((edgels[pick[i]].at - at).norm() <= kMeetNear + 0.5) {
      seen[i] = 1;
      queue.push_back(static_cast<int>(i));
    }
  Vec2 sum(0, 0);
  int n = 0;
  while (!queue.empty()) {
    const int i = queue.front();
    queue.pop_front();
    const Vec2 d = edgels[pick[i]].at - at;
    if (d.norm() >= kSeamNear) sum += d.normalized(), ++n;
    for (std::size_t j = 0; j < pick.size(); ++j) {
      if (seen[j]) continue;
      const Vec2& q = edgels[pick[j]].at;
      if ((q - edgels[pick[i]].at).norm() > 1.05 || (q - at).norm() > kSeamReach) continue;
      seen[j] = 1;
      queue.push_back(static_cast<int>(j));
    }
  }
  if (n < 3 || sum.norm() < 1e-9) return Vec2(0, 0);
  return sum.normalized();
}

// The same over the edgels of `pick` within kSeamReach of `at`.
Vec2 boundary_direction(const std::vector<Edgel>& edgels, const std::vector<int>& pick,
                        const Vec2& at) {
  std::vector<int> near;
  for (int i : pick)
    if ((edgels[i].at - at).norm() <= kSeamReach) near.push_back(i);
  return boundary_direction_near(edgels, near, at);
}

}  // namespace

cv::Mat closed_labels(const Context& ctx, const cv::Rect& box) {
  cv::Mat lab(box.height, box.width, CV_32S);
  std::vector<cv::Point> frontier;
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) {
      lab.at<int>(y, x) = ctx.labels.at(x + box.x, y + box.y);
      if (lab.at<int>(y, x) != 0) frontier.push_back({x, y});
    }
  for (int step = 0; step < kRimClose; ++step) {
    std::vector<std::pair<cv::Point, int>> grown;
    for (const cv::Point& p : frontier)
      for (const cv::Point d :
           {cv::Point(1, 0), cv::Point(-1, 0), cv::Point(0, 1), cv::Point(0, -1)}) {
        const cv::Point q = p + d;
        if (q.x < 0 || q.y < 0 || q.x >= box.width || q.y >= box.height) continue;
        if (lab.at<int>(q) == 0) grown.push_back({q, lab.at<int>(p)});
      }
    frontier.clear();
    for (const auto& [q, l] : grown)
      if (lab.at<int>(q) == 0) lab.at<int>(q) = l, frontier.push_back(q);
  }
  return lab;
}

cv::Rect contact_box(const Context& ctx, int a, int b, int reach) {
  const auto ia = ctx.regions.find(a), ib = ctx.regions.find(b);
  if (ia == ctx.regions.end() || ib == ctx.regions.end()) return {};
  const int margin = kRimClose + 3;
  const cv::Rect near_a(ia->second.box.x - margin, ia->second.box.y - margin,
                        ia->second.box.width + 2 * margin, ia->second.box.height + 2 * margin);
  const cv::Rect near_b(ib->second.box.x - margin, ib->second.box.y - margin,
                        ib->second.box.width + 2 * margin, ib->second.box.height + 2 * margin);
  const cv::Rect contact = near_a & near_b;
  if (contact.empty()) return {};
  const int r = reach + margin;
  cv::Rect box(contact.x - r, contact.y - r, contact.width + 2 * r, contact.height + 2 * r);
  return box & cv::Rect(0, 0, ctx.labels.width(), ctx.labels.height());
}

std::vector<SeamEnd> seam_ends(const Context& ctx, int a, int b) {
  const cv::Rect box = contact_box(ctx, a, b, static_cast<int>(std::ceil(kSeamReach)));
  if (box.empty()) return {};
  // The labels in the box, the unlabelled rims closed.
  const cv::Mat lab = closed_labels(ctx, box);
  // Boundary points between labels (pixel-corner coordinates: pixel (x, y)
  // covers [x, x + 1) x [y, y + 1)).
  std::vector<Edgel> edgels;
  const auto add = [&](int l, int m, const Vec2& at) {
    if (l == m) return;
    if (l != a && l != b) std::swap(l, m);
    if (l != a && l != b) return;
    if (m == a || m == b) {
      edgels.push_back({at, 0, 0});
    } else {
      edgels.push_back({at, l == a ? 1 : 2, m});
    }
  };
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) {
      const Vec2 o(x + box.x, y + box.y);
      if (x + 1 < box.width) add(lab.at<int>(y, x), lab.at<int>(y, x + 1), o + Vec2(1.0, 0.5));
      if (y + 1 < box.height) add(lab.at<int>(y, x), lab.at<int>(y + 1, x), o + Vec2(0.5, 1.0));
    }
  std::vector<int> ab;
  std::map<int, std::vector<int>> ax, bx;
  for (std::size_t i = 0; i < edgels.size(); ++i) {
    const Edgel& e = edgels[i];
    if (e.kind == 0)
      ab.push_back(static_cast<int>(i));
    else
      (e.kind == 1 ? ax : bx)[e.other].push_back(static_cast<int>(i));
  }
  std::vector<SeamEnd> out;
  // Meeting points: a–b boundary points with a pixel of a third label X
  // within kMeetNear (its boundaries with a and with b pass there).
  std::map<int, std::vector<std::pair<Vec2, int>>> ends_of;  // X -> (sum, count)
  const int r = static_cast<int>(kMeetNear);
  for (int i : ab) {
    const Vec2& p = edgels[i].at;
    const int cx = static_cast<int>(std::floor(p.x())) - box.x;
    const int cy = static_cast<int>(std::floor(p.y())) - box.y;
    std::set<int> thirds;
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        const int x = cx + dx, y = cy + dy;
        if (x < 0 || y < 0 || x >= box.width || y >= box.height) continue;
        const int l = lab.at<int>(y, x);
        if (l != a && l != b) thirds.insert(l);
      }
    for (int x : thirds) {
      auto& ends = ends_of[x];
      bool merged = false;
      for (auto& [sum, n] : ends)
        if ((sum / n - p).norm() <= kEndMerge) {
          sum += p, ++n, merged = true;
          break;
        }
      if (!merged) ends.push_back({p, 1});
    }
  }
  for (const auto& [x, ends] : ends_of) {
    const auto ita = ax.find(x), itb = bx.find(x);
    if (ita == ax.end() || itb == bx.end()) continue;
    const std::vector<int>& list_a = ita->second;
    const std::vector<int>& list_b = itb->second;
    for (const auto& [sum, n] : ends) {
      const Vec2 at = sum / n;
      const Vec2 da = boundary_direction(edgels, list_a, at);
      const Vec2 db = boundary_direction(edgels, list_b, at);
      const Vec2 dab = boundary_direction(edgels, ab, at);
      if (da.isZero() || db.isZero() || dab.isZero()) continue;
      SeamEnd end;
      end.at = at;
      end.third = x;
      end.sides = angle_deg(da, db);
      end.through = std::max(angle_deg(dab, da), angle_deg(dab, db));
      out.push_back(end);
    }
  }
  return out;
}

bool seam_geometry(const Context& ctx, int a, int b, const std::function<bool(int, int)>& above) {
  for (const SeamEnd& e : seam_ends(ctx, a, b)) {
    if (e.third != 0 && (above(e.third, a) || above(e.third, b))) continue;
    if (e.sides >= kMinSeamSides && e.through <= kMaxSeamThrough) return true;
  }
  return false;
}

}  // namespace hair25d::completion::detail
