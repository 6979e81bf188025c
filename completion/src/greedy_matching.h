// The case-1 joins' greedy one-to-one matching (match_edges, joins.cpp):
// the scored candidates, cheapest first, each atom joined once, a second
// time as a cut's second partner (Options::second_partner_p, session 33;
// JoinScorerOptions::second_partner_threshold, session 37). Private to
// the case-1 joins.
#pragma once

#include <functional>
#include <vector>

#include "context.h"

namespace hair25d::completion::detail {

class RegionTones;

// The joins chosen among `candidates` (their costs set by the hand cost
// and the nets; those over max_join_cost are dropped). `shaded`: a
// two-tone or gradient drawing (shaded_drawing), where the second-partner
// net acts; `try_join` and `joined` as match_edges takes them.
std::vector<Join> choose_joins(const Context& ctx, const std::vector<Edge>& edges,
                               RegionTones& tones, bool shaded, std::vector<Join> candidates,
                               const std::function<bool(int, int)>& try_join,
                               const std::function<bool(int, int)>& joined);

}  // namespace hair25d::completion::detail
