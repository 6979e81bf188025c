// A second chance for a cut pair refused by max_join_angle_deg (session 35,
// JoinScorerOptions::angle_refusal_threshold): other tangents each edge's
// outline allows, for the net trained on such candidates. Private to the
// case-1 joins.
#pragma once

#include "context.h"
#include "join_features.h"

namespace hair25d::completion::detail {

// One edge's tangents as tried, and which reading gave them.
struct TriedTangents {
  Vec2 p{0, 0}, q{0, 0};
  enum class Kind { kOwn, kEitherEnd, kReversed, kSide, kTurned } kind = Kind::kOwn;
};

struct RetriedTangents {
  bool found = false;
  TriedTangents a, b;
  double angles[4] = {0, 0, 0, 0};  // as joins.cpp orders them
  double worst = 0;
};

// For each edge its own tangents, one end's for both ends (p's, q's), its
// own reversed, its side tangent (Edge::side_tangent) and the direction its
// opposite ends dropped (Edge::turned_tangent) for both: the pair of
// readings (not both own) with the smallest worst angle to the chords c1 =
// b.q − a.p and c2 = a.q − b.p, if within `max_angle` (radians). Without
// `turn_round`, not the readings that turn the outline's own direction
// round (reversed, turned).
RetriedTangents retry_tangents(const Edge& a, const Edge& b, const Vec2& c1, const Vec2& c2,
                               double max_angle, bool turn_round = true);

// The net's inputs for it (JoinTerms::retried ...): `own_worst` the worst
// angle with the edges' own tangents over max_join_angle.
void add_retry_terms(const Edge& a, const Edge& b, const RetriedTangents& r, double own_worst,
                     double fit_length, JoinTerms* t);

}  // namespace hair25d::completion::detail
