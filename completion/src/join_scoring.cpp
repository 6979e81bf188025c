#include "join_scoring.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "bank_crossings.h"
#include "hair25d/completion/join_scorer.h"
#include "join_crop.h"
#include "join_paint.h"

namespace hair25d::completion::detail {
namespace {

// Wide candidates the wide net accepts cost max_join_cost less this times
// how far p lies over JoinScorerOptions::wide_threshold: last of all
// candidates under the limit, the surest first.
constexpr double kWideRankSpan = 1e-6;
// Session 39: candidates let in by their pieces' colour fields cost
// max_join_cost less at most this (after every other candidate under the
// limit but the cover refusals' and angle refusals' second chances that
// lie within it of the limit, the surest first).
constexpr double kFieldRankSpan = 1e-8;
// Input 75 (field_cross_max) in RGB over this scale (join_features.cpp).
constexpr int kFieldCrossInput = 75;
constexpr double kFieldCrossScale = 30.0;

}  // namespace

void add_scorer_terms(RegionTones& tones, int ra, int rb, const std::map<int, int>& under_by,
                      JoinTerms* t) {
  if (tones.screentone()) {
    const RegionTones::Match m = tones.match(ra, rb);
    t->tone_match = m == RegionTones::Match::kSame ? 1 : m == RegionTones::Match::kOther ? -1 : 0;
    const double step = tones.mass_step(ra, rb);
    t->mass_step = std::isfinite(step) ? step : -1.0;
    t->dark_step = std::abs(tones.tone(ra) - tones.tone(rb));
  }
  int total = 0, top = 0;
  for (const auto& [l, n] : under_by) total += n, top = std::max(top, n);
  t->top_occluder = total > 0 ? static_cast<double>(top) / total : 1.0;
  t->patch_occluders = 0;
  for (const auto& [l, n] : under_by) t->patch_occluders += 10 * n >= total;
}

bool shaded_drawing(RegionTones& tones, RegionFields& fields, const Eigen::Vector3d& shadow) {
  return !tones.screentone() && (shadow.squaredNorm() > 0 || !fields.cels().cel_drawing());
}

void score_candidates(const Context& ctx, const std::vector<Edge>& edges,
                      const std::set<int>& front, const std::map<int, int>& edge_count,
                      const std::vector<std::optional<JoinTerms>>& terms_of, bool screentone,
                      bool shaded, bool cel, std::vector<Join>* candidates) {
  const Options& o = *ctx.options;
  const JoinScorerOptions& s = o.join_scorer;
  // Session 31: a shaded drawing's band and edges by the shaded net.
  const bool shaded_net = s.shaded && shaded && !screentone;
  const bool shaded_band = shaded_net && s.shaded_band;
  // Session 31: or the retrained net there (`retrained_shaded`).
  const bool retrained =
      !screentone && !shaded_band && (s.retrained || (s.retrained_shaded && shaded));
  // Session 34: the retrained net's own bar on shaded drawings.
  const bool retrained_shaded_bar = retrained && s.retrained_shaded && shaded;
  const double threshold = screentone             ? s.screentone_threshold
                           : shaded_band          ? s.shaded_threshold
                           : retrained_shaded_bar ? s.retrained_shaded_threshold
                           : retrained            ? s.retrained_threshold
                                                  : s.threshold;
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
  // The rivals of a candidate within the angle limit are the others within
  // it (as the default net was trained); a wide candidate's are all up to
  // wide_band_high (as the wide net was).
  std::vector<double> inner = costs;
  bool any_wide = false;
  // Session 31: a side-tangent candidate is no rival of the others (their
  // features and decisions stay as without it); its own rivals are all of
  // the band.
  auto apart = [&](std::size_t k) {
    const Join& j = (*candidates)[which[k]];
    return j.wide || j.side_tangent || j.cover_retry;
  };
  for (std::size_t k = 0; k < which.size(); ++k)
    if (apart(k)) inner[k] = std::numeric_limits<double>::infinity(), any_wide = true;
  // Session 36: a cover refusal's second chance is no rival of the other
  // candidates kept apart either (their features stay as without it); its
  // own rivals are all of them.
  auto cover_retry = [&](std::size_t k) { return (*candidates)[which[k]].cover_retry; };
  if (any_wide) {
    std::vector<double> outer = costs;
    bool any_cover = false;
    for (std::size_t k = 0; k < which.size(); ++k)
      if (cover_retry(k)) outer[k] = std::numeric_limits<double>::infinity(), any_cover = true;
    const double rivals_high = std::max(s.band_high, s.wide_band_high);
    std::vector<JoinFeatures> all = features;
    add_rival_features(outer, ends, rivals_high, &all);
    for (std::size_t k = 0; k < which.size(); ++k)
      if (apart(k) && !cover_retry(k)) features[k] = all[k];
    if (any_cover) {
      all = features;
      add_rival_features(costs, ends, rivals_high, &all);
      for (std::size_t k = 0; k < which.size(); ++k)
        if (cover_retry(k)) features[k] = all[k];
    }
  }
  {
    std::vector<JoinFeatures> own = features;
    add_rival_features(inner, ends, s.band_high, &own);
    for (std::size_t k = 0; k < which.size(); ++k)
      if (!apart(k)) features[k] = own[k];
  }
  const JoinScorerNet& net = retrained                         ? retrained_join_scorer()
                             : screentone && s.screentone_band ? screentone_join_scorer()
                             : shaded_band                     ? shaded_join_scorer()
                                                               : default_join_scorer();
  // The band's edges: the retrained net off screentone (session 29), the
  // screentone net on it (session 30), the shaded net on a shaded drawing
  // (session 31), each with its own bars.
  const JoinScorerNet& edge_net = screentone   ? screentone_join_scorer()
                                  : shaded_net ? shaded_join_scorer()
                                               : retrained_join_scorer();
  const double veto_below = screentone   ? s.screentone_veto_below
                            : shaded_net ? s.shaded_veto_below
                                         : s.veto_below;
  const double veto_low = screentone ? s.screentone_veto_low : s.veto_low;
  const double rescue_threshold = rescue_threshold_for(s, screentone, shaded);
  // Session 25: the ensemble may rescue what the default net refuses.
  using Ensemble = JoinScorerOptions::Ensemble;
  // Session 26: with kEach, the paint ensemble on the drawings without
  // screentone (trained on theirs), with a higher bar on a cel drawing
  // (`cel`: a shadow ratio), where a right rescue joined to a piece
  // already joined wrongly cost dev two-tone 2084 precision at 0.95.
  const bool screentone_nets =
      s.ensemble == Ensemble::kAll ||
      ((s.ensemble == Ensemble::kScreentone || s.ensemble == Ensemble::kEach) && screentone);
  const bool paint_nets = s.ensemble == Ensemble::kEach && !screentone;
  const std::span<const JoinScorerNet> ensemble = screentone_nets ? ensemble_join_scorers()
                                                  : paint_nets    ? paint_ensemble_join_scorers()
                                                               : std::span<const JoinScorerNet>{};
  const double ensemble_threshold = !paint_nets ? s.ensemble_threshold
                                    : cel       ? s.cel_ensemble_threshold
                                                : s.paint_ensemble_threshold;
  // Session 32: a second opinion on the band's refusals where the default
  // net judges the band (flat drawings): the retrained net, trained on
  // eight times its rows. Not the shaded net where the retrained one judges
  // (shaded drawings): on dev two-tone 3000 one added pair in five was
  // wrong at 0.85, and at 0.95 it lost a right pair (docs/
  // completion-record.md "Session 32: a second opinion on the band's
  // refusals").
  const bool second =
      s.second_threshold < 1 && &net == &default_join_scorer() && !screentone && !shaded;
  // Session 39 (JoinScorerOptions::field_cross_max): on a shaded drawing
  // painted by colour fields, a candidate its net refuses joins last when
  // each piece's own field predicts the other's paint at its cut (input
  // 75, the worse way round; −1 where not measured).
  const bool field_cross = s.enabled && s.field_cross_max > 0 && shaded && !screentone;
  auto fields_agree = [&](std::size_t k, double p) {
    const double worse = features[k][kFieldCrossInput];
    const double larger = features[k][kFieldCrossInput + 1];
    return field_cross && p >= s.field_cross_low && worse >= 0 &&
           (kFieldCrossScale * worse <= s.field_cross_max ||
            kFieldCrossScale * larger <= s.field_cross_larger_max);
  };
  const double field_last = o.max_join_cost - kFieldRankSpan;
  for (std::size_t k = 0; k < which.size(); ++k) {
    Join& j = (*candidates)[which[k]];
    double p = -1.0;
    if (j.cover_retry) {
      // Session 36: a cover refusal's second chance joins only by the net
      // trained on such candidates, after every other candidate under the
      // limit, as the angle refusals' do.
      // Session 37: on flat and screentone drawings by their own net and
      // bars (cover_refusal_bar).
      const double bar = cover_refusal_bar(s, screentone, shaded);
      if (s.enabled && bar < 1)
        p = join_probability(
            cover_by_plain_net(s, shaded) ? cover_plain_join_scorer() : cover_join_scorer(),
            features[k]);
      j.cost = p >= bar ? o.max_join_cost - kWideRankSpan * (p - bar)
                        : std::numeric_limits<double>::infinity();
    } else if (j.angle_retry) {
      // Session 35: an angle refusal's second chance joins only by the net
      // trained on such candidates, after every other candidate under the
      // limit (a right one must not take a surer join's edge, as joins73's
      // turned candidates did ranked with the band's rescues).
      if (s.enabled && s.angle_refusal_threshold < 1 && j.cost <= s.band_high)
        p = join_probability(angle_join_scorer(), features[k]);
      j.cost = p >= s.angle_refusal_threshold
                   ? o.max_join_cost - kWideRankSpan * (p - s.angle_refusal_threshold)
               : fields_agree(k, p) ? field_last + kFieldRankSpan * (1.0 - p)
                                    : std::numeric_limits<double>::infinity();
    } else if (j.side_tangent) {
      // Session 31: an angle refusal undone by a side tangent joins only by
      // the band's net at side_threshold, within the band's top, ranked as
      // the band's rescues; never by the hand cost.
      if (s.enabled && j.cost <= s.band_high) p = join_probability(net, features[k]);
      j.cost = p >= s.side_threshold
                   ? o.max_join_cost + (s.side_threshold - p) * (s.band_high - s.band_low)
                   : std::numeric_limits<double>::infinity();
    } else if (j.wide) {
      // Over the angle limit: the scorer alone joins it.
      // Session 29: joined after every other candidate under the limit
      // (ranked by p among themselves), so that it only takes edges no
      // other join wants: ranked with the band's rescues, a right wide join
      // took the edge of another right join (dev two-tone 2077).
      // Never on screentone drawings (match_edges).
      if (s.enabled) p = join_probability(wide_join_scorer(), features[k]);
      j.cost = s.enabled && !screentone && p >= s.wide_threshold
                   ? o.max_join_cost - kWideRankSpan * (p - s.wide_threshold)
                   : std::numeric_limits<double>::infinity();
    } else if (s.enabled && j.cost >= s.band_low && j.cost <= s.band_high) {
      p = join_probability(net, features[k]);
      // The ensemble's mean, asked only for what the default net refuses;
      // the paint nets only for pieces compared as flat paint (session 26:
      // on dev gradient 2000 their rescues at 0.9 or 0.95 added 2 right
      // pairs and 1 wrong one with the annotation's relations, none with
      // the layering's).
      const bool ask =
          p < threshold && !ensemble.empty() && (!paint_nets || terms_of[which[k]]->flat_paint);
      const double q = ask ? join_probability(ensemble, features[k]) : 0.0;
      if (j.uneven_gradient) {
        if (p >= kUnevenThreshold)
          j.cost = o.max_join_cost + (kUnevenThreshold - p) * (s.band_high - s.band_low);
      } else if (p >= threshold)
        j.cost = std::min(j.cost, o.max_join_cost + (threshold - p) * (s.band_high - s.band_low));
      else if (q >= ensemble_threshold)
        j.cost = std::min(j.cost,
                          o.max_join_cost + (ensemble_threshold - q) * (s.band_high - s.band_low));
      else if (second && p >= s.second_low &&
               join_probability(retrained_join_scorer(), features[k]) >= s.second_threshold)
        // After every candidate under the limit, the surest first by the
        // band's net: it only takes edges no other join wants.
        j.cost = o.max_join_cost - kWideRankSpan * p;
      else if (fields_agree(k, p))
        j.cost = field_last + kFieldRankSpan * (1.0 - p);
      else if (p < s.refuse_below)
        j.cost = std::numeric_limits<double>::infinity();
    } else if (s.enabled && rescue_threshold < 1 && !j.uneven_gradient && j.cost > s.band_high &&
               j.cost <= s.rescue_high) {
      // Over the band (session 29): the edges' net alone may join it,
      // whichever net judges the band.
      p = join_probability(edge_net, features[k]);
      if (p >= rescue_threshold)
        j.cost = o.max_join_cost + (rescue_threshold - p) * (s.band_high - s.band_low);
      else if (fields_agree(k, p))
        j.cost = field_last + kFieldRankSpan * (1.0 - p);
    } else if (s.enabled && veto_below > 0 && j.cost >= veto_low && j.cost < s.band_low) {
      // Under the limit (session 29): the edges' net may refuse it,
      // whichever net judges the band.
      p = join_probability(edge_net, features[k]);
      if (p < veto_below) j.cost = std::numeric_limits<double>::infinity();
    }
    // Options::corridor_width: a candidate the corridor let in joins only
    // when the retrained net finds it likely enough, whatever its cost.
    if (j.corridor && s.enabled) {
      const double q = join_probability(retrained_join_scorer(), features[k]);
      if (q < o.corridor_min_probability) j.cost = std::numeric_limits<double>::infinity();
      if (p < 0) p = q;
    }
    j.probability = p;
    j.features = features[k];
    if (ctx.join_log == nullptr) continue;
    JoinCandidate c;
    c.region_a = edges[j.edge_a].region;
    c.region_b = edges[j.edge_b].region;
    c.hand_cost = costs[k];
    c.cost = j.cost;
    c.probability = p;
    c.features = features[k];
    if (s.crop_size > 0)
      c.crop = join_crop(ctx, edges[j.edge_a], edges[j.edge_b], j.patch, s.crop_size);
    j.record = static_cast<int>(ctx.join_log->size());
    ctx.join_log->push_back(c);
  }
}

}  // namespace hair25d::completion::detail
