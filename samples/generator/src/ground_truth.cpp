#include "ground_truth.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>
#include <opencv2/imgproc.hpp>

#include "render.h"

namespace hair25d::generator {

namespace {

constexpr double kStrokeWidth = 3.0;
// A stroke point keeps this far (pixels, at its nearest pixel centre) from the
// region's edge: 1.5 for the brush radius, 0.71 for the rounding to a pixel,
// and some margin so strokes sit "well inside".
constexpr double kMinDepth = 3.0;
constexpr int kMinContact = 3;  // boundary pixels for two regions to be neighbours
constexpr int kHairStrokes = 3;
constexpr int kBackgroundComponents = 3;
constexpr int kBackgroundStrokes = 2;

struct Component {
  int owner = 0;
  int area = 0;
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // inclusive box
};

// 4-connected pieces of equal owner, line pixels excluded (so a one-pixel
// diagonal line still separates), numbered in scan order of their first pixel.
std::vector<Component> label_components(const cv::Mat& owner, std::vector<int>& comp) {
  const int w = owner.cols, h = owner.rows;
  comp.assign(static_cast<std::size_t>(w) * h, -1);
  const int* own = owner.ptr<int>(0);
  std::vector<Component> out;
  std::vector<int> stack;
  for (int start = 0; start < w * h; ++start) {
    if (own[start] == kLineOwner || comp[start] >= 0) continue;
    Component c;
    c.owner = own[start];
    c.x0 = c.x1 = start % w;
    c.y0 = c.y1 = start / w;
    const int id = static_cast<int>(out.size());
    comp[start] = id;
    stack.assign(1, start);
    while (!stack.empty()) {
      const int p = stack.back();
      stack.pop_back();
      const int x = p % w, y = p / w;
      ++c.area;
      c.x0 = std::min(c.x0, x);
      c.x1 = std::max(c.x1, x);
      c.y0 = std::min(c.y0, y);
      c.y1 = std::max(c.y1, y);
      const int next[4] = {x > 0 ? p - 1 : -1, x + 1 < w ? p + 1 : -1, y > 0 ? p - w : -1,
                           y + 1 < h ? p + w : -1};
      for (int q : next) {
        if (q >= 0 && comp[q] < 0 && own[q] == c.owner) {
          comp[q] = id;
          stack.push_back(q);
        }
      }
    }
    out.push_back(c);
  }
  return out;
}

// Polylines along the middle of component `id`: the deepest pixel of each slice
// across its main axis, joined where the joining segment stays deep inside.
// A stroke along the middle of the candidate area: from its deepest pixel,
// walk both ways in steps, each time to the deepest candidate ahead (turning at
// most 60 degrees) whose segment stays deep inside. It follows bent locks and
// the arc of back hair, as a hand-drawn stroke would.
Polyline ridge_walk(const cv::Mat& dist, const cv::Mat& candidate, double level) {
  double best_depth = -1;
  cv::Point start(-1, -1);
  for (int y = 0; y < dist.rows; ++y) {
    const auto* d = dist.ptr<float>(y);
    const auto* c = candidate.ptr<uchar>(y);
    for (int x = 0; x < dist.cols; ++x) {
      if (c[x] && d[x] > best_depth) {
        best_depth = d[x];
        start = {x, y};
      }
    }
  }
  if (start.x < 0) return {};
  auto depth_at = [&](const Vec2& p) {
    const int x = static_cast<int>(std::lround(p.x())), y = static_cast<int>(std::lround(p.y()));
    if (x < 0 || y < 0 || x >= dist.cols || y >= dist.rows) return -1.0;
    return static_cast<double>(dist.at<float>(y, x));
  };
  auto candidate_at = [&](const Vec2& p) {
    const int x = static_cast<int>(std::lround(p.x())), y = static_cast<int>(std::lround(p.y()));
    return x >= 0 && y >= 0 && x < dist.cols && y < dist.rows && candidate.at<uchar>(y, x) != 0;
  };
  auto deep_enough = [&](const Vec2& a, const Vec2& b) {
    const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() * 2.0)));
    for (int k = 0; k <= steps; ++k) {
      if (depth_at(a + (b - a) * (static_cast<double>(k) / steps)) < kMinDepth) return false;
    }
    return true;
  };
  constexpr int kAngles = 48;
  constexpr int kMaxSteps = 60;
  constexpr double kPi = 3.14159265358979323846;
  const double step = std::clamp(level, 4.0, 14.0);
  const Vec2 origin(start.x, start.y);
  std::vector<Polyline> halves(2);
  Vec2 first_dir(0, 0);
  for (int half = 0; half < 2; ++half) {
    Vec2 p = origin;
    Vec2 dir = half == 0 ? Vec2(0, 0) : Vec2(-first_dir);
    for (int n = 0; n < kMaxSteps; ++n) {
      // Deepest first; the segment test runs only until one passes.
      std::vector<std::pair<double, Vec2>> ahead;
      for (int k = 0; k < kAngles; ++k) {
        const double a = 2.0 * kPi * k / kAngles;
        const Vec2 u(std::cos(a), std::sin(a));
        if (dir.squaredNorm() > 0 && u.dot(dir) < 0.5) continue;  // at most 60 degrees
        const Vec2 q = p + u * step;
        if (candidate_at(q)) ahead.emplace_back(depth_at(q), q);
      }
      std::stable_sort(ahead.begin(), ahead.end(),
                       [](const auto& a, const auto& b) { return a.first > b.first; });
      Vec2 next(0, 0);
      bool found = false;
      for (const auto& [d, q] : ahead) {
        if (deep_enough(p, q)) {
          next = q;
          found = true;
          break;
        }
      }
      if (!found) break;
      // Do not walk back over the other half.
      bool revisit = false;
      for (const Polyline& h : halves) {
        for (const Vec2& q : h) revisit = revisit || (q - next).norm() < 0.7 * step;
      }
      if ((next - origin).norm() < 0.7 * step && n > 0) revisit = true;
      if (revisit) break;
      dir = (next - p).normalized();
      if (half == 0 && n == 0) first_dir = dir;
      halves[half].push_back(next);
      p = next;
    }
    if (half == 0 && halves[0].empty()) break;  // a dot: no direction to go
  }
  Polyline line(halves[1].rbegin(), halves[1].rend());
  line.push_back(origin);
  line.insert(line.end(), halves[0].begin(), halves[0].end());
  for (Vec2& q : line) q = Vec2(std::round(q.x()), std::round(q.y()));
  return line;
}

// Strokes along the middle of component `id`. A region that bends (the back
// hair around a cap, a U-shaped lock) gets more strokes, in the parts the first
// ones leave far away, as a user would mark each arm.
std::vector<Polyline> inner_strokes(const std::vector<int>& comp, int width, int id,
                                    const Component& c, int max_strokes) {
  const int bw = c.x1 - c.x0 + 3, bh = c.y1 - c.y0 + 3;  // one empty pixel around
  cv::Mat mask(bh, bw, CV_8U, cv::Scalar(0));
  for (int y = c.y0; y <= c.y1; ++y) {
    const int* row = comp.data() + static_cast<std::size_t>(y) * width;
    auto* m = mask.ptr<uchar>(y - c.y0 + 1);
    for (int x = c.x0; x <= c.x1; ++x) m[x - c.x0 + 1] = row[x] == id ? 255 : 0;
  }
  cv::Mat dist;
  cv::distanceTransform(mask, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  double dmax = 0;
  cv::minMaxLoc(dist, nullptr, &dmax);
  if (dmax < kMinDepth) return {};
  const double thr = std::max(kMinDepth, 0.5 * dmax);
  // A part counts as covered within this distance of a stroke.
  const double reach = std::max(30.0, 3.0 * thr);

  cv::Mat covered(bh, bw, CV_8U, cv::Scalar(0));
  std::vector<Polyline> out;
  std::size_t inside = 0;  // pixels that could hold a stroke
  for (int y = 0; y < bh; ++y) {
    const auto* d = dist.ptr<float>(y);
    for (int x = 0; x < bw; ++x) inside += d[x] >= kMinDepth;
  }
  while (static_cast<int>(out.size()) < max_strokes) {
    // The uncovered part, and how deep it is: a thin arm left over from a
    // wide region gets a stroke along its own middle.
    double deepest = 0;
    std::size_t left = 0;
    for (int y = 0; y < bh; ++y) {
      const auto* d = dist.ptr<float>(y);
      const auto* cv_row = covered.ptr<uchar>(y);
      for (int x = 0; x < bw; ++x) {
        if (cv_row[x] || d[x] < kMinDepth) continue;
        deepest = std::max(deepest, static_cast<double>(d[x]));
        ++left;
      }
    }
    // Stop when what is left is a small part of the region's inside.
    if (left == 0 || (!out.empty() && left * 12 < inside)) break;
    const double level = out.empty() ? thr : std::max(kMinDepth, 0.5 * deepest);
    cv::Mat candidate = (dist >= level) & (covered == 0);
    Polyline line = ridge_walk(dist, candidate, level);
    if (line.empty()) break;
    std::vector<cv::Point> pts;
    for (const Vec2& p : line) pts.emplace_back(static_cast<int>(p.x()), static_cast<int>(p.y()));
    const int radius = static_cast<int>(reach);
    if (pts.size() == 1) {
      cv::circle(covered, pts[0], radius, cv::Scalar(255), cv::FILLED);
    } else {
      cv::polylines(covered, std::vector{pts}, false, cv::Scalar(255), 2 * radius);
    }
    for (Vec2& p : line) p += Vec2(c.x0 - 1, c.y0 - 1);
    out.push_back(std::move(line));
  }
  return out;
}

// Short strokes on the paper around the hair, a fixed distance from it, one per
// sector around the head: they fence the hair in, which is where a user puts
// background strokes and where a segmentation needs them.
std::vector<Polyline> ring_strokes(const std::vector<int>& comp, int width, int height, int id,
                                   const Vec2& head, double line_width) {
  cv::Mat mask(height, width, CV_8U);
  for (int y = 0; y < height; ++y) {
    const int* row = comp.data() + static_cast<std::size_t>(y) * width;
    auto* m = mask.ptr<uchar>(y);
    for (int x = 0; x < width; ++x) m[x] = row[x] == id ? 255 : 0;
  }
  cv::Mat dist;
  cv::distanceTransform(mask, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  // The image border is not an edge of the paper: measure from drawn shapes only.
  const double ring = std::clamp(4.0 * line_width, 8.0, 24.0);
  constexpr int kSectors = 8;
  constexpr double kTwoPi = 2.0 * 3.14159265358979323846;
  std::vector<Vec2> best(kSectors, Vec2(-1, -1));
  std::vector<double> best_err(kSectors, 1e300);
  for (int y = 0; y < height; ++y) {
    const auto* d = dist.ptr<float>(y);
    for (int x = 0; x < width; ++x) {
      if (std::abs(d[x] - ring) > 0.75) continue;
      const int border = std::min({x, y, width - 1 - x, height - 1 - y});
      if (border < ring) continue;  // measured from the frame, not from a shape
      const double a = std::atan2(y - head.y(), x - head.x()) + kTwoPi / 2;  // 0..2π
      const int sector = std::min(kSectors - 1, static_cast<int>(a / kTwoPi * kSectors));
      const double mid = (sector + 0.5) * kTwoPi / kSectors;
      const double err = std::abs(a - mid);
      if (err < best_err[sector]) {
        best_err[sector] = err;
        best[sector] = Vec2(x, y);
      }
    }
  }
  std::vector<Polyline> out;
  for (const Vec2& p : best) {
    if (p.x() < 0) continue;
    const Vec2 radial = (p - head).normalized();
    const Vec2 tangent(-radial.y(), radial.x());
    Polyline line{p};
    const Vec2 q = p + tangent * std::min(12.0, ring);
    bool ok = true;
    const int steps = 24;
    for (int k = 0; k <= steps && ok; ++k) {
      const Vec2 r = p + (q - p) * (static_cast<double>(k) / steps);
      const int x = static_cast<int>(std::lround(r.x())), y = static_cast<int>(std::lround(r.y()));
      ok = x >= 0 && y >= 0 && x < width && y < height && dist.at<float>(y, x) >= kMinDepth;
    }
    if (ok) line.emplace_back(std::round(q.x()), std::round(q.y()));
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace

GroundTruth make_ground_truth(const Scene& scene, const cv::Mat& owner) {
  const int w = owner.cols, h = owner.rows;
  std::vector<int> comp;
  const std::vector<Component> comps = label_components(owner, comp);
  auto is_hair = [&](const Component& c) {
    return c.owner > 0 && scene.shapes[static_cast<std::size_t>(c.owner) - 1].hair;
  };

  GroundTruth gt;
  gt.strokes.head_center = scene.head_center;
  std::vector<int> region_of(comps.size(), 0);
  for (std::size_t i = 0; i < comps.size(); ++i) {
    if (!is_hair(comps[i])) continue;
    auto lines = inner_strokes(comp, w, static_cast<int>(i), comps[i], kHairStrokes);
    if (lines.empty()) continue;
    const int id = static_cast<int>(gt.region_list.size()) + 1;
    region_of[i] = id;
    const Shape& s = scene.shapes[static_cast<std::size_t>(comps[i].owner) - 1];
    gt.region_list.push_back({id, s.strand, s.name});
    for (Polyline& l : lines) gt.strokes.strokes.push_back({id, kStrokeWidth, std::move(l)});
  }
  // Background strokes on the largest pieces that are not hair (paper, face, body).
  std::vector<std::size_t> others;
  for (std::size_t i = 0; i < comps.size(); ++i) {
    if (!is_hair(comps[i])) others.push_back(i);
  }
  std::stable_sort(others.begin(), others.end(),
                   [&](std::size_t a, std::size_t b) { return comps[a].area > comps[b].area; });
  if (others.size() > static_cast<std::size_t>(kBackgroundComponents)) {
    others.resize(kBackgroundComponents);
  }
  for (std::size_t i : others) {
    for (Polyline& l : inner_strokes(comp, w, static_cast<int>(i), comps[i], kBackgroundStrokes)) {
      gt.strokes.strokes.push_back({0, kStrokeWidth, std::move(l)});
    }
  }
  int paper = -1;  // the largest piece of bare paper
  for (std::size_t i = 0; i < comps.size(); ++i) {
    if (comps[i].owner == 0 && (paper < 0 || comps[i].area > comps[paper].area)) {
      paper = static_cast<int>(i);
    }
  }
  if (paper >= 0) {
    for (Polyline& l : ring_strokes(comp, w, h, paper, scene.head_center, scene.line_width)) {
      gt.strokes.strokes.push_back({0, kStrokeWidth, std::move(l)});
    }
  }

  // Line pixels go to the nearest piece (breadth first), so regions separated
  // only by a line become 4-neighbours. Slivers too thin to be regions still
  // grow as pieces of their own: two regions on either side of a sliver of a
  // third strand do not meet.
  // Growth stops half a line width (plus a pixel) out, so where several
  // outlines pile up into a thick blot of ink the regions around it do not
  // meet: neighbours are at most a line width (plus 3 pixels) apart.
  const int reach = static_cast<int>(std::ceil(scene.line_width / 2.0)) + 1;
  std::vector<int> grown(comp.begin(), comp.end());
  std::vector<int> depth(comp.size(), 0);
  std::vector<int> queue;
  queue.reserve(comp.size());
  for (std::size_t p = 0; p < comp.size(); ++p) {
    if (comp[p] >= 0) queue.push_back(static_cast<int>(p));
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int p = queue[head], x = p % w, y = p / w;
    if (depth[p] >= reach) continue;
    const int next[4] = {x > 0 ? p - 1 : -1, x + 1 < w ? p + 1 : -1, y > 0 ? p - w : -1,
                         y + 1 < h ? p + w : -1};
    for (int q : next) {
      if (q >= 0 && grown[q] < 0) {
        grown[q] = grown[p];
        depth[q] = depth[p] + 1;
        queue.push_back(q);
      }
    }
  }
  std::map<std::pair<int, int>, int> contact;
  auto touch = [&](int p, int q) {
    const int a = grown[p] >= 0 ? region_of[grown[p]] : 0;
    const int b = grown[q] >= 0 ? region_of[grown[q]] : 0;
    if (a > 0 && b > 0 && a != b) ++contact[{std::min(a, b), std::max(a, b)}];
  };
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int p = y * w + x;
      if (x + 1 < w) touch(p, p + 1);
      if (y + 1 < h) touch(p, p + w);
    }
  }
  std::vector<int> owner_of(gt.region_list.size() + 1, 0);
  for (std::size_t i = 0; i < comps.size(); ++i) {
    if (region_of[i] > 0) owner_of[region_of[i]] = comps[i].owner;
  }
  for (const auto& [key, count] : contact) {
    if (count < kMinContact) continue;
    const auto [a, b] = key;
    Relation r = Relation::kEqual;
    if (gt.region_list[a - 1].strand != gt.region_list[b - 1].strand) {
      r = owner_of[a] < owner_of[b] ? Relation::kBelow : Relation::kAbove;
    }
    gt.pairs.push_back({a, b, r});
  }

  gt.regions = LabelMap(w, h, 0);
  for (std::size_t p = 0; p < comp.size(); ++p) {
    if (comp[p] >= 0) gt.regions.data()[p] = region_of[comp[p]];
  }
  return gt;
}

}  // namespace hair25d::generator
