// How completion reads the layering's relations (private): which were
// measured, and the measured orders as "x directly above y".
#pragma once

#include <algorithm>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "hair25d/core/hair_model.h"

namespace hair25d::completion::detail {

// A relation nothing was measured for: not the user's, score 0, between
// regions that do not touch once the outlines are assigned. The layering
// relates such regions (meeting only at a thick junction or across a
// sliver: layering's add_island_neighbours) by its drawing order alone,
// "equal" where their depths happen to tie — no evidence of one strand, nor
// of one lying above the other. Session 16 (joins22), the layering's
// relations on dev set flat 2000-2099: 236 such "equal" pairs, 161 of two
// strands (merged into one); 978 such orders, 90 between pieces of one
// strand (never joined then). Ignored, precision / recall with the
// layering's relations: flat 2000-2099 0.744 / 0.585 -> 0.938 / 0.661, mixed
// 0.681 / 0.488 -> 0.897 / 0.539 (docs/completion-record.md, "Session 16: joins
// with the layering's relations"); with the annotation's relations
// (user-fixed) nothing changes.
inline bool unmeasured(const RegionRelation& r, const std::set<std::pair<int, int>>& touching) {
  return !r.user_fixed && r.score == 0.0 &&
         !touching.count({std::min(r.a, r.b), std::max(r.a, r.b)});
}

// The measured relations as "x lies directly above y" (seam_geometry's
// `above`).
class DirectOrders {
 public:
  DirectOrders(const std::vector<RegionRelation>& relations,
               const std::set<std::pair<int, int>>& touching) {
    for (const RegionRelation& r : relations)
      if (!unmeasured(r, touching)) direct_[{r.a, r.b}] = r.relation;
  }

  bool above(int x, int y) const {
    auto it = direct_.find({x, y});
    if (it != direct_.end()) return it->second == Relation::kAbove;
    it = direct_.find({y, x});
    return it != direct_.end() && it->second == Relation::kBelow;
  }

 private:
  std::map<std::pair<int, int>, Relation> direct_;
};

}  // namespace hair25d::completion::detail
