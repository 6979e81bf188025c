// The dot lattice of a screentone among an inpainting's sources: small ink
// components whose centres repeat by two basis vectors. inpaint_cel copies
// patches from whole lattice translates of the target (the dots continue in
// phase) and lets the dots through its ink rule (they are the paint, not a
// feature to keep out of the hole).
#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "inpaint_internal.h"
#include "raster.h"

namespace hair25d::completion::detail {

namespace {

struct Vec {
  double x, y;
};

double norm(Vec v) { return std::hypot(v.x, v.y); }
double cross(Vec a, Vec b) { return a.x * b.y - a.y * b.x; }

// The step most steps agree with (v and -v alike): the mean of the steps
// within 15 % of its length of the step with about the most such
// neighbours; of those within a tenth of the most, the shortest (a square
// lattice's diagonals are as common as its second axis).
Vec mode_step(const std::vector<Vec>& all, int* support) {
  // At most kMaxSteps of them (evenly spread) vote: the count is quadratic.
  constexpr std::size_t kMaxSteps = 600;
  std::vector<Vec> steps;
  const std::size_t stride = (all.size() + kMaxSteps - 1) / kMaxSteps;
  for (std::size_t i = 0; i < all.size(); i += stride) steps.push_back(all[i]);
  const auto close = [](Vec s, Vec m, double tol2) {
    const double dx = s.x - m.x, dy = s.y - m.y, fx = s.x + m.x, fy = s.y + m.y;
    return dx * dx + dy * dy <= tol2 || fx * fx + fy * fy <= tol2;
  };
  std::vector<int> count(steps.size(), 0);
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const double tol2 = 0.0225 * (steps[i].x * steps[i].x + steps[i].y * steps[i].y);
    for (const Vec& s : steps) count[i] += close(s, steps[i], tol2);
  }
  const int most = *std::max_element(count.begin(), count.end());
  std::size_t best_i = 0;
  double best_len = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < steps.size(); ++i)
    if (count[i] * 1.1 >= most && norm(steps[i]) < best_len) best_len = norm(steps[i]), best_i = i;
  Vec sum{0.0, 0.0};
  int n = 0;
  const Vec m = steps[best_i];
  const double tol2 = 0.0225 * (m.x * m.x + m.y * m.y);
  for (const Vec& s : all) {
    const double dx = s.x - m.x, dy = s.y - m.y;
    if (dx * dx + dy * dy <= tol2)
      sum.x += s.x, sum.y += s.y, ++n;
    else if (close(s, m, tol2))
      sum.x -= s.x, sum.y -= s.y, ++n;
  }
  *support = n;
  return {sum.x / std::max(1, n), sum.y / std::max(1, n)};
}

// The basis vectors a, b of the lattice the dot centres lie on; false when
// they lie on none.
bool fit_lattice(const std::vector<Vec>& centres, int w, int h, Vec* a_out, Vec* b_out) {
  // Dots binned by kBin px: a dot's neighbours within kReach px are in the
  // 5×5 bins round its own.
  constexpr int kBin = 8, kReach = 2 * kBin;
  const int bins_x = w / kBin + 1, bins_y = h / kBin + 1;
  std::vector<std::vector<int>> bins(static_cast<std::size_t>(bins_x) * bins_y);
  for (std::size_t i = 0; i < centres.size(); ++i)
    bins[static_cast<std::size_t>(static_cast<int>(centres[i].y) / kBin) * bins_x +
         static_cast<int>(centres[i].x) / kBin]
        .push_back(static_cast<int>(i));
  const auto neighbours = [&](std::size_t i, double reach, std::vector<Vec>* out) {
    const Vec c = centres[i];
    const int bx = static_cast<int>(c.x) / kBin, by = static_cast<int>(c.y) / kBin;
    for (int y = std::max(0, by - 2); y <= std::min(bins_y - 1, by + 2); ++y)
      for (int x = std::max(0, bx - 2); x <= std::min(bins_x - 1, bx + 2); ++x)
        for (int j : bins[static_cast<std::size_t>(y) * bins_x + x]) {
          if (static_cast<std::size_t>(j) == i) continue;
          const Vec v{centres[j].x - c.x, centres[j].y - c.y};
          if (v.x * v.x + v.y * v.y <= reach * reach) out->push_back(v);
        }
  };
  // At most kSample dots (evenly spread over the list) vote.
  const std::size_t stride = std::max<std::size_t>(1, centres.size() / kSample);
  std::vector<Vec> nearest, near;
  for (std::size_t i = 0; i < centres.size(); i += stride) {
    near.clear();
    neighbours(i, kReach, &near);
    if (near.empty()) continue;
    nearest.push_back(*std::min_element(near.begin(), near.end(), [](Vec p, Vec q) {
      return p.x * p.x + p.y * p.y < q.x * q.x + q.y * q.y;
    }));
  }
  if (static_cast<int>(nearest.size()) < kMinDots) return false;
  int support = 0;
  Vec a = mode_step(nearest, &support);
  const double period = norm(a);
  if (period < 2.0 || support < static_cast<int>(nearest.size()) / 3) return false;
  // The second axis: the commonest neighbour step at least 30° off the first.
  std::vector<Vec> off_axis;
  for (std::size_t i = 0; i < centres.size(); i += stride) {
    near.clear();
    neighbours(i, std::min<double>(kReach, 1.6 * period), &near);
    for (const Vec& v : near)
      if (std::abs(cross(a, v)) > 0.5 * period * norm(v)) off_axis.push_back(v);
  }
  if (static_cast<int>(off_axis.size()) < kMinDots) return false;
  Vec b = mode_step(off_axis, &support);
  // The shortest representative of b modulo a.
  const double along = std::round((a.x * b.x + a.y * b.y) / (period * period));
  b = {b.x - along * a.x, b.y - along * a.y};
  const double cell = std::abs(cross(a, b));
  if (cell < 4.0) return false;
  // Every neighbour step of a lattice's dots is a whole lattice vector.
  int whole = 0, all = 0;
  for (std::size_t i = 0; i < centres.size(); i += stride) {
    near.clear();
    neighbours(i, std::min<double>(kReach, 1.6 * std::max(period, norm(b))), &near);
    for (const Vec& v : near) {
      const double i_a = cross(v, b) / cross(a, b), j_b = cross(a, v) / cross(a, b);
      ++all;
      whole += std::abs(i_a - std::round(i_a)) < 0.2 && std::abs(j_b - std::round(j_b)) < 0.2;
    }
  }
  if (all == 0 || whole < kMinWholeShare * all) return false;
  // Least squares over every step within kReach, v = i a + j b for the
  // rounded lattice coordinates: the nearest steps alone are biased short
  // where the centres are noisy (a dense tone's cores).
  double sii = 0, sij = 0, sjj = 0, six = 0, siy = 0, sjx = 0, sjy = 0;
  for (std::size_t i = 0; i < centres.size(); i += stride) {
    near.clear();
    neighbours(i, kReach, &near);
    for (const Vec& v : near) {
      const double fi = cross(v, b) / cross(a, b), fj = cross(a, v) / cross(a, b);
      const double ri = std::round(fi), rj = std::round(fj);
      if (std::abs(fi - ri) >= 0.2 || std::abs(fj - rj) >= 0.2) continue;
      sii += ri * ri, sij += ri * rj, sjj += rj * rj;
      six += ri * v.x, siy += ri * v.y, sjx += rj * v.x, sjy += rj * v.y;
    }
  }
  const double det = sii * sjj - sij * sij;
  if (det > 0) {
    a = {(sjj * six - sij * sjx) / det, (sjj * siy - sij * sjy) / det};
    b = {(sii * sjx - sij * six) / det, (sii * sjy - sij * siy) / det};
  }
  *a_out = a, *b_out = b;
  return true;
}

// The dots of `mask` (components of min_area to kMaxDotArea px
// and at most kMaxDotSide px each way): their centres, and per component
// label whether it is one.
std::vector<Vec> dots_of(const cv::Mat& mask, int min_area, int connectivity, cv::Mat* labels,
                         std::vector<std::uint8_t>* is_dot) {
  cv::Mat stats, centroids;
  const int n =
      cv::connectedComponentsWithStats(mask, *labels, stats, centroids, connectivity, CV_32S);
  std::vector<Vec> centres;
  is_dot->assign(static_cast<std::size_t>(n), 0);
  for (int k = 1; k < n; ++k) {
    const int area = stats.at<int>(k, cv::CC_STAT_AREA);
    const int bw = stats.at<int>(k, cv::CC_STAT_WIDTH), bh = stats.at<int>(k, cv::CC_STAT_HEIGHT);
    if (area < min_area || area > kMaxDotArea || bw > kMaxDotSide || bh > kMaxDotSide) continue;
    (*is_dot)[static_cast<std::size_t>(k)] = 1;
    centres.push_back({centroids.at<double>(k, 0), centroids.at<double>(k, 1)});
  }
  return centres;
}

// An upper bound on the number of dots dots_of would find in `mask`: its
// runs (of at most kMaxDotSide px) that touch no pixel of the row above.
// Every component has at least one such run, its first, and a dot's first
// run is no longer than the dot is wide. Far cheaper than the labelling:
// where it is under kMinDots (a flat strand's lines and their cores) no
// lattice can be found there.
int dot_bound(const cv::Mat& mask, int connectivity) {
  const int reach = connectivity == 8 ? 1 : 0;
  int bound = 0;
  for (int y = 0; y < mask.rows; ++y) {
    const std::uint8_t* row = mask.ptr<std::uint8_t>(y);
    const std::uint8_t* above = y > 0 ? mask.ptr<std::uint8_t>(y - 1) : nullptr;
    for (int x = 0; x < mask.cols;) {
      if (!row[x]) {
        ++x;
        continue;
      }
      const int x0 = x;
      while (x < mask.cols && row[x]) ++x;
      if (x - x0 > kMaxDotSide) continue;
      bool joined = false;
      if (above != nullptr)
        for (int i = std::max(0, x0 - reach); i < std::min(mask.cols, x + reach) && !joined; ++i)
          joined = above[i] != 0;
      bound += !joined;
    }
  }
  return bound;
}

// The q-th quantile of the values counted in `histogram` (`total` of them):
// the value std::nth_element puts at position q·(total − 1).
int percentile(const std::vector<std::size_t>& histogram, std::size_t total, double q) {
  const auto k = static_cast<std::size_t>(q * static_cast<double>(total - 1));
  std::size_t seen = 0;
  for (std::size_t v = 0; v < histogram.size(); ++v) {
    seen += histogram[v];
    if (seen > k) return static_cast<int>(v);
  }
  return static_cast<int>(histogram.size()) - 1;
}

}  // namespace

DotLattice find_dot_lattice(const Image& image, const LabelMap& fill, const LabelMap& source,
                            const std::vector<std::uint8_t>& ink) {
  DotLattice lattice;
  const int w = image.width(), h = image.height();
  const auto at = [w](int x, int y) { return static_cast<std::size_t>(y) * w + x; };
  cv::Mat mask(h, w, CV_8U, cv::Scalar(0));
  // The sources' lumas, counted per value (for the dense tone's percentiles).
  std::vector<std::size_t> lumas(256, 0);
  std::size_t usable_count = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = at(x, y);
      const bool usable = fill.data()[i] == 0 && (source.empty() || source.data()[i] != 0);
      if (!usable) continue;
      const Rgba& c = image.data()[i];
      const int l = (luma(c) * c.a + 255 * (255 - c.a)) / 255;
      ++lumas[static_cast<std::size_t>(l)];
      ++usable_count;
      if (ink[i]) mask.at<std::uint8_t>(y, x) = 255;
    }
  cv::Mat labels;
  std::vector<std::uint8_t> is_dot;
  Vec a{0, 0}, b{0, 0};
  std::vector<Vec> centres;
  if (dot_bound(mask, 8) >= kMinDots) centres = dots_of(mask, kMinDotArea, 8, &labels, &is_dot);
  if (static_cast<int>(centres.size()) >= kMinDots && fit_lattice(centres, w, h, &a, &b)) {
    lattice.dots.assign(static_cast<std::size_t>(w) * h, 0);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (is_dot[static_cast<std::size_t>(labels.at<int>(y, x))]) lattice.dots[at(x, y)] = 1;
  } else {
    // A dense tone: the dots touch through their anti-aliased rims, and the
    // ink is one web (or, on a tone darker than half its paper, hardly ink
    // at all: source_ink_options lowers ink_luma). Their cores (the darkest
    // part of the way from the darkest sources to the paper) stay apart; an ink pixel is the tone's
    // when its nearest core is a dot's within half a period (a line's own pixels are nearer the
    // line's dark middle).
    if (usable_count < static_cast<std::size_t>(kMinDots)) return lattice;
    const int dark = percentile(lumas, usable_count, 0.05);
    const int paper = percentile(lumas, usable_count, 0.9);
    if (paper - dark < kMinToneContrast) return lattice;
    const int core_luma = dark + (paper - dark) * kCoreShare;
    cv::Mat core(h, w, CV_8U, cv::Scalar(0));
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const std::size_t i = at(x, y);
        if (fill.data()[i] != 0 || (!source.empty() && source.data()[i] == 0)) continue;
        const Rgba& c = image.data()[i];
        if ((luma(c) * c.a + 255 * (255 - c.a)) / 255 < core_luma)
          core.at<std::uint8_t>(y, x) = 255;
      }
    // 4-connected: dense dots' cores touch at corners.
    if (dot_bound(core, 4) < kMinDots) return lattice;
    centres = dots_of(core, 1, 4, &labels, &is_dot);
    if (static_cast<int>(centres.size()) < kMinDots || !fit_lattice(centres, w, h, &a, &b))
      return lattice;
    cv::Mat distance, nearest;
    cv::distanceTransform(~core, distance, nearest, cv::DIST_L2, cv::DIST_MASK_5,
                          cv::DIST_LABEL_CCOMP);
    // distanceTransform's numbers of the cores, read back at their pixels.
    std::vector<int> core_label;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (core.at<std::uint8_t>(y, x)) {
          const auto k = static_cast<std::size_t>(nearest.at<int>(y, x));
          if (core_label.size() <= k) core_label.resize(k + 1, 0);
          core_label[k] = labels.at<int>(y, x);
        }
    const double reach = 0.5 * std::min(norm(a), norm(b));
    lattice.dots.assign(static_cast<std::size_t>(w) * h, 0);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (!mask.at<std::uint8_t>(y, x) || distance.at<float>(y, x) > reach) continue;
        const int k = nearest.at<int>(y, x);
        if (k > 0 && k < static_cast<int>(core_label.size()) &&
            is_dot[static_cast<std::size_t>(core_label[static_cast<std::size_t>(k)])])
          lattice.dots[at(x, y)] = 1;
      }
  }
  lattice.valid = true;
  lattice.ax = a.x, lattice.ay = a.y, lattice.bx = b.x, lattice.by = b.y;
  return lattice;
}

}  // namespace hair25d::completion::detail
