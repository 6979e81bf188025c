#include "join_features.h"

#include <algorithm>
#include <cmath>

#include "hair25d/completion/bezier.h"
#include "raster.h"

namespace hair25d::completion::detail {
namespace {

// Samples across a piece, parallel to its cut, at two depths inside it: a
// strand keeps its width profile and the positions of its shading bands
// under the occluder, so the profile of one piece read from p to q matches
// the other's read from q to p.
constexpr int kAcross = 7;
constexpr double kDepths[2] = {3.0, 6.0};

struct Profile {
  std::array<Eigen::Vector3d, kAcross> rgb;
  std::array<bool, kAcross> valid{};
};

Profile profile(const Context& ctx, const Edge& e) {
  Profile out;
  Vec2 inward = -(e.tangent_p + e.tangent_q);
  if (inward.norm() < 1e-6) {
    const Vec2 chord = e.q - e.p;
    inward = Vec2(-chord.y(), chord.x());
  }
  inward.normalize();
  for (int k = 0; k < kAcross; ++k) {
    const Vec2 on = e.p + (e.q - e.p) * ((k + 0.5) / kAcross);
    Eigen::Vector3d sum(0, 0, 0);
    int n = 0;
    for (double d : kDepths) {
      const Vec2 at = on + inward * d;
      const int x = static_cast<int>(std::floor(at.x())), y = static_cast<int>(std::floor(at.y()));
      if (!ctx.original->contains(x, y) || ctx.original->at(x, y) != e.region) continue;
      const Rgba& c = ctx.image->at(x, y);
      sum += Eigen::Vector3d(c.r, c.g, c.b);
      ++n;
    }
    out.valid[k] = n > 0;
    out.rgb[k] = n > 0 ? Eigen::Vector3d(sum / n) : Eigen::Vector3d(0, 0, 0);
  }
  return out;
}

double luma(const Eigen::Vector3d& c) { return 0.299 * c.x() + 0.587 * c.y() + 0.114 * c.z(); }

}  // namespace

JoinFeatures join_features(const Context& ctx, const Edge& a, const Edge& b, const JoinTerms& t,
                           const std::set<int>& front, const std::map<int, int>& edge_count) {
  JoinFeatures f{};
  f[0] = static_cast<float>(t.mean_angle);
  f[1] = static_cast<float>(t.worst_angle);
  f[2] = static_cast<float>(t.colour);
  f[3] = static_cast<float>(t.colour_step);
  f[4] = static_cast<float>(t.width_change);
  f[5] = static_cast<float>(t.gap_per_width);
  f[6] = static_cast<float>(t.bulge);
  f[7] = t.common_occluder ? 0.0f : 1.0f;
  f[8] = static_cast<float>(1.0 - t.cover);
  f[9] = static_cast<float>(t.hand_cost);
  f[10] = static_cast<float>(std::log(std::max(t.wide, 1.0)));
  f[11] = static_cast<float>(std::log1p(std::max(t.gap, 0.0)));

  // Profiles: a's p → q against b's q → p (p_a meets q_b).
  const Profile pa = profile(ctx, a), pb = profile(ctx, b);
  double dl = 0, drgb = 0;
  int n = 0;
  std::array<double, kAcross> la{}, lb{};
  for (int k = 0; k < kAcross; ++k) {
    const int m = kAcross - 1 - k;
    if (!pa.valid[k] || !pb.valid[m]) continue;
    la[n] = luma(pa.rgb[k]);
    lb[n] = luma(pb.rgb[m]);
    dl += std::abs(la[n] - lb[n]);
    drgb += (pa.rgb[k] - pb.rgb[m]).norm();
    ++n;
  }
  double corr = 0, spread = 0;
  if (n >= 3) {
    double ma = 0, mb = 0;
    for (int i = 0; i < n; ++i) ma += la[i], mb += lb[i];
    ma /= n, mb /= n;
    double sab = 0, saa = 0, sbb = 0;
    for (int i = 0; i < n; ++i) {
      sab += (la[i] - ma) * (lb[i] - mb);
      saa += (la[i] - ma) * (la[i] - ma);
      sbb += (lb[i] - mb) * (lb[i] - mb);
    }
    // Flat profiles have no shape to compare.
    if (saa > 4.0 * n && sbb > 4.0 * n) corr = sab / std::sqrt(saa * sbb);
    spread = std::max(std::sqrt(saa / n), std::sqrt(sbb / n));
  }
  f[12] = static_cast<float>(n > 0 ? dl / n / 255.0 : 1.0);
  f[13] = static_cast<float>(n > 0 ? drgb / n / 255.0 : 1.0);
  f[14] = static_cast<float>(corr);
  f[15] = static_cast<float>(spread / 255.0);
  f[16] = static_cast<float>((a.colour_spread + b.colour_spread) / 100.0);

  // What the middle of the hypothesised strand passes under.
  const CubicBezier first = join_bezier(a.p, a.tangent_p, b.q, -b.tangent_q);
  const CubicBezier second = join_bezier(b.p, b.tangent_p, a.q, -a.tangent_q);
  constexpr int kAlong = 16;
  int both = 0, unlabelled = 0, one = 0, counted = 0;
  std::set<int> crossed;
  for (int k = 0; k < kAlong; ++k) {
    const double s = (k + 0.5) / kAlong;
    const int l = ctx.label((first.point(s) + second.point(1.0 - s)) * 0.5);
    if (l == a.region || l == b.region) continue;
    ++counted;
    if (l == 0) {
      ++unlabelled;
      continue;
    }
    const bool over_a = ctx.is_above(l, a.region), over_b = ctx.is_above(l, b.region);
    both += over_a && over_b;
    one += over_a != over_b;
    if (over_a || over_b) crossed.insert(l);
  }
  f[17] = counted > 0 ? static_cast<float>(both) / counted : 1.0f;
  f[18] = counted > 0 ? static_cast<float>(unlabelled) / counted : 0.0f;
  f[19] = counted > 0 ? static_cast<float>(one) / counted : 0.0f;
  f[20] = static_cast<float>(std::min<std::size_t>(crossed.size(), 4)) / 4.0f;

  // Pieces above no region are back hair; a piece occluded at two places
  // continues somewhere.
  f[21] = 0.5f * static_cast<float>(!front.count(a.region) + !front.count(b.region));
  auto edges_of = [&](int region) {
    auto it = edge_count.find(region);
    return std::min(it != edge_count.end() ? it->second : 0, 4);
  };
  const int ea = edges_of(a.region), eb = edges_of(b.region);
  f[22] = static_cast<float>(std::min(ea, eb)) / 4.0f;
  f[23] = static_cast<float>(std::max(ea, eb)) / 4.0f;

  // Strands run from the head outwards: the join's direction against the
  // direction from the head.
  const Vec2 ma = 0.5 * (a.p + a.q), mb = 0.5 * (b.p + b.q);
  const Vec2 chord = mb - ma, radial = 0.5 * (ma + mb) - ctx.head;
  f[24] = chord.norm() > 1e-6 && radial.norm() > 1e-6
              ? static_cast<float>(std::abs(chord.dot(radial)) / (chord.norm() * radial.norm()))
              : 0.0f;
  // A long piece against a nub peeking out from under an occluder.
  auto elongation = [&](const Edge& e) {
    auto it = ctx.regions.find(e.region);
    const double pixels = it != ctx.regions.end() ? it->second.pixels : 0;
    const double w = std::max(e.width, 1.0);
    return std::log(std::max(pixels, 1.0) / (w * w));
  };
  const double ga = elongation(a), gb = elongation(b);
  f[25] = static_cast<float>(std::min(ga, gb));
  f[26] = static_cast<float>(std::max(ga, gb));
  const auto ra = ctx.regions.find(a.region), rb = ctx.regions.find(b.region);
  f[31] = ra != ctx.regions.end() && rb != ctx.regions.end()
              ? static_cast<float>((ra->second.colour - rb->second.colour).norm() / 90.0)
              : 0.0f;
  // Session 14: the paint and tone terms the hand cost gained since the
  // scorer was first trained (each in the hand cost too, f[9], but the sum
  // hides which of them moved it).
  f[32] = static_cast<float>(std::min(t.paint_step, 60.0) / 30.0);
  f[33] = t.flat_paint ? 1.0f : 0.0f;
  f[34] = t.shading_continues ? 1.0f : 0.0f;
  f[35] = t.rare_paint ? 1.0f : 0.0f;
  f[36] = static_cast<float>(std::clamp(t.tone_cost, -3.0, 3.0));
  f[37] = t.one_sided ? 1.0f : 0.0f;
  // Session 17: the dots' tone match the tone cost sums into one number,
  // its continuous steps, and whether one occluder hides the whole gap.
  f[38] = t.tone_match > 0 ? 1.0f : 0.0f;
  f[39] = t.tone_match < 0 ? 1.0f : 0.0f;
  f[40] = t.mass_step >= 0 ? static_cast<float>(std::min(t.mass_step, 0.5)) : 0.6f;
  f[41] = static_cast<float>(std::min(t.dark_step, 0.3));
  f[42] = static_cast<float>(t.top_occluder);
  f[43] = static_cast<float>(std::min(t.patch_occluders, 4)) / 4.0f;
  // Session 35: an angle refusal's second chance (zero for the others,
  // where the nets trained before have no weights).
  if (t.retried) {
    f[44] = 1.0f;
    f[45] = static_cast<float>(std::min(t.own_worst_angle, 3.0));
    f[46] = static_cast<float>(t.arm_min);
    f[47] = static_cast<float>(t.arm_mean);
    f[48] = static_cast<float>(t.ends_part);
    f[49] = t.retried_either_end ? 1.0f : 0.0f;
    f[50] = t.retried_reversed ? 1.0f : 0.0f;
    f[51] = t.retried_side ? 1.0f : 0.0f;
    f[52] = t.retried_turned ? 1.0f : 0.0f;
    f[53] = static_cast<float>(std::clamp(t.sliver, 0.0, 4.0));
  }
  // Session 36: a cover refusal's second chance (zero for the others).
  if (t.cover_retried) {
    f[54] = 1.0f;
    f[55] = static_cast<float>(t.miss_paper);
    f[56] = static_cast<float>(t.miss_face);
    f[57] = static_cast<float>(t.miss_ink);
    f[58] = static_cast<float>(t.miss_below);
    f[59] = static_cast<float>(t.miss_sibling);
    f[60] = static_cast<float>(t.miss_other);
    f[61] = static_cast<float>(std::clamp(t.shape_cover, 0.0, 1.0));
    f[62] = static_cast<float>(std::log1p(std::min(t.miss_per_width, 50.0)));
    f[63] = static_cast<float>(t.miss_at_cuts);
  }
  // Session 39: the pieces' fields across the gap, every candidate (no
  // net trained before reads them: their weights there are zero).
  const auto rgb = [](double v) {
    return v < 0 ? -1.0f : static_cast<float>(std::min(v, 60.0) / 30.0);
  };
  f[75] = rgb(t.field_cross_max);
  f[76] = rgb(t.field_cross_larger);
  return f;
}

void add_rival_features(const std::vector<double>& costs,
                        const std::vector<std::pair<int, int>>& ends, double band_high,
                        std::vector<JoinFeatures>* features) {
  // Cheapest other candidate and number of others within the band, per edge.
  constexpr double kNone = 4.0;
  std::map<int, std::vector<int>> of_edge;
  for (std::size_t i = 0; i < ends.size(); ++i) {
    of_edge[ends[i].first].push_back(static_cast<int>(i));
    of_edge[ends[i].second].push_back(static_cast<int>(i));
  }
  for (std::size_t i = 0; i < ends.size(); ++i) {
    double margin[2], rivals[2];
    const int sides[2] = {ends[i].first, ends[i].second};
    for (int s = 0; s < 2; ++s) {
      double best = kNone;
      int count = 0;
      for (int j : of_edge[sides[s]]) {
        if (j == static_cast<int>(i)) continue;
        best = std::min(best, costs[j]);
        count += costs[j] <= band_high;
      }
      margin[s] = std::clamp(best - costs[i], -kNone, kNone);
      rivals[s] = std::min(count, 5) / 5.0;
    }
    JoinFeatures& f = (*features)[i];
    f[27] = static_cast<float>(std::min(margin[0], margin[1]));
    f[28] = static_cast<float>(std::max(margin[0], margin[1]));
    f[29] = static_cast<float>(std::min(rivals[0], rivals[1]));
    f[30] = static_cast<float>(std::max(rivals[0], rivals[1]));
  }
}

}  // namespace hair25d::completion::detail
