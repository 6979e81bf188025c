#include "strand_continuation.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "raster.h"
#include "seam_joins.h"

namespace hair25d::completion::detail {
namespace {

// Slices are taken from kNearSlice px off the a–b line (its own pixels'
// jags stay out) up to its length clamped to [kMinDepth, kMaxDepth] px:
// far enough to read a side beside a region lying over the meeting point,
// near enough that a curving side stays straight (16 px: 14 right pairs
// fewer on dev mixed 3000; 32 px: 4 more on dev flat and mixed 3000, not
// taken).
constexpr int kNearSlice = 2;
constexpr int kMinDepth = 6;
constexpr int kMaxDepth = 24;
// Slices run along the line at most this far (px) from its centre, and the
// box of closed labels reaches this far round the contact. A run reaching
// it has no side there: a cut under ~30° to the strand puts its sides out of
// reach (64 px lost 6 right pairs on dev flat and mixed 2000, 28 px the
// same as 40 within 2).
constexpr int kSliceReach = 40;
// A side fit needs this many slices with that end seen (2 changed nothing).
constexpr int kMinFitSlices = 3;
// A side runs on across the line where the two pieces' fits meet within
// kMaxSideOffset px at it and their directions differ by at most
// kMaxSideAngle degrees (3.5 px: +10 right pairs and +2 wrong on dev flat
// and mixed 2000 and 3000; 30°: +2 right on mixed 3000).
constexpr double kMaxSideOffset = 2.5;
constexpr double kMaxSideAngle = 20.0;

struct SliceEnd {
  double s;  // signed distance from the line (a's side positive)
  double u;  // position along the line
};

struct Fit {
  double at0 = 0.0, slope = 0.0;
};

Fit fit_line(const std::vector<SliceEnd>& ends) {
  double ss = 0, su = 0, sss = 0, ssu = 0;
  const double n = static_cast<double>(ends.size());
  for (const SliceEnd& e : ends) ss += e.s, su += e.u, sss += e.s * e.s, ssu += e.s * e.u;
  const double den = n * sss - ss * ss;
  Fit f;
  f.slope = std::abs(den) < 1e-9 ? 0.0 : (n * ssu - ss * su) / den;
  f.at0 = (su - f.slope * ss) / n;
  return f;
}

SideFit compare(const std::vector<SliceEnd>& on_a, const std::vector<SliceEnd>& on_b) {
  SideFit out;
  if (static_cast<int>(on_a.size()) < kMinFitSlices ||
      static_cast<int>(on_b.size()) < kMinFitSlices)
    return out;
  const Fit fa = fit_line(on_a), fb = fit_line(on_b);
  out.measured = true;
  out.offset = std::abs(fa.at0 - fb.at0);
  out.angle = std::abs(std::atan(fa.slope) - std::atan(fb.slope)) * 180.0 / M_PI;
  return out;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

}  // namespace

StrandContinuation strand_continuation(const Context& ctx, int a, int b,
                                       const std::function<bool(int, int)>& above) {
  StrandContinuation out;
  const cv::Rect box = contact_box(ctx, a, b, kSliceReach);
  if (box.empty()) return out;
  const cv::Mat lab = closed_labels(ctx, box);
  // The a–b line: midpoints of 4-neighbour a–b pixel pairs (box pixels).
  std::vector<Vec2> line;
  Vec2 a_side(0, 0);
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) {
      const int l = lab.at<int>(y, x);
      if (l != a && l != b) continue;
      const int sign = l == a ? 1 : -1;
      for (const cv::Point d : {cv::Point(1, 0), cv::Point(0, 1)}) {
        if (x + d.x >= box.width || y + d.y >= box.height) continue;
        const int m = lab.at<int>(y + d.y, x + d.x);
        if (m != (l == a ? b : a)) continue;
        line.push_back(Vec2(x + 0.5 + 0.5 * d.x, y + 0.5 + 0.5 * d.y));
        a_side -= sign * Vec2(d.x, d.y);
      }
    }
  if (line.size() < 3) return out;
  const TotalFit fit = total_least_squares(line);
  const Vec2 c = fit.mean, t = fit.axis;
  Vec2 n(-t.y(), t.x());
  // a_side sums, over the a–b pairs, the step from the b pixel to the a pixel.
  if (a_side.dot(n) < 0) n = -n;
  double lo = 1e9, hi = -1e9;
  for (const Vec2& p : line) {
    const double u = (p - c).dot(t);
    lo = std::min(lo, u), hi = std::max(hi, u);
  }
  out.line_length = hi - lo + 1.0;
  out.bend = fit.across;
  const int depth =
      std::clamp(static_cast<int>(std::lround(out.line_length)), kMinDepth, kMaxDepth);
  const double reach = kSliceReach;

  const auto label_at = [&](const Vec2& p) {
    const int x = static_cast<int>(std::floor(p.x())), y = static_cast<int>(std::floor(p.y()));
    if (x < 0 || y < 0 || x >= box.width || y >= box.height) return -1;
    return lab.at<int>(y, x);
  };
  std::vector<SliceEnd> low_a, low_b, high_a, high_b;
  std::vector<double> widths_a, widths_b;
  for (const int piece : {a, b}) {
    const double sign = piece == a ? 1.0 : -1.0;
    const int other = piece == a ? b : a;
    // An end is a side where the run stops on the paper or a region not
    // lying above the piece; a run reaching the slice's end or the box's edge
    // (-1) has no side there.
    const auto seen = [&](int l) { return l != other && l != -1 && (l == 0 || !above(l, piece)); };
    for (int s = kNearSlice; s <= depth; ++s) {
      const Vec2 base = c + n * (sign * s);
      // Runs of the piece along the slice, sampled every half pixel.
      struct Run {
        double from, to;
        int before, after;
      };
      std::vector<Run> runs;
      int prev = -1;  // a run from the slice's start has no side there
      for (double u = -reach; u <= reach; u += 0.5) {
        const int l = label_at(base + t * u);
        if (l == piece && prev != piece) runs.push_back({u, u, prev, -1});
        if (l == piece) runs.back().to = u;
        if (l != piece && prev == piece) runs.back().after = l;
        prev = l;
      }
      // The run facing the line: the longest overlap with its extent.
      const Run* best = nullptr;
      double best_overlap = 0.0;
      for (const Run& r : runs) {
        const double overlap = std::min(r.to, hi + 3.0) - std::max(r.from, lo - 3.0);
        if (overlap > best_overlap) best_overlap = overlap, best = &r;
      }
      if (best == nullptr) continue;
      const bool low_seen = seen(best->before), high_seen = seen(best->after);
      if (low_seen) (piece == a ? low_a : low_b).push_back({sign * s, best->from});
      if (high_seen) (piece == a ? high_a : high_b).push_back({sign * s, best->to});
      if (low_seen && high_seen)
        (piece == a ? widths_a : widths_b).push_back(best->to - best->from + 0.5);
    }
  }
  out.slices_a = static_cast<int>(widths_a.size());
  out.slices_b = static_cast<int>(widths_b.size());
  out.width_a = median(widths_a);
  out.width_b = median(widths_b);
  out.low = compare(low_a, low_b);
  out.high = compare(high_a, high_b);
  out.measured = out.slices_a + out.slices_b > 0 || out.low.measured || out.high.measured;
  return out;
}

bool continues_one_strand(const StrandContinuation& c) {
  if (!c.measured) return false;
  const auto runs_on = [](const SideFit& f) {
    return f.offset <= kMaxSideOffset && f.angle <= kMaxSideAngle;
  };
  if (!c.low.measured && !c.high.measured) return false;
  return (!c.low.measured || runs_on(c.low)) && (!c.high.measured || runs_on(c.high));
}

}  // namespace hair25d::completion::detail
