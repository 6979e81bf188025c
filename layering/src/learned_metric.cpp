#include "hair25d/layering/learned_metric.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "hair25d/layering/metrics.h"

namespace hair25d::layering {
namespace {
constexpr double kPi = std::numbers::pi;

// Soft indicators of the junction shapes the paper's properties name: a
// straight continuation (the occluder's outline runs through, Property 1), a
// right angle (the occludee's cut outline), a tip (Property 4), a reflex
// sector (a region wrapping around the junction).
double straight(double a) { return std::max(0.0, 1.0 - std::abs(a - kPi) / (kPi / 4)); }
double right_angle(double a) { return std::max(0.0, 1.0 - std::abs(a - kPi / 2) / (kPi / 4)); }
double tip(double a) { return std::max(0.0, 1.0 - a / (kPi / 4)); }
double reflex(double a) { return std::clamp((a - kPi) / (kPi / 2), 0.0, 1.0); }

double safe_log(double v) { return std::log(std::max(v, 1.0)); }
}  // namespace

BoundaryFeatures boundary_features(const BoundaryCues& c) {
  BoundaryFeatures f{};
  for (const EndAngles& e : {c.start, c.end}) {
    if (!e.used) continue;
    const double a = e.left, b = e.right;
    f[0] += junction_metric(a, b);
    f[1] += (a - b) / kPi;
    f[2] += straight(a) - straight(b);
    f[3] += right_angle(a) - right_angle(b);
    f[4] += tip(a) - tip(b);
    f[5] += reflex(a) - reflex(b);
    // Property 3 (α + β ≈ π: the stem of a T between two regions both below
    // the bar) says nothing; the ideal T and the tip as products.
    f[10] += junction_metric(a, b) * (1.0 - straight(a + b));
    f[11] += e.rays >= 4 ? (a - b) / kPi : 0.0;
    f[12] += straight(a) * right_angle(b) - straight(b) * right_angle(a);
    f[13] += tip(a) * (1.0 - straight(b)) - tip(b) * (1.0 - straight(a));
    const double wa = e.wide_left, wb = e.wide_right;
    f[14] += junction_metric(wa, wb);
    f[15] += (wa - wb) / kPi;
    f[16] += straight(wa) - straight(wb);
    f[17] += tip(wa) - tip(wb);
    const double ca = e.curved_left, cb = e.curved_right;
    f[18] += junction_metric(ca, cb);
    f[19] += (ca - cb) / kPi;
    f[20] += straight(ca) - straight(cb);
    f[21] += straight(ca) * right_angle(cb) - straight(cb) * right_angle(ca);
    f[22] += tip(ca) * (1.0 - straight(cb)) - tip(cb) * (1.0 - straight(ca));
    const double oa = e.circle_left, ob = e.circle_right;
    f[24] += (oa - ob) / kPi;
    f[25] += straight(oa) - straight(ob);
    f[26] += tip(oa) - tip(ob);
    const double pa = e.circle_wide_left, pb = e.circle_wide_right;
    f[27] += (pa - pb) / kPi;
    f[28] += straight(pa) - straight(pb);
    f[29] += tip(pa) - tip(pb);
  }
  f[6] = std::clamp(c.phi_r, -1.0, 1.0);
  f[7] = safe_log(c.area_left) - safe_log(c.area_right);
  // Compactness, area / perimeter²: a strand is long and thin, a tuft or a
  // cap round.
  auto compact = [](double area, double perimeter) {
    return perimeter > 0 ? 4 * kPi * area / (perimeter * perimeter) : 0.0;
  };
  f[8] = compact(c.area_left, c.perimeter_left) - compact(c.area_right, c.perimeter_right);
  f[9] = c.turning / kPi;
  f[23] = c.shared_left - c.shared_right;
  return f;
}

EqualFeatures equal_features(const EqualCues& c) {
  EqualFeatures f{};
  f[0] = 1.0;  // intercept: same-depth boundaries are rare
  f[1] = std::min(c.colour_difference / 32.0, 4.0);
  // Relative to the drawing's own spread of colours: in a grey manga page
  // every strand has about the same tone, so "same paint" says less.
  f[2] = std::min(c.colour_difference / (c.typical_colour_difference + 2.0), 4.0);
  f[3] = std::min(std::abs(c.order_log_odds), 4.0);
  f[4] = safe_log(c.length_widths);
  f[5] = std::min(std::abs(safe_log(c.area_left) - safe_log(c.area_right)), 4.0);
  f[6] = std::clamp(c.contrast_ratio, 0.0, 3.0);
  f[7] = std::clamp(c.contrast_low_ratio, 0.0, 3.0);
  int used = 0;
  for (const EndAngles& e : {c.start, c.end}) {
    if (!e.used) continue;
    ++used;
    f[8] += std::min(e.left, e.right) / kPi;
    f[9] += tip(e.left) * tip(e.right);  // both regions end in a point: a forked tip
  }
  if (used > 0) f[8] /= used;
  // The same read off the label map (circle sectors), how alike the two
  // sides look at the ends (a fork's halves sit symmetrically; an occluder's
  // outline runs through), and a lens: one side ending in a point at both
  // ends, as the piece between a fork line and the strand's outline does.
  for (const EndAngles& e : {c.start, c.end}) {
    if (!e.used) continue;
    f[10] += tip(e.circle_left) * tip(e.circle_right);
    f[12] += std::abs(e.circle_left - e.circle_right) / kPi / used;
  }
  if (c.start.used && c.end.used)
    f[11] = std::max(tip(c.start.circle_left) * tip(c.end.circle_left),
                     tip(c.start.circle_right) * tip(c.end.circle_right));
  f[13] = std::max(c.shared_left, c.shared_right);
  return f;
}

double equal_metric(const EqualFeatures& features) {
  const EqualFeatures& w = equal_weights();
  double s = 0.0;
  for (int i = 0; i < kEqualFeatureCount; ++i) s += w[i] * features[i];
  return s;
}

std::vector<double> context_differences(const std::vector<ContextBoundary>& boundaries) {
  // Per region: Σ w·p and Σ w over all its boundaries, and the same per pair,
  // so that a pair's own boundaries can be taken out again.
  std::map<int, std::pair<double, double>> region;
  std::map<std::pair<int, int>, std::pair<double, double>> pair;  // of the smaller id
  auto vote = [](const ContextBoundary& b) { return std::tanh(0.5 * b.log_odds); };
  for (const ContextBoundary& b : boundaries) {
    if (!b.used || b.left <= 0 || b.right <= 0 || b.left == b.right) continue;
    const double p = vote(b);
    region[b.left].first += b.length * p;
    region[b.left].second += b.length;
    region[b.right].first -= b.length * p;
    region[b.right].second += b.length;
    auto& q = pair[{std::min(b.left, b.right), std::max(b.left, b.right)}];
    q.first += b.length * (b.left < b.right ? p : -p);
    q.second += b.length;
  }
  std::vector<double> out(boundaries.size(), 0.0);
  for (std::size_t i = 0; i < boundaries.size(); ++i) {
    const ContextBoundary& b = boundaries[i];
    if (b.left <= 0 || b.right <= 0 || b.left == b.right) continue;
    const auto k = std::make_pair(std::min(b.left, b.right), std::max(b.left, b.right));
    const auto it = pair.find(k);
    const double own = it == pair.end() ? 0.0 : it->second.first;  // toward the smaller id
    const double own_w = it == pair.end() ? 0.0 : it->second.second;
    auto mean_without = [&](int id, double own_toward_id) {
      const auto r = region.find(id);
      if (r == region.end()) return 0.0;
      const double w = r->second.second - own_w;
      return w > 1e-9 ? (r->second.first - own_toward_id) / w : 0.0;
    };
    const double own_left = b.left < b.right ? own : -own;
    out[i] = mean_without(b.left, own_left) - mean_without(b.right, -own_left);
  }
  return out;
}

ContextTerms context_terms(double log_odds, double context) {
  const double l = std::clamp(log_odds, -8.0, 8.0);
  return {l, context, context / (1.0 + std::abs(l))};
}

double context_metric(double log_odds, double context) {
  const ContextTerms t = context_terms(log_odds, context);
  const ContextTerms& w = context_weights();
  double s = 0.0;
  for (int i = 0; i < kContextTermCount; ++i) s += w[i] * t[i];
  return s;
}

LearnedTerms learned_terms(const BoundaryFeatures& f) {
  LearnedTerms t{};
  int k = 0;
  for (double v : f) t[k++] = v;
  for (int i = 0; i < kBoundaryFeatureCount; ++i)
    for (int j = 0; j < kBoundaryFeatureCount; ++j)
      if (i != j) t[k++] = f[i] * std::abs(f[j]);
  return t;
}

double learned_metric(const BoundaryFeatures& features) {
  const LearnedTerms& w = learned_weights();
  const LearnedTerms t = learned_terms(features);
  double s = 0.0;
  for (int i = 0; i < kLearnedTermCount; ++i) s += w[i] * t[i];
  return s;
}

}  // namespace hair25d::layering
