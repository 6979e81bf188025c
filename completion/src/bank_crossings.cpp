#include "bank_crossings.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "join_paint.h"

namespace hair25d::completion::detail {
namespace {

// Farthest a piece is followed inwards behind an edge, pixels.
constexpr double kMaxDepth = 200.0;
// A ray lands next to an edge when it ends within this many pixels of it.
constexpr double kLandingReach = 3.0;
// Minimum depth behind both edges, in widths crossed.
constexpr double kMinDepthRatio = 1.5;
// ... unless the piece is a *window* (session 12): at least this share of
// its edge's rays, run inwards across it, end under one of its occluders — a
// piece seen between two strands lying over it (a cap sliver between bangs),
// not a strand end lying on the wide piece, whose far side shows. Its rays
// also reach up to kMaxDepth, not 0.6 edge lengths. Seeds 101-116: flat
// 0.968 / 0.775 -> 0.973 / 0.793, gradient 0.969 / 0.797 -> 0.969 / 0.812,
// two-tone, screentone and the annotated six unchanged; share 0.5: two-tone
// precision 0.884 -> 0.856; without the longer reach only flat gains (0.972
// / 0.779).
constexpr double kMinWindowShare = 0.9;

std::vector<BankRay> landing_next_to(const std::vector<BankRay>& hits, const Edge& target) {
  std::vector<BankRay> kept;
  for (const BankRay& h : hits) {
    double best = 1e18;
    for (const Vec2& p : target.points) best = std::min(best, (p - std::get<2>(h)).squaredNorm());
    if (best <= kLandingReach * kLandingReach) kept.push_back(h);
  }
  return kept;
}

}  // namespace

std::optional<std::pair<Vec2, Vec2>> outward_ray(const Context& ctx,
                                                 const std::vector<cv::Point>& contour, int i,
                                                 int id) {
  const int n = static_cast<int>(contour.size());
  const cv::Point& ahead = contour[(i + 3) % n];
  const cv::Point& behind = contour[(i - 3 + n) % n];
  const Vec2 t(ahead.x - behind.x, ahead.y - behind.y);
  if (t.norm() < 1.0) return std::nullopt;
  Vec2 normal(-t.y(), t.x());
  normal.normalize();
  const Vec2 p(contour[i].x + 0.5, contour[i].y + 0.5);
  if (ctx.label(p + 2.0 * normal) == id) normal = -normal;
  return std::make_pair(p, normal);
}

std::vector<Polyline> ray_bands(const std::vector<BankRay>& rays) {
  std::vector<Polyline> out;
  std::size_t k = 0;
  while (k < rays.size()) {
    std::size_t end = k + 1;
    while (end < rays.size() && std::get<0>(rays[end]) - std::get<0>(rays[end - 1]) <= 4) ++end;
    if (end - k >= 2) {
      Polyline band;
      for (std::size_t r = k; r < end; ++r) band.push_back(std::get<1>(rays[r]));
      for (std::size_t r = end; r-- > k;) band.push_back(std::get<2>(rays[r]));
      out.push_back(std::move(band));
    }
    k = end;
  }
  return out;
}

BankCrossings cross_occluders(const Context& ctx, const Edge& edge) {
  BankCrossings out;
  const Polyline& pts = edge.points;
  const int n = static_cast<int>(pts.size());
  // The far bank lies within a fraction of the edge's length only when the
  // piece is wide compared with the occluder over it.
  const double reach = std::max(6.0, 0.6 * n);
  for (int i = 0; i < n; i += 2) {
    const Vec2 t = pts[std::min(i + 3, n - 1)] - pts[std::max(i - 3, 0)];
    if (t.norm() < 1.0) continue;
    Vec2 normal(-t.y(), t.x());
    normal.normalize();
    if (ctx.label(pts[i] + 2.0 * normal) == edge.region) normal = -normal;
    ++out.rays;
    double inside = 0.0;
    while (inside < kMaxDepth && ctx.label(pts[i] - (inside + 1.0) * normal) == edge.region)
      inside += 1.0;
    out.depth += inside;
    // Just beyond the piece's far side an occluder of the piece makes the
    // ray a window's.
    bool window = false;
    for (double k = 1.0; k <= 4.0; k += 1.0) {
      const int l = ctx.label(pts[i] - (inside + k) * normal);
      if (l == edge.region) continue;
      window = l != 0 && ctx.is_above(l, edge.region);
      break;
    }
    out.window += window;
    // A window's far bank lies across a whole strand, however short the edge.
    const double reach_here = window ? kMaxDepth : reach;
    std::set<int> crossed;
    double unlabelled = 0.0;  // length of the current run of label 0
    for (double s = 1.0; s <= reach_here; s += 0.7) {
      const Vec2 x = pts[i] + s * normal;
      const int l = ctx.label(x);
      if (l == edge.region && s < 3.0) continue;  // the outline pixels next to the start
      if (l == 0 && !crossed.empty() && (unlabelled += 0.7) <= kMaxOutlineGap) continue;
      unlabelled = 0.0;
      if (l == 0 || l == edge.region) break;
      if (ctx.is_above(l, edge.region)) {
        crossed.insert(l);
        continue;
      }
      bool under = !crossed.empty();
      for (int c : crossed) under = under && ctx.is_above(c, l);
      if (under) out.hits[l].emplace_back(i, pts[i], x);
      break;
    }
  }
  if (out.rays > 0) {
    out.depth /= out.rays;
    out.window /= out.rays;
  }

  return out;
}

BankJoin bank_join(const BankCrossings& ca, const BankCrossings& cb, const Edge& a, const Edge& b) {
  BankJoin join;
  auto ia = ca.hits.find(b.region);
  auto ib = cb.hits.find(a.region);
  if (ia == ca.hits.end() || ib == cb.hits.end() || ca.rays == 0 || cb.rays == 0) return join;
  const std::vector<BankRay> from_a = landing_next_to(ia->second, b);
  const std::vector<BankRay> from_b = landing_next_to(ib->second, a);
  if (from_a.empty() || from_b.empty()) return join;
  double across = 0.0;
  for (const BankRay& r : from_a) across += (std::get<2>(r) - std::get<1>(r)).norm();
  across /= static_cast<double>(from_a.size());
  const double depth = kMinDepthRatio * across;
  auto window = [&](const BankCrossings& c) {
    return c.depth < depth && c.window >= kMinWindowShare;
  };
  if ((ca.depth < depth && !window(ca)) || (cb.depth < depth && !window(cb))) return join;
  join.window = window(ca) || window(cb);
  join.share = std::min(static_cast<double>(from_a.size()) / ca.rays,
                        static_cast<double>(from_b.size()) / cb.rays);
  join.bands = ray_bands(from_a);
  return join;
}

}  // namespace hair25d::completion::detail

namespace hair25d::completion::detail {
namespace {

// Fewest landing rays (every other outline pixel) each way: a pixel or two
// of a piece that happen to face another through a gap are no cut. 6 before:
// back hair seen in slivers between strands (and above and below the face)
// faces its other pieces with 3–5 rays; on generated seeds 101–116 (four
// shadings) the candidates with 3–5 rays and a colour step <= 10 were all
// right ones.
constexpr int kMinMassRays = 3;
// A piece must reach behind the outline the rays leave from at least this
// share of the width they cross (a strand end lying on the back hair is
// thin). 0.5 before: right candidates measured 0.30–2.8 (a third of them
// below 0.5: back hair between the face and a wide side lock), wrong ones
// with a colour step <= 10 mostly 0.02–0.26 (strand tips on the face), two
// 0.32 and 0.43 (a bang lying on the face, in the back hair's colour).
constexpr double kMinMassDepthRatio = 0.3;

struct MassRay {
  int index = 0;  // along the outline
  Vec2 from{0, 0}, to{0, 0};
  double depth = 0.0;
  Eigen::Vector3d colour_from{0, 0, 0}, colour_to{0, 0, 0};
  double spread = 0.0;  // the two windows' RGB standard deviations, summed
};

// Median over rays of the colour step across the cut: shading (gradients,
// cel bands, tone) changes little across a strand but much across a head.
double median_spread(const std::vector<MassRay>& list) {
  std::vector<double> v;
  for (const MassRay& r : list) v.push_back(r.spread);
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

double median_colour_step(const std::vector<MassRay>& list) {
  std::vector<double> steps;
  for (const MassRay& r : list) steps.push_back((r.colour_from - r.colour_to).norm());
  std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
  return steps[steps.size() / 2];
}

}  // namespace

Eigen::Vector3d colour_near(const Context& ctx, int region, const Vec2& at, const Vec2& inward,
                            double* spread) {
  const Vec2 c = at + 6.0 * inward;
  Eigen::Vector3d sum(0, 0, 0);
  double squares = 0.0;
  int count = 0;
  for (int dy = -5; dy <= 5; ++dy)
    for (int dx = -5; dx <= 5; ++dx) {
      const int x = static_cast<int>(std::floor(c.x())) + dx;
      const int y = static_cast<int>(std::floor(c.y())) + dy;
      if (!ctx.original->contains(x, y) || ctx.original->at(x, y) != region) continue;
      const Rgba& px = ctx.image->at(x, y);
      const Eigen::Vector3d v(px.r, px.g, px.b);
      sum += v;
      squares += v.squaredNorm();
      ++count;
    }
  if (count == 0) {
    if (spread) *spread = 0.0;
    return ctx.regions.at(region).colour;
  }
  const Eigen::Vector3d mean = sum / count;
  if (spread) *spread = std::sqrt(std::max(0.0, squares / count - mean.squaredNorm()));
  return mean;
}

TailedHair tailed_hair(const Context& ctx, const std::set<int>& front) {
  // Back hair with tails hanging from under it lies above them, so it is
  // front hair too. A tail: a lowest region covered only by regions that lie
  // above lowest regions only (back hair itself also lies under the cap,
  // bangs and strands lying over other strands). A covered piece lying
  // above tails only is back hair as well: a source and a target, which
  // rays still cross to what lies beyond (it may be a strand lying on a
  // lock). On generated seeds 101-116 the generator's back hair over its
  // tails was otherwise left apart (flat and two-tone 112-115: 0.681 /
  // 0.508 -> 0.805 / 0.574); the looser rule without the tail test (any
  // region above lowest ones only) also took bangs and behind-strands lying
  // on one sliver of back hair (annotated case2 4-8 joined, precision 0.982
  // -> 0.973).
  std::set<int> over_lowest;
  TailedHair out;
  for (const auto& [id, info] : ctx.regions) {
    if (!front.count(id)) continue;
    bool only_lowest = true;
    for (const auto& [low, low_info] : ctx.regions)
      if (low_info.occluders.count(id)) only_lowest = only_lowest && !front.count(low);
    if (only_lowest) over_lowest.insert(id);
  }
  // The locks of a tail may lie on each other (the generator hangs up to
  // four): a lock lying on lowest locks only is then above a region, so the
  // back hair over it lay on other hair and was no back hair (flat 114: the
  // back over two stacked pairs of locks). Such a lock is *stacked* when all
  // that covers it lies on lowest regions and such locks only, and on at
  // least one lowest region itself (the back hair hangs both locks); that
  // cover counts as lying above lowest regions only.
  std::set<int> stacked, over_stack;
  for (const auto& [id, info] : ctx.regions) {
    if (!front.count(id) || over_lowest.count(id)) continue;
    bool on_tails = true, on_lowest = false;
    for (const auto& [low, low_info] : ctx.regions) {
      if (!low_info.occluders.count(id)) continue;
      on_tails = on_tails && (!front.count(low) || over_lowest.count(low));
      on_lowest = on_lowest || !front.count(low);
    }
    if (on_tails && on_lowest) over_stack.insert(id);
  }
  for (int id : over_lowest) {
    const std::set<int>& ups = ctx.regions.at(id).occluders;
    bool hangs = !ups.empty();
    for (int up : ups) hangs = hangs && over_stack.count(up) > 0;
    if (hangs) stacked.insert(id);
  }
  // The cover joins the pieces over lowest regions when it hangs a stacked
  // lock. Any such cover (also a side lock lying on back hair and on a
  // lock) gained more on two-tone 101-116 (0.784 / 0.557 -> 0.799 / 0.592)
  // but is the strand lying on other hair of the tests (annotated case2 4-8
  // was joined by a rule like it). Flat 101-116 0.932 / 0.557 -> 0.928 /
  // 0.572, gradient 0.933 / 0.568 -> 0.935 / 0.579; seeds 201-216 two-tone
  // 0.839 / 0.505 -> 0.841 / 0.513, screentone 0.758 / 0.281 -> 0.767 /
  // 0.296, gradient 0.807 / 0.485 -> 0.801 / 0.485; the rest unchanged.
  for (int id : over_stack)
    for (int lock : stacked)
      if (ctx.regions.at(lock).occluders.count(id)) over_lowest.insert(id);
  for (int id : stacked) over_lowest.erase(id);
  for (int id : over_lowest) {
    const RegionInfo& info = ctx.regions.at(id);
    if (info.occluders.empty()) continue;
    bool over_tail_only = true;
    for (const auto& [low, low_info] : ctx.regions) {
      if (!low_info.occluders.count(id)) continue;
      for (int up : low_info.occluders)
        over_tail_only = over_tail_only && (over_lowest.count(up) > 0 || stacked.count(up) > 0);
    }
    if (over_tail_only) out.over_tails.insert(id);
  }
  for (const auto& [id, info] : ctx.regions) {
    if (front.count(id) || info.occluders.empty()) continue;
    bool tail = true;
    for (int up : info.occluders)
      tail = tail && (out.over_tails.count(up) > 0 || stacked.count(up) > 0);
    if (tail) out.tails.insert(id);
  }
  // A stacked lock under back hair hangs as a tail does (kept out of the
  // face joins too).
  for (int id : stacked) {
    bool tail = true;
    for (int up : ctx.regions.at(id).occluders) tail = tail && out.over_tails.count(up) > 0;
    if (tail) out.tails.insert(id);
  }
  return out;
}

void untail_back_paint(const Context& ctx, const std::set<int>& front, RegionCels& cels,
                       TailedHair* tailed) {
  if (tailed->tails.empty() || !cels.cel_drawing()) return;
  // The back: pieces above no region and back hair over tails, no tail.
  std::vector<int> back;
  for (const auto& [id, info] : ctx.regions)
    if ((!front.count(id) || tailed->over_tails.count(id)) && !tailed->tails.count(id))
      back.push_back(id);
  std::vector<int> painted;
  for (int t : tailed->tails)
    for (int b : back)
      if (cels.judge(t, b).same) {
        painted.push_back(t);
        break;
      }
  for (int t : painted) tailed->tails.erase(t);
}

std::vector<MassJoin> mass_join_candidates(const Context& ctx, RegionTones& tones,
                                           RegionFields& fields) {
  const std::set<int> front = ctx.front();
  const TailedHair tailed = tailed_hair(ctx, front);
  const std::set<int>& over_tails = tailed.over_tails;
  cv::Rect hair;
  for (const auto& [id, info] : ctx.regions) hair = hair.area() == 0 ? info.box : (hair | info.box);
  const double reach = 0.5 * std::max(hair.width, hair.height);
  // rays[a][b]: rays from a's outline landing on b.
  std::map<int, std::map<int, std::vector<MassRay>>> rays;
  for (const auto& [id, info] : ctx.regions) {
    if ((front.count(id) && !over_tails.count(id)) || info.occluders.empty()) continue;
    const auto& c = info.contour;
    const int n = static_cast<int>(c.size());
    if (n < 8) continue;
    for (int i = 0; i < n; i += 2) {
      const auto leaving = outward_ray(ctx, c, i, id);
      if (!leaving) continue;
      const auto& [p, normal] = *leaving;
      // The ray leaves the piece into a region above it, crosses front hair
      // only, and lands on the first other piece, which the region it leaves
      // last must lie above (the occluders at both cuts). Strands of the fan
      // need not touch both pieces, so no relation need say they lie above
      // both.
      int first = 0, last = 0;
      double unlabelled = 0.0;  // length of the current run of label 0
      for (double s = 1.0; s <= reach; s += 0.7) {
        const Vec2 x = p + s * normal;
        const int l = ctx.label(x);
        if (l == id && s < 3.0) continue;
        if (l == 0 && first != 0 && (unlabelled += 0.7) <= kMaxOutlineGap) continue;
        unlabelled = 0.0;
        if (l == id || l == 0) break;
        if (first == 0) {
          if (!ctx.is_above(l, id)) break;
          first = l;
        }
        auto land = [&] {
          double depth = 0.0;
          while (depth < 200.0 && ctx.label(p - (depth + 1.0) * normal) == id) depth += 1.0;
          double spread_from = 0.0, spread_to = 0.0;
          const Eigen::Vector3d from = colour_near(ctx, id, p, -normal, &spread_from);
          const Eigen::Vector3d to = colour_near(ctx, l, x, normal, &spread_to);
          rays[id][l].push_back({i, p, x, depth, from, to, spread_from + spread_to});
        };
        if (front.count(l)) {
          // Back hair over tails is landed on and crossed.
          if (over_tails.count(l) && l != id && ctx.is_above(last, l) && !ctx.is_above(l, id) &&
              !ctx.is_above(id, l))
            land();
          last = l;
          continue;
        }
        if (!ctx.is_above(last, l)) break;
        land();
        break;
      }
    }
  }
  std::vector<MassJoin> out;
  for (const auto& [a, targets] : rays)
    for (const auto& [b, ab] : targets) {
      if (b <= a) continue;
      auto back = rays.find(b);
      if (back == rays.end() || !back->second.count(a)) continue;
      const std::vector<MassRay>& ba = back->second.at(a);
      const int fewer = static_cast<int>(std::min(ab.size(), ba.size()));
      if (fewer < kMinMassRays) continue;
      double j_colour = 0.0;
      j_colour = std::max(median_colour_step(ab), median_colour_step(ba));
      const double spread = std::max(median_spread(ab), median_spread(ba));
      // A gradient over the back hair steps across the fan; one linear field
      // painting both pieces explains the step (not on screentone, where
      // the tone decides).
      // On a cel drawing the pieces' paint decides first (RegionCels::judge):
      // other flat colours are refused, a piece in the other's base or band
      // (on its side of the band's level) passes whatever the windows step.
      const RegionCels::Judgement cel = fields.cels().judge(a, b);
      if (cel.other || (std::isfinite(cel.step) && cel.step > kMaxMassCelStep)) continue;
      // Two gradients: both pieces linear, the joint field a gradient that
      // misses them by more than kMinOtherFieldStep, whatever the windows
      // at the cuts step.
      const double field =
          tones.screentone() ? std::numeric_limits<double>::infinity() : fields.step(a, b);
      if (std::isfinite(field) && field > kMinOtherFieldStep) continue;
      if (j_colour >
              kMaxMassColourStep + kMassSpreadShare * std::max(0.0, spread - kTextureFloor) &&
          field > kMaxMassFieldStep && !cel.same)
        continue;
      // Both pieces wide behind the cut, compared with the strands crossed.
      auto wide = [](const std::vector<MassRay>& list) {
        double across = 0.0, depth = 0.0;
        for (const MassRay& r : list) depth += r.depth, across += (r.to - r.from).norm();
        return depth >= kMinMassDepthRatio * across;
      };
      // On screentone the tone tells a strand's end from the back hair, and
      // a sliver of the back hair between strands is thin: pieces of one
      // tone by their dots, or not of two tones and with dark shares that
      // agree (RegionTones::same_tone, both toned: a sliver holds no whole
      // dot), need not be wide. Screentone seeds 101-116: the candidates that
      // passed the window step and failed the width were 109's back 1 and
      // its sliver 22 (dark shares 0.563 / 0.544, 22 without a whole dot)
      // and four of two strands, all two tones by their dots.
      // Two tones by the dots are two strands (session 18: on dev screentone
      // 2000-2099 and 3000-3099 the mass joins of pieces of two tones made 6
      // wrong links and 5 right ones, each right one of a dense tone whose
      // touching dots passed for whole ones, now `whole_dot_mass`, or with
      // a small piece whose dark share alone stepped, now `kMinShareDots`).
      if (tones.two_tones(a, b)) continue;
      const RegionTones::Match match = tones.match(a, b);
      bool toned = false;
      const bool one_tone = match == RegionTones::Match::kSame ||
                            (tones.screentone() && match != RegionTones::Match::kOther &&
                             tones.same_tone(a, b, &toned) && toned);
      if (!one_tone && (!wide(ab) || !wide(ba))) continue;
      out.push_back(mass_join(a, b, fewer, j_colour, ab));
    }
  sort_by_rays(out);
  return out;
}

void sort_by_rays(std::vector<MassJoin>& joins) {
  std::sort(joins.begin(), joins.end(),
            [](const MassJoin& x, const MassJoin& y) { return x.rays > y.rays; });
}

bool one_paint(RegionTones& tones, RegionFields& fields, int a, int b) {
  if (tones.screentone()) return tones.match(a, b) == RegionTones::Match::kSame;
  return fields.paint_step(a, b) <= kMaxOnePaintStep;
}

bool two_paints(RegionTones& tones, RegionFields& fields, int a, int b) {
  if (tones.screentone()) {
    if (tones.match(a, b) == RegionTones::Match::kOther) return true;
    if (!two_tones_by_dots(tones, a, b)) return false;
    const int white = tones.tone(a) < tones.tone(b) ? a : b;
    const double period = tones.dot_period();
    return period > 0 && tones.tone_pixels(white) >= RegionTones::kMinDots * period * period;
  }
  const double step = fields.paint_step(a, b);
  return std::isfinite(step) && step > kMinTwoPaintStep;
}

bool dark_shares_apart(RegionTones& tones, int a, int b) {
  const double ta = tones.tone(a), tb = tones.tone(b);
  return std::max(ta, tb) >= RegionTones::kMinTone &&
         std::abs(ta - tb) > RegionTones::kMinOtherToneStep;
}

bool two_tones_by_dots(RegionTones& tones, int a, int b) {
  if (!tones.screentone()) return false;
  if (tones.match(a, b) == RegionTones::Match::kOther) return true;
  return std::min(tones.tone(a), tones.tone(b)) < RegionTones::kPaperWhite &&
         dark_shares_apart(tones, a, b);
}

}  // namespace hair25d::completion::detail
