// A cut already taken (session 37, JoinScorerOptions::
// second_partner_threshold): a strand-join candidate whose atoms on one of
// its edges an earlier join of the greedy matching took, described for the
// net trained on such candidates: how sure the scorer was of it and of the
// join that took the cut, and how the two partners lie along the cut.
// Private to the case-1 joins.
#pragma once

#include <set>
#include <vector>

#include "context.h"
#include "hair25d/completion/join_scorer.h"

namespace hair25d::completion::detail {

// The first of the inputs saying a row is a cut's second partner; the
// others follow it (join_scorer.cpp names them).
inline constexpr int kSecondCut = 64;

// A join chosen earlier that holds atoms of the taken edge.
struct FirstPartner {
  int own = 0;    // its edge holding those atoms
  int other = 0;  // its edge on the other piece
  double probability = -1.0;
  double cost = 0.0;
};

// The edge of `j` whose atoms are in `used`, when only one of its two
// edges has any; −1 when neither has or both have.
int taken_edge(const Join& j, const std::vector<Edge>& edges, const std::set<int>& used);

// The part of `cut`'s boundary that `other` faces: its points from the one
// nearest other.p to the one nearest other.q (joins83's faced_part).
Polyline faced_part(const Edge& cut, const Edge& other);

// Inputs kSecondCut.. of `f` for `j`, whose edge `taken` is held by the
// joins `firsts` (not empty).
void add_second_terms(const std::vector<Edge>& edges, const Join& j, int taken,
                      const std::vector<FirstPartner>& firsts, JoinFeatures* f);

}  // namespace hair25d::completion::detail
