// The traced edge pair of pieces a and b that reached `stage`
// (Options::trace_joins; a pair of pieces has one trace per pair of their
// edges), for the tests that ask how far a candidate got.
#pragma once

#include <set>
#include <utility>
#include <vector>

#include "hair25d/completion/completion.h"

namespace hair25d::completion::test {

inline const JoinTrace* trace_of(const Result& r, int a, int b, JoinStage stage) {
  for (const JoinTrace& t : r.join_trace)
    if (((t.region_a == a && t.region_b == b) || (t.region_a == b && t.region_b == a)) &&
        t.stage == stage)
      return &t;
  return nullptr;
}

// The pairs of pieces (as traced, a then b) with an edge pair that reached
// `stage`.
inline std::set<std::pair<int, int>> traced_pairs(const Result& r, JoinStage stage) {
  std::set<std::pair<int, int>> out;
  for (const JoinTrace& t : r.join_trace)
    if (t.stage == stage) out.insert({t.region_a, t.region_b});
  return out;
}

// The joins of `on` a cover second chance added: chosen there, refused by
// the cover in `off` and not chosen there, the patch under
// min_join_coverage.
inline std::vector<JoinTrace> cover_gains(const Result& off, const Result& on) {
  const auto refused = traced_pairs(off, JoinStage::kCover),
             before = traced_pairs(off, JoinStage::kChosen);
  std::vector<JoinTrace> out;
  for (const JoinTrace& t : on.join_trace) {
    const std::pair<int, int> pair{t.region_a, t.region_b};
    if (t.stage == JoinStage::kChosen && !before.count(pair) && refused.count(pair) &&
        t.cover < Options{}.min_join_coverage)
      out.push_back(t);
  }
  return out;
}

}  // namespace hair25d::completion::test
