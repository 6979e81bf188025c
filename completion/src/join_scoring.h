// The learned scorer's part of the strand-join matching (joins.cpp): the
// terms it reads beyond the hand cost's, and its judgement of the
// candidates (join_scorer.h says when and how).
#pragma once

#include <Eigen/Core>
#include <map>
#include <optional>
#include <set>
#include <vector>

#include "context.h"
#include "join_features.h"

namespace hair25d::completion::detail {

// An uneven-gradient candidate (joins.cpp, "Uneven gradient") joins when
// the scorer's probability reaches this.
inline constexpr double kUnevenThreshold = 0.2;

// The bar a candidate over the band must reach to be joined (the retrained
// net's off screentone, session 29; the screentone net's on it, session 30;
// the shaded net's on a shaded drawing with JoinScorerOptions::shaded,
// session 31); 1 or more means no rescue on such drawings. match_edges
// reads it to know how far to look, score_candidates to judge.
inline double rescue_threshold_for(const JoinScorerOptions& s, bool screentone, bool shaded) {
  return screentone           ? s.screentone_rescue_threshold
         : shaded && s.shaded ? s.shaded_rescue_threshold
                              : s.rescue_threshold;
}

// The bar a cover refusal's second chance must reach (1 or more: none is
// kept): session 36's net and bar on shaded drawings (or on every drawing
// with cover_refusal_all_shadings); session 37's flat and screentone net
// and its bar of the drawing's shading elsewhere (cover_by_plain_net).
inline bool cover_by_plain_net(const JoinScorerOptions& s, bool shaded) {
  return !shaded && !s.cover_refusal_all_shadings;
}
inline double cover_refusal_bar(const JoinScorerOptions& s, bool screentone, bool shaded) {
  return !cover_by_plain_net(s, shaded) ? s.cover_refusal_threshold
         : screentone                   ? s.cover_screentone_threshold
                                        : s.cover_flat_threshold;
}

// Whether a drawing without screentone is shaded (session 31): a cel shadow
// band (`shadow`, join_paint.h shadow_ratio, not zero) or paint that is not
// cel (RegionCels::cel_drawing false: gradients). Told from the drawing's
// paint, never from how it was made; flat drawings are neither.
bool shaded_drawing(RegionTones& tones, RegionFields& fields, const Eigen::Vector3d& shadow);

// The scorer's inputs of session 17 (join_features.h): the dots' tone match
// and steps on a screentone drawing, and how the covered part of the patch
// (`under_by`: pixels per occluder) falls to its occluders.
void add_scorer_terms(RegionTones& tones, int ra, int rb, const std::map<int, int>& under_by,
                      JoinTerms* t);

// The learned scorer decides the strand joins whose hand cost lies in its
// band, and the retrained net the band's edges (join_scorer.h): the
// candidates' costs are set from the nets' probabilities; every strand
// candidate is recorded when ctx.join_log is set.
void score_candidates(const Context& ctx, const std::vector<Edge>& edges,
                      const std::set<int>& front, const std::map<int, int>& edge_count,
                      const std::vector<std::optional<JoinTerms>>& terms_of, bool screentone,
                      bool shaded, bool cel, std::vector<Join>* candidates);

}  // namespace hair25d::completion::detail
