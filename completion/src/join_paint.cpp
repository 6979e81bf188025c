#include "join_paint.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <opencv2/core.hpp>
#include <optional>
#include <unordered_map>

#include "raster.h"

namespace hair25d::completion::detail {
namespace {

// A gradient carries on across the gap (`PaintStep::shading_continues`):
// both pieces' slopes at least kMinSlope RGB a pixel, the change they
// predict across the gap at least kMinShadingChange RGB and the step beyond
// it at most kMaxShadingStep. On generated gradient seeds 101-116 such
// strand candidates were 26 right and 5 wrong at hand costs 2.4-3.0 (all:
// 31 / 29), 24 / 7 at 3.0-3.6. The join then costs less (joins.cpp, kShadingContinuesBonus):
// 0.6 took gradient 101-116 0.970 / 0.601 -> 0.973 / 0.653, 201-216 0.910 /
// 0.562 -> 0.924 / 0.627 (0.4: 0.949 / 0.616 and 0.9: 0.946 / 0.642 without
// the change rule, 0.6 without it 0.949 / 0.624; change at least 10 RGB:
// 0.951 / 0.642).
constexpr double kMinSlope = 0.1;
constexpr double kMinShadingChange = 6.0;
constexpr double kMaxShadingStep = 3.0;
// Two linear pieces are two strands (`PaintStep::off_gradient`, a strand
// join refused) when their fits step more than kMaxFlatFitStep RGB where the
// slopes predict less than kMinShadingChange across the gap (both cuts lie
// on one level of the gradient), or more than kMaxShadingStep and
// kFittedChangeShare of the predicted change elsewhere (a curved strand's
// change is extrapolated from straight fits; the generator varies each
// strand's colour by up to 8 %). Session 13, the chosen strand joins of
// gradient seeds 101-116 and 201-216 compared by the fits: right ones with
// less change predicted stepped at most 0.24 RGB, wrong ones 1.49, 8.66 and
// 9.87 (change 0.4-2.5); elsewhere right ones stepped at most 2.56 (one
// 7.37 at a change of 40), wrong ones 3.57 at 15 (and 1.2-3.8 at changes of
// 10-45, kept). Figures in docs/completion-record.md, "Session 13".
constexpr double kMaxFlatFitStep = 1.0;
constexpr double kFittedChangeShare = 0.2;
// `PaintStep::uneven_slopes`: one window's slope under this share of the
// other's (session 24: 13 of the 33 right pairs of dev gradient 2000-2099
// that `off_gradient` alone refused).
constexpr double kUnevenSlopeShare = 0.25;

// Flat paint: both regions' three commonest colours hold this share of their
// pixels (generated flat drawings 1.0, two-tone 0.88-1.0, gradient mostly
// 0.15-0.75, the annotated cases 0.07-0.98).
constexpr double kFlatPaintShare = 0.85;
// A linear fit explains a piece when its colour deviates from it by at most
// this (RGB): generated gradient windows 0.5-5.5, two-tone windows holding a
// band edge 8-29, the annotated cases' 11-73 (line rims, noise).
constexpr double kLinearResidual = 4.0;
// flat_colours: a cluster is flat paint when one exact colour holds more
// than half of it; its colour is then the mean of the colours within
// kExactRadius RGB of that one.
constexpr double kExactRadius = 1.0;

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

}  // namespace

std::vector<Eigen::Vector3d> flat_colours(const Image& image, const std::vector<cv::Point>& pixels,
                                          int most, double min_share, bool exact_paint) {
  std::vector<Eigen::Vector3d> flats;
  if (pixels.size() < 8) return flats;
  // Bins 1-32 of a 34-wide grid: a neighbour of bin 32 (a channel at 248 or
  // more) is the empty bin 33, not bin 0 of the next row (a colour with
  // that channel near 0).
  constexpr int kSide = 34;
  auto key = [](int r, int g, int b) {
    return (((r >> 3) + 1) * kSide + (g >> 3) + 1) * kSide + (b >> 3) + 1;
  };
  std::map<int, std::vector<Eigen::Vector3d>> bins;
  for (const cv::Point& p : pixels) {
    const Rgba& c = image.at(p.x, p.y);
    bins[key(c.r, c.g, c.b)].push_back(Eigen::Vector3d(c.r, c.g, c.b));
  }
  auto around =
      [&](int k,
          const std::function<void(std::map<int, std::vector<Eigen::Vector3d>>::iterator)>& f) {
        for (int dr = -1; dr <= 1; ++dr)
          for (int dg = -1; dg <= 1; ++dg)
            for (int db = -1; db <= 1; ++db) {
              auto it = bins.find(k + (dr * kSide + dg) * kSide + db);
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
    std::unordered_map<int, int> exact;  // packed RGB -> pixels
    around(best, [&](auto it) {
      for (const Eigen::Vector3d& c : it->second) {
        sum += c;
        if (exact_paint)
          ++exact[(static_cast<int>(c.x()) << 16) | (static_cast<int>(c.y()) << 8) |
                  static_cast<int>(c.z())];
      }
      taken.push_back(it->first);
    });
    for (int k : taken) bins.erase(k);
    Eigen::Vector3d flat = sum / static_cast<double>(held);
    // Flat paint is one exact colour: where one holds most of the cluster,
    // the colours within kExactRadius of it are the paint, and the blends
    // of a cel band's anti-aliased edge that fall into the neighbouring bins
    // are not. On two-tone drawings they pulled a region's flats towards
    // each other (dev two-tone 2000-2099: half the regions' flats moved
    // over 0.1 RGB, a tenth over 1.1 RGB once they were left out), so
    // pieces of one strand stepped over the rare paint's 0.5 RGB. (A
    // colour holding more than half is unique: no tie to break.)
    const auto unpack = [](int k) {
      return Eigen::Vector3d((k >> 16) & 255, (k >> 8) & 255, k & 255);
    };
    const auto mode =
        std::max_element(exact.begin(), exact.end(),
                         [](const auto& x, const auto& y) { return x.second < y.second; });
    if (mode != exact.end() && 2 * static_cast<std::size_t>(mode->second) > held) {
      const Eigen::Vector3d m = unpack(mode->first);
      Eigen::Vector3d near(0, 0, 0);
      int n = 0;
      for (const auto& [c, count] : exact) {
        const Eigen::Vector3d v = unpack(c);
        if ((v - m).norm() <= kExactRadius) near += count * v, n += count;
      }
      flat = near / static_cast<double>(n);
    }
    flats.push_back(flat);
  }
  return flats;
}

EdgePaint edge_paint(const Context& ctx, const Edge& e) {
  EdgePaint out;
  out.flats = flat_colours(*ctx.image, pixels_near(ctx, e, 5), 2, 0.15, true);
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
  out.flats = flat_colours(*ctx.image, pixels, 3, 0.05, true);
  std::vector<int> counts;
  for (const auto& [k, n] : exact) counts.push_back(n);
  std::sort(counts.rbegin(), counts.rend());
  int top = 0;
  for (std::size_t k = 0; k < counts.size() && k < 3; ++k) top += counts[k];
  out.exact_share = pixels.empty() ? 0.0 : static_cast<double>(top) / pixels.size();
  return out;
}

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
    out.off_gradient =
        out.step > (change.norm() < kMinShadingChange
                        ? kMaxFlatFitStep
                        : std::max(kMaxShadingStep, kFittedChangeShare * change.norm()));
    out.uneven_slopes = std::min(pa.slope.norm(), pb.slope.norm()) <
                        kUnevenSlopeShare * std::max(pa.slope.norm(), pb.slope.norm());
    return out;
  }
  out.step = std::max(0.0, (a.colour - b.colour).norm() - (a.colour_spread + b.colour_spread));
  return out;
}

}  // namespace hair25d::completion::detail

namespace hair25d::completion::detail {
namespace {

// Positions in the fields' sums are in units of this many pixels (well
// conditioned normal equations).
constexpr double kFieldScale = 100.0;
// A piece needs this many interior pixels for a field.
constexpr double kMinFieldPixels = 12.0;
// Pull towards no slope (per unit of kFieldScale, times the pixel count): a
// sliver's slope across it is not measured.
constexpr double kFieldPull = 1e-3;
// Ink inside a piece (drawn lines, dots): darker than this share of the
// piece's median luma (the generator's lines are the hair's colour times
// 0.2-0.35 or near black; its gradients run from 1.12 to 0.72 of it).
constexpr double kInkShare = 0.5;
// The field says something only where each piece is painted by a linear
// field (deviation at most this, RGB, as kLinearResidual for the strand
// joins' windows: cel bands, real shading, lines and noise deviate more),
// and where the joint field is a gradient: at least kMinFieldSlope RGB a
// px, predicting at least kMinFieldChange RGB between the pieces' centres.
// Pieces of one flat paint fit one field whatever strand they belong to
// (the annotated six: without the gradient rule 0.982 / 0.931 -> 0.790 /
// 0.940, their cap slivers and bangs joined); that is for the colour step
// to judge, as before.
constexpr double kMaxFieldResidual = 4.0;
constexpr double kMinFieldSlope = 0.1;
constexpr double kMinFieldChange = 6.0;

using Sums = RegionFields::Sums;

Eigen::Matrix3d fit(const Sums& s) {
  Eigen::Matrix3d xx = s.xx;
  xx(1, 1) += kFieldPull * s.n;
  xx(2, 2) += kFieldPull * s.n;
  return xx.ldlt().solve(s.xc);
}

// Mean square of the piece's colours about field `beta`.
double mean_square(const Sums& s, const Eigen::Matrix3d& beta) {
  const double sq =
      s.cc - 2.0 * (beta.transpose() * s.xc).trace() + (beta.transpose() * s.xx * beta).trace();
  return std::max(0.0, sq / s.n);
}

// Each piece's own field, when both pieces have pixels enough and each is
// linear itself: what RegionFields::step and cross_miss both ask first.
std::optional<std::pair<Eigen::Matrix3d, Eigen::Matrix3d>> own_fields(const Sums& sa,
                                                                      const Sums& sb) {
  if (sa.n < kMinFieldPixels || sb.n < kMinFieldPixels) return std::nullopt;
  Eigen::Matrix3d fa = fit(sa), fb = fit(sb);
  if (std::sqrt(mean_square(sa, fa)) > kMaxFieldResidual ||
      std::sqrt(mean_square(sb, fb)) > kMaxFieldResidual)
    return std::nullopt;
  return std::pair{fa, fb};
}

}  // namespace

const Sums& RegionFields::sums(int region) {
  auto it = sums_.find(region);
  if (it != sums_.end()) return it->second;
  Sums s;
  const cv::Rect box = ctx_->regions.at(region).box;
  const LabelMap& labels = *ctx_->original;
  const auto own = [&](int x, int y) { return labels.contains(x, y) && labels.at(x, y) == region; };
  const Vec2 o(0.5 * ctx_->image->width(), 0.5 * ctx_->image->height());
  const auto luma = [](const Rgba& p) { return 0.299 * p.r + 0.587 * p.g + 0.114 * p.b; };
  std::vector<cv::Point> inside;
  std::vector<double> lumas;
  // Pixels 2 px inside (the drawn line's anti-aliased rim is no paint), or
  // 1 px, or all, for a sliver.
  for (int m = 2; m >= 0 && static_cast<double>(inside.size()) < kMinFieldPixels; --m) {
    inside.clear();
    lumas.clear();
    for (int y = box.y; y < box.y + box.height; ++y)
      for (int x = box.x; x < box.x + box.width; ++x)
        if (own(x, y) && own(x - m, y) && own(x + m, y) && own(x, y - m) && own(x, y + m)) {
          inside.emplace_back(x, y);
          lumas.push_back(luma(ctx_->image->at(x, y)));
        }
  }
  if (inside.empty()) return sums_[region] = s;
  std::nth_element(lumas.begin(), lumas.begin() + lumas.size() / 2, lumas.end());
  const double ink = kInkShare * lumas[lumas.size() / 2];
  for (const cv::Point& q : inside) {
    const Rgba& p = ctx_->image->at(q.x, q.y);
    if (luma(p) < ink) continue;
    const Eigen::Vector3d d(1.0, (q.x + 0.5 - o.x()) / kFieldScale,
                            (q.y + 0.5 - o.y()) / kFieldScale);
    const Eigen::Vector3d c(p.r, p.g, p.b);
    s.n += 1;
    s.xx += d * d.transpose();
    s.xc += d * c.transpose();
    s.cc += c.squaredNorm();
  }
  return sums_[region] = s;
}

double RegionFields::step(int a, int b) {
  const Sums sa = sums(a), sb = sums(b);
  const auto own = own_fields(sa, sb);
  if (!own) return std::numeric_limits<double>::infinity();
  const auto& [fa, fb] = *own;
  Sums both;
  both.n = sa.n + sb.n;
  both.xx = sa.xx + sb.xx;
  both.xc = sa.xc + sb.xc;
  both.cc = sa.cc + sb.cc;
  const Eigen::Matrix3d joint = fit(both);
  // Rows 1, 2 of the fit: RGB per kFieldScale px along x and y.
  const Eigen::Matrix<double, 2, 3> slope = joint.bottomRows<2>() / kFieldScale;
  const Eigen::RowVector2d between((sb.xx(0, 1) / sb.n - sa.xx(0, 1) / sa.n) * kFieldScale,
                                   (sb.xx(0, 2) / sb.n - sa.xx(0, 2) / sa.n) * kFieldScale);
  // The gradient must be seen inside a piece: between two flat pieces of
  // slightly different colours the joint fit itself slopes.
  const auto own_slope = [](const Eigen::Matrix3d& f) {
    return f.bottomRows<2>().norm() / kFieldScale;
  };
  if (slope.norm() < kMinFieldSlope || std::max(own_slope(fa), own_slope(fb)) < kMinFieldSlope ||
      (between * slope).norm() < kMinFieldChange)
    return std::numeric_limits<double>::infinity();
  const auto excess = [&](const Sums& s, const Eigen::Matrix3d& f) {
    return std::sqrt(std::max(0.0, mean_square(s, joint) - mean_square(s, f)));
  };
  return excess(sa, fa) + excess(sb, fb);
}

std::pair<double, double> RegionFields::cross_miss(int a, const Vec2& at_a, int b,
                                                   const Vec2& at_b) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const Sums sa = sums(a), sb = sums(b);
  const auto own = own_fields(sa, sb);
  if (!own) return {kInf, kInf};
  const auto& [fa, fb] = *own;
  const Vec2 o(0.5 * ctx_->image->width(), 0.5 * ctx_->image->height());
  const auto at = [&](const Eigen::Matrix3d& beta, const Vec2& v) -> Eigen::Vector3d {
    const Eigen::Vector3d d(1.0, (v.x() - o.x()) / kFieldScale, (v.y() - o.y()) / kFieldScale);
    return beta.transpose() * d;
  };
  const double into_b = (at(fa, at_b) - at(fb, at_b)).norm();
  const double into_a = (at(fb, at_a) - at(fa, at_a)).norm();
  // The larger piece's field is the better measured one (a sliver's slope
  // across it is pulled to none).
  return {std::max(into_a, into_b), sa.n >= sb.n ? into_b : into_a};
}

}  // namespace hair25d::completion::detail

namespace hair25d::completion::detail {
namespace {

// Cel paint: this share of a piece's inner pixels within kCelTolerance RGB
// of its flat colours.
constexpr double kCelShare = 0.9;
constexpr double kCelTolerance = 6.0;
// Fewest inner pixels a piece's paint is measured on.
constexpr int kMinCelPixels = 12;
// A cel drawing: this share of its regions with at least
// kMinCelDrawingPixels inner pixels are cel paint.
constexpr double kCelDrawingShare = 0.75;
constexpr int kMinCelDrawingPixels = 200;
// RegionCels::judge. Mass and path candidates of generated seeds 101-116
// (a temporary print, labelled by the generator's strands): flat, one
// strand 120 all at 0-1.0 RGB, two strands 122: 1 at 1.0, 2 at 1.4, the
// rest 3 and up; two-tone, one strand 90: 86 at 0-1.0, 3 at 1.4-2.7; two
// strands 115: 4 at 0.3-0.9 (all on the wrong side of the level), 15 at
// 1-3. Two-tone 101-116 with (refuse, join) at (2, 1), (3, 1.5), (5, 1):
// the same pairs as (3, 1).
constexpr double kMaxSameCelStep = 1.0;
constexpr double kMinOtherCelStep = 3.0;

}  // namespace

const RegionCels::Cel& RegionCels::cel(int region) {
  auto it = cels_.find(region);
  if (it != cels_.end()) return it->second;
  Cel c;
  const cv::Rect box = ctx_->regions.at(region).box;
  const LabelMap& labels = *ctx_->original;
  const auto own = [&](int x, int y) { return labels.contains(x, y) && labels.at(x, y) == region; };
  std::vector<cv::Point> inside;
  for (int m = 2; m >= 0 && static_cast<int>(inside.size()) < 4 * kMinCelPixels; --m) {
    inside.clear();
    for (int y = box.y; y < box.y + box.height; ++y)
      for (int x = box.x; x < box.x + box.width; ++x)
        if (own(x, y) && own(x - m, y) && own(x + m, y) && own(x, y - m) && own(x, y + m))
          inside.emplace_back(x, y);
  }
  c.pixels = static_cast<int>(inside.size());
  if (c.pixels >= kMinCelPixels) {
    // The mean, not the exact paint (flat_colours' `exact_paint`): the cel
    // judgement's limits and the rare cel paths' sharing were set on it.
    // Exact paint here too (with `same` at most 0.5 RGB) raised dev recall
    // more but lost precision on fresh mixed 8000-8099 (0.959 -> 0.949: a
    // region join merged a lock of 7 pieces with one of 2); session 25.
    c.flats = flat_colours(*ctx_->image, inside, 3, 0.02);
    std::vector<std::vector<double>> rows(c.flats.size());
    int near = 0;
    for (const cv::Point& p : inside) {
      const Eigen::Vector3d v = rgb_at(*ctx_, p.x, p.y);
      int best = -1;
      double d = kCelTolerance;
      for (std::size_t k = 0; k < c.flats.size(); ++k)
        if ((v - c.flats[k]).norm() <= d) d = (v - c.flats[k]).norm(), best = static_cast<int>(k);
      if (best < 0) continue;
      ++near;
      rows[best].push_back(p.y + 0.5);
    }
    c.share = static_cast<double>(near) / c.pixels;
    for (auto& r : rows) {
      std::sort(r.begin(), r.end());
      c.top.push_back(r.empty() ? 0.0 : r[r.size() / 20]);
      c.bottom.push_back(r.empty() ? 0.0 : r[r.size() - 1 - r.size() / 20]);
    }
  }
  return cels_[region] = c;
}

// The darker kMinShade-kMaxShade of the lighter on every channel, the
// channels' ratios within kShadeSpread of each other (the generator's band
// is 0.72 of the base); the lighter at least kMinShadeLight on every
// channel.
constexpr double kMinShade = 0.5, kMaxShade = 0.9, kShadeSpread = 0.06;
constexpr double kMinShadeLight = 16.0;

bool shade_of(const Eigen::Vector3d& light, const Eigen::Vector3d& dark) {
  if (light.minCoeff() < kMinShadeLight) return false;
  const Eigen::Vector3d r = dark.cwiseQuotient(light);
  return r.minCoeff() >= kMinShade && r.maxCoeff() <= kMaxShade &&
         r.maxCoeff() - r.minCoeff() <= kShadeSpread;
}

namespace {

constexpr double kLevelSlack = 0.1;

// A piece painted in a base and its cel shadow: its two commonest flat
// colours, one the other's shade (shade_of).
bool shaded(const RegionCels::Cel& c) {
  if (c.flats.size() < 2) return false;
  Eigen::Vector3d light = c.flats[0], dark = c.flats[1];
  if (light.sum() < dark.sum()) std::swap(light, dark);
  if (!shade_of(light, dark)) return false;
  // Below a level: the band's rows begin where the base's end (within
  // kLevelSlack of the piece's height; a strand's band runs along it beside
  // the base).
  const std::size_t base = c.flats[0].sum() >= c.flats[1].sum() ? 0 : 1, band = 1 - base;
  const double height = std::max(1.0, c.bottom[band] - c.top[base]);
  return c.top[band] >= c.bottom[base] - kLevelSlack * height;
}

}  // namespace

double RegionCels::step(int a, int b, bool* level) {
  const Cel& ca = cel(a);
  const Cel& cb = cel(b);
  if (level) *level = false;
  if (ca.share < kCelShare || cb.share < kCelShare || ca.flats.empty() || cb.flats.empty())
    return std::numeric_limits<double>::infinity();
  // The flats of `from` against the nearest of `to`: the worst distance,
  // and whether each lies on its side of `to`'s level.
  const auto one_way = [](const Cel& from, const Cel& to, bool* side) {
    double worst = 0.0;
    *side = shaded(to);
    for (std::size_t i = 0; i < from.flats.size(); ++i) {
      std::size_t best = 0;
      for (std::size_t k = 1; k < to.flats.size(); ++k)
        if ((from.flats[i] - to.flats[k]).norm() < (from.flats[i] - to.flats[best]).norm())
          best = k;
      worst = std::max(worst, (from.flats[i] - to.flats[best]).norm());
      if (to.flats.size() < 2) continue;
      // The other flat of `to` (its commonest other than `best`).
      const std::size_t other = best == 0 ? 1 : 0;
      const bool darker = to.flats[best].sum() < to.flats[other].sum();
      // Band below the base: a piece in the band reaches below the band's
      // top; in the base, above the base's bottom.
      if (darker)
        *side = *side && from.bottom[i] >= to.top[best];
      else
        *side = *side && from.top[i] <= to.bottom[best];
    }
    return worst;
  };
  bool side_ab = false, side_ba = false;
  const double ab = one_way(ca, cb, &side_ab), ba = one_way(cb, ca, &side_ba);
  if (level) *level = ab <= ba ? side_ab : side_ba;
  return std::min(ab, ba);
}

RegionCels::Judgement RegionCels::judge(int a, int b) {
  Judgement out;
  if (!cel_drawing()) return out;
  bool level = false;
  out.step = step(a, b, &level);
  if (!std::isfinite(out.step)) return out;
  out.other = out.step > kMinOtherCelStep;
  out.same = out.step <= kMaxSameCelStep && level;
  return out;
}

bool RegionCels::cel_drawing() {
  if (cel_drawing_ < 0) {
    int big = 0, flat = 0;
    for (const auto& [id, info] : ctx_->regions) {
      const Cel& c = cel(id);
      if (c.pixels < kMinCelDrawingPixels) continue;
      ++big;
      flat += c.share >= kCelShare;
    }
    cel_drawing_ = big > 0 && flat >= kCelDrawingShare * big;
  }
  return cel_drawing_ == 1;
}

}  // namespace hair25d::completion::detail
