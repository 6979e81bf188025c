// Strands as groups of regions while completion merges them, with the depth
// order between the groups: in the 2.5D model (Yeh et al. 2015, §3) a strand
// has one depth, so no merge may leave a strand above itself (private).
#pragma once

#include <map>
#include <set>
#include <utility>
#include <vector>

#include "hair25d/completion/completion.h"

namespace hair25d::completion::detail {

// region -> the regions above it through any chain of `above` (region -> the
// regions directly above it).
std::map<int, std::set<int>> chains_above(const std::map<int, std::set<int>>& above);

class StrandGroups {
 public:
  // The group (its root region) of region `x`; an unseen region is its own.
  int find(int x);
  // Makes the groups of `a` and `b` one, unchecked (equal relations, seams).
  void unite(int a, int b);

  // `upper` lies directly above `lower` by a firm relation: such a pair, and
  // any two regions one of which is above the other through a chain of firm
  // relations between regions, are never one strand.
  void add_firm_order(int lower, int upper);
  // `upper` lies directly above `lower` by a relation too weak to keep the
  // two out of one strand; it counts in chains through other groups with
  // StrandOrderGuard::kAll only.
  void add_weak_order(int lower, int upper);
  void set_guard(StrandOrderGuard guard) { guard_ = guard; }

  // Unites the groups of `a` and `b` unless they are one already, a member
  // of one lies above a member of the other through a chain of firm
  // relations between regions, or (with a guard) one group lies above the
  // other through a chain of orders that passes through at least one third
  // group: merging would then make that group lie above the new strand and
  // below it at once. Returns whether they were united.
  bool try_join(int a, int b);

  // Region pairs (a, b) as offered to try_join that only the guard refused.
  const std::vector<std::pair<int, int>>& guard_refusals() const { return guard_refusals_; }

 private:
  bool firmly_ordered(int ga, int gb);
  // Whether `to` lies above `from` through a chain of orders (of the
  // guard's kind) that passes through at least one group other than both.
  bool above_through_others(int from, int to);

  std::map<int, int> parent_;
  std::map<int, std::set<int>> firm_above_;   // region -> regions directly firmly above
  std::map<int, std::set<int>> weak_above_;   // region -> regions directly weakly above
  std::map<int, std::set<int>> firm_chains_;  // region -> firm_above_'s closure
  bool chains_stale_ = false;
  StrandOrderGuard guard_ = StrandOrderGuard::kOff;
  std::vector<std::pair<int, int>> guard_refusals_;
};

}  // namespace hair25d::completion::detail
