// The learned join scorer's inputs for one strand-join candidate (paper §5.1;
// private): the hand cost's terms and what they leave out.
#pragma once

#include <map>
#include <set>

#include "context.h"
#include "hair25d/completion/join_scorer.h"

namespace hair25d::completion::detail {

// The hand cost's terms of a strand join (joins.cpp), as it computed them.
struct JoinTerms {
  double mean_angle = 0, worst_angle = 0;  // over max_join_angle
  double colour = 0;                       // over max_colour_distance
  double colour_step = 0;                  // the step beyond the windows' spread, / 30 RGB
  double width_change = 0;                 // 1 − narrow / wide
  double gap_per_width = 0;                // min(gap / wide, 3)
  double bulge = 0;
  bool common_occluder = true;
  double cover = 1;  // share of the patch under occluders
  double hand_cost = 0;
  double gap = 0, wide = 0;  // pixels
  // Session 14: the paint and tone terms the hand cost gained (joins.cpp).
  double paint_step = 0;           // `PaintStep::step`, RGB
  bool flat_paint = false;         // compared as flat paint
  bool shading_continues = false;  // a gradient carries on across the gap
  bool rare_paint = false;         // one flat paint few regions share
  double tone_cost = 0;            // `tone_join_cost` (screentone)
  bool one_sided = false;          // a nub's tangents left out
  // Session 17: what the tone cost and the cover leave out (screentone: the
  // dots' match and its continuous steps; the occluders over the patch).
  int tone_match = 0;       // RegionTones::match: 1 same, −1 other, 0 unknown
  double mass_step = -1;    // RegionTones::mass_step, −1 unknown / not screentone
  double dark_step = 0;     // |tone(a) − tone(b)| (screentone)
  double top_occluder = 1;  // share of the covered patch under its largest occluder
  int patch_occluders = 0;  // occluders holding ≥ 10 % of the covered patch
  // Session 35: an angle refusal's second chance (Join::angle_retry): the
  // worst angle with the edges' own tangents (over max_join_angle), which
  // other tangents each edge took, and what backs its ends (Edge::arm_p,
  // arm_q over fit_length, ends_part over π, the occluded run's length over
  // its chord, log). All 0 for any other candidate.
  bool retried = false;
  double own_worst_angle = 0;
  double arm_min = 0, arm_mean = 0;
  double ends_part = 0;
  bool retried_either_end = false, retried_reversed = false, retried_side = false,
       retried_turned = false;
  double sliver = 0;
  // Session 36: a cover refusal's second chance (Join::cover_retry): the
  // patch's pixels outside both pieces that no occluder covers, by what
  // lies there, as shares of those pixels (paper or background, the face,
  // ink, a region under a piece, a region under a piece's occluder, any
  // other hair region); the cover of the best patch of joins68's arm
  // shares; the uncovered pixels over the wider cut's width squared; the
  // share of them beside the two cuts. All 0 for any other candidate.
  bool cover_retried = false;
  double miss_paper = 0, miss_face = 0, miss_ink = 0;
  double miss_below = 0, miss_sibling = 0, miss_other = 0;
  double shape_cover = 0;
  double miss_per_width = 0;
  double miss_at_cuts = 0;
  // Session 39: each piece's own colour field (RegionFields::cross_miss)
  // predicting the other piece's paint at its cut, RGB: the worse way
  // round, and the larger piece's way; −1 when not measured (too small, not linear, or not
  // a shaded drawing). Inputs 75, 76.
  double field_cross_max = -1, field_cross_larger = -1;
};

// Every input but the rivals' (indices 27–30, filled by `add_rival_features`).
// `front`: regions above some region; `edge_count`: atoms of each region.
JoinFeatures join_features(const Context& ctx, const Edge& a, const Edge& b, const JoinTerms& t,
                           const std::set<int>& front, const std::map<int, int>& edge_count);

// The rival candidates of each edge (other candidates sharing it):
// `costs[i]` the hand cost of candidate i, `ends[i]` its two edges.
void add_rival_features(const std::vector<double>& costs,
                        const std::vector<std::pair<int, int>>& ends, double band_high,
                        std::vector<JoinFeatures>* features);

}  // namespace hair25d::completion::detail
