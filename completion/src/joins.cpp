#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <set>

#include "bank_crossings.h"
#include "context.h"
#include "hair25d/completion/bezier.h"
#include "join_features.h"
#include "raster.h"

namespace hair25d::completion::detail {
namespace {

// Weight of the width change half-way along a join (|log(middle / ends)|)
// in the cost; chosen on the annotated cases with the other weights.
constexpr double kBulgeWeight = 4.0;
// Cost of a strand join whose pieces share no occluder (the gap lies under
// two overlapping strands). 0.4 before; 0.2 keeps the preference for a
// common occluder while long strands, which pass under several, still join
// (generated 1000 × 800 drawings: precision 0.702 → 0.754, recall 0.333 →
// 0.358; annotated cases unchanged).
constexpr double kNoCommonOccluderCost = 0.2;
// Cost per 30 RGB of the colour step between the pieces that their paint
// does not explain (`paint_step`). Session 4 (0.5, the step between the
// windows' means beyond their spread): on the generated drawings (strands of
// one hair colour with small per-strand changes) the chosen strand joins
// stepped median 3.3 RGB when right and 15.1 when wrong (seeds 101-116); a
// heavier plain colour term lost annotated joins whose edges lie in shading
// bands, and weight 1.0 lost gradient recall (0.557 -> 0.528). Session 10:
// with the step measured by the paint (a gradient's predicted change and a
// cel band's colours no longer count), 1.0: precision / recall 101-116
// two-tone 0.851 / 0.601, gradient 0.970 / 0.601, flat 0.959 / 0.775
// (0.5: 0.806 / 0.566 without the shadow ratio, 0.948 / 0.605, 0.943 /
// 0.731; 1.5: 0.878 / 0.601, 0.969 / 0.583, 0.968 / 0.775); annotated
// unchanged at all three. Between flat paints the step is exact (no fit
// carried across the gap), so it weighs 1.5 there: two-tone 0.856 -> 0.884
// (201-216 0.896 -> 0.920), flat 0.959 -> 0.968, the rest unchanged (2.5:
// two-tone 0.895 / 0.596, flat 0.972 / 0.775).
constexpr double kColourStepWeight = 1.0;
constexpr double kFlatStepWeight = 1.5;
// A gradient carries on across the gap (`PaintStep::shading_continues`):
// both pieces' slopes at least kMinSlope RGB a pixel, the change they
// predict across the gap at least kMinShadingChange RGB and the step beyond
// it at most kMaxShadingStep. On generated gradient seeds 101-116 such
// strand candidates were 26 right and 5 wrong at hand costs 2.4-3.0 (all:
// 31 / 29), 24 / 7 at 3.0-3.6. The join costs kShadingContinuesBonus less:
// 0.6 took gradient 101-116 0.970 / 0.601 -> 0.973 / 0.653, 201-216 0.910 /
// 0.562 -> 0.924 / 0.627 (0.4: 0.949 / 0.616 and 0.9: 0.946 / 0.642 without
// the change rule, 0.6 without it 0.949 / 0.624; change at least 10 RGB:
// 0.951 / 0.642).
constexpr double kMinSlope = 0.1;
constexpr double kMinShadingChange = 6.0;
constexpr double kMaxShadingStep = 3.0;
constexpr double kShadingContinuesBonus = 0.6;

// How a piece is painted next to its cut: its flat colours (cel paint: a
// base and a shadow band) in the 11 x 11 windows along the edge, and a
// linear fit of its colour over 25 x 25 windows (a gradient along the
// strand). Drawn pixels of the region only, not outlines.
struct EdgePaint {
  std::vector<Eigen::Vector3d> flats;   // up to two flat colours, commonest first
  Eigen::Vector3d fit_colour{0, 0, 0};  // the fit's colour at fit_centre
  Vec2 fit_centre{0, 0};                // mean position of the fitted pixels
  Eigen::Matrix<double, 3, 2> slope = Eigen::Matrix<double, 3, 2>::Zero();  // RGB per px
  double fit_residual = 0.0;  // RGB deviation from the fit
};

// A region's flat colours (up to three, each at least 5 % of its pixels) and
// the share of its pixels that its three commonest colours hold (4-level
// bins): near 1 for flat and cel paint, low for gradients and real shading.
struct RegionPaint {
  std::vector<Eigen::Vector3d> flats;
  double exact_share = 0.0;
};

// Flat paint: both regions' three commonest colours hold this share of their
// pixels (generated flat drawings 1.0, two-tone 0.88-1.0, gradient mostly
// 0.15-0.75, the annotated cases 0.07-0.98).
constexpr double kFlatPaintShare = 0.85;
// A linear fit explains a piece when its colour deviates from it by at most
// this (RGB): generated gradient windows 0.5-5.5, two-tone windows holding a
// band edge 8-29, the annotated cases' 11-73 (line rims, noise).
constexpr double kLinearResidual = 4.0;

Eigen::Vector3d rgb_at(const Context& ctx, int x, int y) {
  const Rgba& c = ctx.image->at(x, y);
  return {static_cast<double>(c.r), static_cast<double>(c.g), static_cast<double>(c.b)};
}

// The region's own pixels within `radius` (Chebyshev) of every other point
// of the edge, each once.
std::vector<cv::Point> pixels_near(const Context& ctx, const Edge& e, int radius) {
  std::vector<cv::Point> out;
  double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18;
  for (const Vec2& p : e.points) {
    x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y());
    x1 = std::max(x1, p.x()), y1 = std::max(y1, p.y());
  }
  const int bx = static_cast<int>(x0) - radius, by = static_cast<int>(y0) - radius;
  const int w = static_cast<int>(x1) + radius + 1 - bx, h = static_cast<int>(y1) + radius + 1 - by;
  if (w <= 0 || h <= 0) return out;
  cv::Mat seen(h, w, CV_8U, cv::Scalar(0));
  for (std::size_t i = 0; i < e.points.size(); i += 2) {
    const int cx = static_cast<int>(e.points[i].x()), cy = static_cast<int>(e.points[i].y());
    for (int y = cy - radius; y <= cy + radius; ++y)
      for (int x = cx - radius; x <= cx + radius; ++x) {
        if (!ctx.original->contains(x, y) || ctx.original->at(x, y) != e.region) continue;
        std::uint8_t& s = seen.at<std::uint8_t>(y - by, x - bx);
        if (s) continue;
        s = 1;
        out.emplace_back(x, y);
      }
  }
  return out;
}

// Flat colours of `pixels`: in 8-level bins, the mean of the pixels in the
// 3 x 3 x 3 bins round the bin whose neighbourhood holds most, taken out in
// turn while that holds at least `min_share` of the pixels.
std::vector<Eigen::Vector3d> flat_colours(const Context& ctx, const std::vector<cv::Point>& pixels,
                                          int most, double min_share) {
  std::vector<Eigen::Vector3d> flats;
  if (pixels.size() < 8) return flats;
  auto key = [](int r, int g, int b) { return ((r >> 3) * 32 + (g >> 3)) * 32 + (b >> 3); };
  std::map<int, std::vector<Eigen::Vector3d>> bins;
  for (const cv::Point& p : pixels) {
    const Rgba& c = ctx.image->at(p.x, p.y);
    bins[key(c.r, c.g, c.b)].push_back(rgb_at(ctx, p.x, p.y));
  }
  auto around =
      [&](int k,
          const std::function<void(std::map<int, std::vector<Eigen::Vector3d>>::iterator)>& f) {
        for (int dr = -1; dr <= 1; ++dr)
          for (int dg = -1; dg <= 1; ++dg)
            for (int db = -1; db <= 1; ++db) {
              auto it = bins.find(k + (dr * 32 + dg) * 32 + db);
              if (it != bins.end()) f(it);
            }
      };
  while (static_cast<int>(flats.size()) < most) {
    int best = -1;
    std::size_t held = 0;
    for (const auto& [k, list] : bins) {
      std::size_t n = 0;
      around(k, [&](auto it) { n += it->second.size(); });
      if (n > held) held = n, best = k;
    }
    if (best < 0 || held < min_share * pixels.size()) break;
    Eigen::Vector3d sum(0, 0, 0);
    std::vector<int> taken;
    around(best, [&](auto it) {
      for (const Eigen::Vector3d& c : it->second) sum += c;
      taken.push_back(it->first);
    });
    for (int k : taken) bins.erase(k);
    flats.push_back(sum / static_cast<double>(held));
  }
  return flats;
}

EdgePaint edge_paint(const Context& ctx, const Edge& e) {
  EdgePaint out;
  out.flats = flat_colours(ctx, pixels_near(ctx, e, 5), 2, 0.15);
  const std::vector<cv::Point> wide = pixels_near(ctx, e, 12);
  if (wide.size() < 8) {
    out.fit_colour = e.colour;
    out.fit_residual = std::numeric_limits<double>::infinity();
    return out;
  }
  Vec2 m(0, 0);
  Eigen::Vector3d c(0, 0, 0);
  for (const cv::Point& p : wide) m += centre(p), c += rgb_at(ctx, p.x, p.y);
  m /= static_cast<double>(wide.size());
  c /= static_cast<double>(wide.size());
  // Least squares, pulled a little towards no slope where the pixels do not
  // spread (a thin piece).
  Eigen::Matrix2d xx = Eigen::Matrix2d::Identity() * 0.5 * static_cast<double>(wide.size());
  Eigen::Matrix<double, 3, 2> cx = Eigen::Matrix<double, 3, 2>::Zero();
  for (const cv::Point& p : wide) {
    const Vec2 d = centre(p) - m;
    xx += d * d.transpose();
    cx += (rgb_at(ctx, p.x, p.y) - c) * d.transpose();
  }
  out.slope = cx * xx.inverse();
  double squares = 0.0;
  for (const cv::Point& p : wide)
    squares += (rgb_at(ctx, p.x, p.y) - c - out.slope * (centre(p) - m)).squaredNorm();
  out.fit_residual = std::sqrt(squares / static_cast<double>(wide.size()));
  out.fit_colour = c;
  out.fit_centre = m;
  return out;
}

RegionPaint region_paint(const Context& ctx, int region) {
  std::vector<cv::Point> pixels;
  const RegionInfo& r = ctx.regions.at(region);
  std::map<int, int> exact;
  for (int y = r.box.y; y < r.box.y + r.box.height; ++y)
    for (int x = r.box.x; x < r.box.x + r.box.width; ++x)
      if (ctx.original->at(x, y) == region) {
        pixels.emplace_back(x, y);
        const Rgba& c = ctx.image->at(x, y);
        ++exact[((c.r >> 2) * 64 + (c.g >> 2)) * 64 + (c.b >> 2)];
      }
  RegionPaint out;
  out.flats = flat_colours(ctx, pixels, 3, 0.05);
  std::vector<int> counts;
  for (const auto& [k, n] : exact) counts.push_back(n);
  std::sort(counts.rbegin(), counts.rend());
  int top = 0;
  for (std::size_t k = 0; k < counts.size() && k < 3; ++k) top += counts[k];
  out.exact_share = pixels.empty() ? 0.0 : static_cast<double>(top) / pixels.size();
  return out;
}

// The drawing's cel shadow: per channel, the ratio of a flat-painted
// region's darker flat colour to its lighter one, when at least 3 regions
// show two and half of them agree within 0.05 on every channel (the median);
// none (all 0) otherwise.
Eigen::Vector3d shadow_ratio(const std::map<int, RegionPaint>& paints) {
  std::vector<Eigen::Vector3d> ratios;
  for (const auto& [id, p] : paints) {
    if (p.exact_share < kFlatPaintShare || p.flats.size() < 2) continue;
    Eigen::Vector3d light = p.flats[0], dark = p.flats[1];
    if (light.sum() < dark.sum()) std::swap(light, dark);
    if (light.minCoeff() < 16 || light.sum() < dark.sum() + 30) continue;
    ratios.push_back(dark.cwiseQuotient(light));
  }
  if (ratios.size() < 3) return Eigen::Vector3d::Zero();
  Eigen::Vector3d median;
  for (int c = 0; c < 3; ++c) {
    std::vector<double> v;
    for (const auto& r : ratios) v.push_back(r[c]);
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    median[c] = v[v.size() / 2];
  }
  std::size_t agree = 0;
  for (const auto& r : ratios) agree += (r - median).cwiseAbs().maxCoeff() <= 0.05;
  return 2 * agree >= ratios.size() ? median : Eigen::Vector3d::Zero();
}

// The largest distance from a flat colour of `from` to the nearest of `to`,
// or of `to` in the drawing's shadow or out of it (0 when either has none:
// nothing to compare).
double flat_distance(const std::vector<Eigen::Vector3d>& from,
                     const std::vector<Eigen::Vector3d>& to, const Eigen::Vector3d& shadow) {
  double worst = 0.0;
  if (to.empty()) return worst;
  std::vector<Eigen::Vector3d> painted = to;
  if (shadow.minCoeff() > 0)
    for (const Eigen::Vector3d& y : to) {
      painted.push_back(y.cwiseProduct(shadow));
      painted.push_back(y.cwiseQuotient(shadow));
    }
  for (const Eigen::Vector3d& x : from) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& y : painted) nearest = std::min(nearest, (x - y).norm());
    worst = std::max(worst, nearest);
  }
  return worst;
}

// The colour step between two pieces' cuts that their paint does not
// explain (RGB):
// - flat or cel paint (both regions): the flat colours at one cut that the
//   other piece is not painted in anywhere, the smaller way round. A cel
//   band spreads a window's colours, so the mean step beyond the spread
//   said nothing on two-tone drawings; a piece may show only the base or
//   only the band at its cut, but the strand is painted in both.
// - colour linear in position (both windows, a gradient along the strand):
//   the step beyond the change the mean slope of the two pieces predicts
//   between them, beyond the fits' deviations;
// - else the step between the windows' means beyond their spread.
struct PaintStep {
  double step = 0.0;               // RGB
  bool flat = false;               // compared as flat paint
  bool shading_continues = false;  // both pieces' gradients predict the step
};
PaintStep paint_step(const Edge& a, const Edge& b, const EdgePaint& pa, const EdgePaint& pb,
                     const RegionPaint& ra, const RegionPaint& rb, const Eigen::Vector3d& shadow) {
  PaintStep out;
  const bool linear = std::max(pa.fit_residual, pb.fit_residual) <= kLinearResidual;
  const bool sloped = std::min(pa.slope.norm(), pb.slope.norm()) >= kMinSlope;
  // A small piece of a gradient may hold few colours: a slope seen on both
  // sides says gradient.
  if (ra.exact_share >= kFlatPaintShare && rb.exact_share >= kFlatPaintShare &&
      !(linear && sloped)) {
    out.step = std::min(flat_distance(pa.flats, rb.flats, shadow),
                        flat_distance(pb.flats, ra.flats, shadow));
    out.flat = true;
    return out;
  }
  if (linear) {
    const Vec2 d = pb.fit_centre - pa.fit_centre;
    const Eigen::Vector3d change = 0.5 * (pa.slope + pb.slope) * d;
    out.step = std::max(
        0.0, (pb.fit_colour - pa.fit_colour - change).norm() - (pa.fit_residual + pb.fit_residual));
    out.shading_continues =
        sloped && out.step <= kMaxShadingStep && change.norm() >= kMinShadingChange;
    return out;
  }
  out.step = std::max(0.0, (a.colour - b.colour).norm() - (a.colour_spread + b.colour_spread));
  return out;
}

double colour_step_cost(const PaintStep& s) {
  return (s.flat ? kFlatStepWeight : kColourStepWeight) * s.step / 30.0;
}

double angle(const Vec2& a, const Vec2& b) {
  const double la = a.norm(), lb = b.norm();
  if (la <= 0 || lb <= 0) return M_PI;
  return std::acos(std::clamp(a.dot(b) / (la * lb), -1.0, 1.0));
}

bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  auto orient = [](const Vec2& p, const Vec2& q, const Vec2& r) {
    return (q - p).x() * (r - p).y() - (q - p).y() * (r - p).x();
  };
  const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a),
               o4 = orient(c, d, b);
  return o1 * o2 < 0 && o3 * o4 < 0;
}

// The completed area between two pieces: Bézier p_a → q_b, b's edge back to
// p_b, Bézier p_b → q_a, a's edge back to p_a (§5.1).
Polyline join_patch(const Edge& a, const Edge& b) {
  const CubicBezier first = join_bezier(a.p, a.tangent_p, b.q, -b.tangent_q);
  const CubicBezier second = join_bezier(b.p, b.tangent_p, a.q, -a.tangent_q);
  const int s1 = std::max(4, static_cast<int>((a.p - b.q).norm() / 2));
  const int s2 = std::max(4, static_cast<int>((b.p - a.q).norm() / 2));
  Polyline patch = first.sample(s1);
  for (auto it = b.points.rbegin() + 1; it != b.points.rend(); ++it) patch.push_back(*it);
  const Polyline second_points = second.sample(s2);
  patch.insert(patch.end(), second_points.begin() + 1, second_points.end());
  for (auto it = a.points.rbegin() + 1; it != a.points.rend(); ++it) patch.push_back(*it);
  return patch;
}

// Share of the patch's pixels outside both pieces that lie under an occluder
// of either piece: the hidden part may only be where the drawing shows hair
// in front (§5 "completed part lies under the occluders").
double coverage(const Context& ctx, const Polyline& patch, int ra, int rb, const cv::Mat& face,
                int* hidden) {
  double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18;
  for (const Vec2& p : patch) {
    x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y());
    x1 = std::max(x1, p.x()), y1 = std::max(y1, p.y());
  }
  const cv::Point origin(static_cast<int>(std::floor(x0)) - 1,
                         static_cast<int>(std::floor(y0)) - 1);
  const int w = static_cast<int>(std::ceil(x1)) - origin.x + 2;
  const int h = static_cast<int>(std::ceil(y1)) - origin.y + 2;
  if (w <= 0 || h <= 0 || static_cast<double>(w) * h > 4e6) return 0.0;
  cv::Mat mask(h, w, CV_8U, cv::Scalar(0));
  fill_polygon(mask, patch, origin, 255);
  int under = 0, total = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!mask.at<std::uint8_t>(y, x)) continue;
      const int gx = x + origin.x, gy = y + origin.y;
      if (!ctx.labels.contains(gx, gy)) {
        ++total;
        continue;
      }
      const int l = ctx.labels.at(gx, gy);
      if (l == ra || l == rb) continue;
      ++total;
      if (l != 0 && (ctx.is_above(l, ra) || ctx.is_above(l, rb))) ++under;
      if (l == 0 && !face.empty() && face.at<std::uint8_t>(gy, gx)) ++under;
    }
  *hidden = total;
  return total > 0 ? static_cast<double>(under) / total : 1.0;
}

// The learned scorer decides the strand joins whose hand cost lies in its
// band (join_scorer.h); every strand candidate is recorded when asked.
void score_candidates(const Context& ctx, const std::vector<Edge>& edges,
                      const std::set<int>& front, const std::map<int, int>& edge_count,
                      const std::vector<std::optional<JoinTerms>>& terms_of,
                      std::vector<Join>* candidates) {
  const Options& o = *ctx.options;
  const JoinScorerOptions& s = o.join_scorer;
  std::vector<int> which;
  std::vector<double> costs;
  std::vector<std::pair<int, int>> ends;
  std::vector<JoinFeatures> features;
  for (std::size_t i = 0; i < candidates->size(); ++i) {
    if (!terms_of[i]) continue;
    const Join& j = (*candidates)[i];
    which.push_back(static_cast<int>(i));
    costs.push_back(j.cost);
    ends.emplace_back(j.edge_a, j.edge_b);
    features.push_back(
        join_features(ctx, edges[j.edge_a], edges[j.edge_b], *terms_of[i], front, edge_count));
  }
  add_rival_features(costs, ends, s.band_high, &features);
  const JoinScorerNet& net = default_join_scorer();
  for (std::size_t k = 0; k < which.size(); ++k) {
    Join& j = (*candidates)[which[k]];
    double p = -1.0;
    if (s.enabled && j.cost >= s.band_low && j.cost <= s.band_high) {
      p = join_probability(net, features[k]);
      if (p >= s.threshold)
        j.cost = std::min(j.cost, o.max_join_cost + (s.threshold - p) * (s.band_high - s.band_low));
      else if (p < s.refuse_below)
        j.cost = std::numeric_limits<double>::infinity();
    }
    if (ctx.join_log == nullptr) continue;
    JoinCandidate c;
    c.region_a = edges[j.edge_a].region;
    c.region_b = edges[j.edge_b].region;
    c.hand_cost = costs[k];
    c.cost = j.cost;
    c.probability = p;
    c.features = features[k];
    j.record = static_cast<int>(ctx.join_log->size());
    ctx.join_log->push_back(c);
  }
}

}  // namespace

std::vector<Join> match_edges(const Context& ctx, const std::vector<Edge>& edges,
                              const cv::Mat& face, const std::function<bool(int, int)>& try_join) {
  const Options& o = *ctx.options;
  // Back hair: regions above no region. Only the face hides back hair; a
  // strand lying on the face is drawn over it, so the face between two of
  // its pieces means they are not one strand.
  std::set<int> front;
  for (const auto& [id, ups] : ctx.above) front.insert(ups.begin(), ups.end());
  const cv::Mat no_face;
  const double max_angle = o.max_join_angle_deg * M_PI / 180.0;
  RegionTones tones(ctx);
  std::vector<BankCrossings> crossings(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i)
    if (edges[i].atoms.size() == 1) crossings[i] = cross_occluders(ctx, edges[i]);
  // The learned scorer (join_scorer.h) sees candidates up to its band's top.
  const JoinScorerOptions& scorer = o.join_scorer;
  const bool scoring = scorer.enabled || ctx.join_log != nullptr;
  const double limit = scoring ? std::max(o.max_join_cost, scorer.band_high) : o.max_join_cost;
  std::vector<EdgePaint> paints(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) paints[i] = edge_paint(ctx, edges[i]);
  std::map<int, RegionPaint> region_paints;
  auto region_paint_of = [&](int region) -> const RegionPaint& {
    auto it = region_paints.find(region);
    if (it == region_paints.end())
      it = region_paints.emplace(region, region_paint(ctx, region)).first;
    return it->second;
  };
  for (const auto& [id, info] : ctx.regions) region_paint_of(id);
  const Eigen::Vector3d shadow = shadow_ratio(region_paints);
  std::map<int, int> edge_count;
  for (const Edge& e : edges) edge_count[e.region] += e.atoms.size() == 1;
  std::vector<Join> candidates;
  std::vector<std::optional<JoinTerms>> terms_of;
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const Edge& a = edges[i];
      const Edge& b = edges[j];
      if (a.region == b.region) continue;
      if (ctx.occludes(a.region, b.region) || ctx.occludes(b.region, a.region)) continue;
      const double colour = (a.colour - b.colour).norm();
      if (colour > o.max_colour_distance) continue;
      BankJoin bank;
      if (a.atoms.size() == 1 && b.atoms.size() == 1)
        bank = bank_join(crossings[i], crossings[j], a, b);
      // p_a ↔ q_b and p_b ↔ q_a: the outlines traverse both pieces the same way.
      const Vec2 c1 = b.q - a.p, c2 = a.q - b.p;
      const double angles[4] = {angle(a.tangent_p, c1), angle(-b.tangent_q, c1),
                                angle(b.tangent_p, c2), angle(-a.tangent_q, c2)};
      const double worst = *std::max_element(angles, angles + 4);
      const double wide = std::max(a.width, b.width), narrow = std::min(a.width, b.width);
      // A wide piece's side under a strand (tangents only guessed) is no cut
      // across a strand: on the annotated cases such edges joined the cap to
      // the bangs in front of it.
      const bool strand_like = !a.guessed && !b.guessed && wide > 0 &&
                               narrow / wide >= o.min_width_ratio && worst <= max_angle &&
                               !segments_cross(a.p, b.q, b.p, a.q);
      if (!strand_like && bank.share < kMinBankShare) continue;
      Join join;
      join.edge_a = static_cast<int>(i);
      join.edge_b = static_cast<int>(j);
      double cost = std::numeric_limits<double>::infinity();
      std::optional<JoinTerms> terms;
      const PaintStep step = paint_step(a, b, paints[i], paints[j], region_paint_of(a.region),
                                        region_paint_of(b.region), shadow);
      if (strand_like) {
        // The hidden part keeps a strand's width: half-way along the joins its
        // width lies near the widths at the two cuts (criterion 3 of §5.1 seen
        // from the whole join, not only its ends).
        const CubicBezier first = join_bezier(a.p, a.tangent_p, b.q, -b.tangent_q);
        const CubicBezier second = join_bezier(b.p, b.tangent_p, a.q, -a.tangent_q);
        const double middle = (first.point(0.5) - second.point(0.5)).norm();
        const double ends = 0.5 * (a.width + b.width);
        const double bulge = std::abs(std::log(std::max(middle, 1.0) / std::max(ends, 1.0)));
        const double gap = 0.5 * (c1.norm() + c2.norm());
        // Tangent continuity is the most reliable cue (§5.1 criterion 3);
        // colour varies with shading and widths with the angle of the cut.
        const double mean_angle = (angles[0] + angles[1] + angles[2] + angles[3]) / 4;
        cost = 2.0 * mean_angle / max_angle + worst / max_angle +
               0.4 * colour / o.max_colour_distance + 0.5 * (1.0 - narrow / wide) +
               0.5 * std::min(gap / wide, 3.0) + kBulgeWeight * bulge;
        // §5.1 matches edges "around a common occluder"; a gap under two
        // overlapping occluders is allowed but costs a little more.
        bool common = false;
        for (int occ : a.occluders) common = common || b.occluders.count(occ) > 0;
        if (!common) cost += kNoCommonOccluderCost;
        // A colour step the paint does not explain: two flat pieces of
        // different colours are two strands; a cel band or a gradient
        // explains its own step (`paint_step`).
        cost += colour_step_cost(step);
        // A gradient seen on both sides that carries on across the gap is
        // what a person follows under the occluder.
        if (step.shading_continues) cost -= kShadingContinuesBonus;
        // Screentone: the colour says nothing there, the dots' tone does.
        cost += tone_join_cost(tones, a.region, b.region);
        if (cost <= limit) {  // before the costly coverage raster
          join.patch = join_patch(a, b);
          int hidden = 0;
          join.behind_face = !face.empty() && !front.count(a.region) && !front.count(b.region);
          const double cover = coverage(ctx, join.patch, a.region, b.region,
                                        join.behind_face ? face : no_face, &hidden);
          cost = cover < o.min_join_coverage ? std::numeric_limits<double>::infinity()
                                             : cost + 3.0 * (1.0 - cover);
          if (scoring && std::isfinite(cost))
            terms = JoinTerms{mean_angle / max_angle,
                              worst / max_angle,
                              colour / o.max_colour_distance,
                              std::max(0.0, colour - (a.colour_spread + b.colour_spread)) / 30.0,
                              1.0 - narrow / wide,
                              std::min(gap / wide, 3.0),
                              bulge,
                              common,
                              cover,
                              cost,
                              gap,
                              wide};
        }
      }
      // Across the banks of one occluder the rays themselves are the hidden
      // part; the more of them land on the other piece, the surer the join.
      // The paint is compared as for strand joins (session 10: a two-tone
      // back piece was bank-joined across a strand to a piece 39 RGB off).
      const double bank_cost = kBankBaseCost + kBankShareWeight * (1.0 - bank.share) +
                               0.4 * colour / o.max_colour_distance + colour_step_cost(step);
      if (bank.share >= kMinBankShare && bank_cost < cost) {
        cost = bank_cost;
        join.patch.clear();
        join.behind_face = false;
        join.bands = std::move(bank.bands);
        terms.reset();
      }
      if (cost > limit) continue;
      join.cost = cost;
      candidates.push_back(std::move(join));
      terms_of.push_back(terms);
    }
  if (scoring) score_candidates(ctx, edges, front, edge_count, terms_of, &candidates);
  // Greedy one-to-one: cheapest first, every edge joined at most once.
  std::erase_if(candidates, [&](const Join& x) { return x.cost > o.max_join_cost; });
  std::sort(candidates.begin(), candidates.end(),
            [](const Join& x, const Join& y) { return x.cost < y.cost; });
  // Edges may overlap (an atom and a merged edge holding it): an atom joins once.
  std::set<int> used;
  std::vector<Join> chosen;
  for (Join& j : candidates) {
    bool free = true;
    for (int e : {j.edge_a, j.edge_b})
      for (int atom : edges[e].atoms) free = free && !used.count(atom);
    if (!free || !try_join(edges[j.edge_a].region, edges[j.edge_b].region)) continue;
    for (int e : {j.edge_a, j.edge_b}) used.insert(edges[e].atoms.begin(), edges[e].atoms.end());
    if (j.record >= 0) (*ctx.join_log)[j.record].chosen = true;
    chosen.push_back(std::move(j));
  }
  return chosen;
}

}  // namespace hair25d::completion::detail
