#include "strand_order.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "hair25d/layering/depth_order.h"

namespace hair25d::pipeline {
namespace {

// The evidence that strand `lo` lies above strand `hi` (lo < hi), from the
// region relations between them; each field positive for "lo above".
struct Tally {
  double fixed_sum = 0;
  int fixed_votes = 0;
  double sum = 0;
  int votes = 0;
  int overridden_votes = 0;
  bool any_fixed = false;
  bool any_order = false;  // some relation says above or below
};

// +1 when the relation puts `lo` above, -1 below, 0 for equal.
int sign_for_lo(const RegionRelation& r, bool a_in_lo) {
  const int s = r.relation == Relation::kAbove ? 1 : (r.relation == Relation::kBelow ? -1 : 0);
  return a_in_lo ? s : -s;
}

int sign_of(double v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

}  // namespace

StrandOrder order_strands(const std::vector<std::vector<int>>& strands,
                          const std::map<int, int>& region_depth,
                          std::vector<RegionRelation>* relations) {
  std::map<int, int> strand_of;
  for (std::size_t s = 0; s < strands.size(); ++s)
    for (int r : strands[s]) strand_of.emplace(r, static_cast<int>(s));
  const auto strand = [&](int region) {
    auto it = strand_of.find(region);
    return it == strand_of.end() ? -1 : it->second;
  };

  // A strand joined from pieces may meet another strand through several
  // region boundaries that disagree (piece A above X, piece B below X): the
  // pair is decided once, by all of them together.
  std::map<std::pair<int, int>, Tally> tallies;
  for (const RegionRelation& r : *relations) {
    const int sa = strand(r.a), sb = strand(r.b);
    if (sa < 0 || sb < 0 || sa == sb) continue;
    const bool a_in_lo = sa < sb;
    Tally& t = tallies[{std::min(sa, sb), std::max(sa, sb)}];
    const int dir = sign_for_lo(r, a_in_lo);
    t.any_order |= dir != 0;
    if (r.user_fixed) {
      t.any_fixed = true;
      t.fixed_sum += dir * std::abs(r.score);
      t.fixed_votes += dir;
    } else if (r.overridden) {
      // Already flipped to agree with the region order, and weaker than the
      // relations that order kept: it only breaks ties.
      t.overridden_votes += dir;
    } else {
      t.sum += dir * std::abs(r.score);
      t.votes += dir;
    }
  }

  // Front-most piece of each strand: the last tie-break.
  std::vector<int> key(strands.size(), 0);
  for (std::size_t s = 0; s < strands.size(); ++s)
    for (int r : strands[s]) {
      auto it = region_depth.find(r);
      if (it != region_depth.end()) key[s] = std::max(key[s], it->second);
    }

  std::vector<RegionRelation> strand_relations;
  for (const auto& [pair, t] : tallies) {
    RegionRelation sr;
    sr.a = pair.first;
    sr.b = pair.second;
    sr.user_fixed = t.any_fixed;
    int dir = 0;
    if (t.any_fixed)
      dir = sign_of(t.fixed_sum) != 0 ? sign_of(t.fixed_sum) : sign_of(t.fixed_votes);
    if (dir == 0) dir = sign_of(t.sum);
    if (dir == 0) dir = sign_of(t.votes);
    if (dir == 0) dir = sign_of(t.overridden_votes);
    // Relations that cancel exactly still say the two are not level: two
    // strands at one depth would have no drawing order.
    if (dir == 0 && t.any_order)
      dir =
          key[pair.first] != key[pair.second] ? (key[pair.first] > key[pair.second] ? 1 : -1) : -1;
    sr.relation = dir > 0 ? Relation::kAbove : (dir < 0 ? Relation::kBelow : Relation::kEqual);
    sr.score = dir * std::abs(t.any_fixed ? t.fixed_sum : t.sum);
    strand_relations.push_back(sr);
  }

  std::vector<int> ids(strands.size());
  for (std::size_t s = 0; s < strands.size(); ++s) ids[s] = static_cast<int>(s);
  const layering::DepthOrder order = layering::order_regions(ids, strand_relations);

  StrandOrder out;
  out.strand_relations = static_cast<int>(strand_relations.size());
  out.depth.resize(strands.size(), 0);
  for (std::size_t s = 0; s < strands.size(); ++s)
    out.depth[s] = order.depth.at(static_cast<int>(s));
  for (RegionRelation& r : *relations) {
    const int sa = strand(r.a), sb = strand(r.b);
    if (sa < 0 || sb < 0 || sa == sb) continue;
    const int da = out.depth[sa], db = out.depth[sb];
    const Relation implied =
        da > db ? Relation::kAbove : (da < db ? Relation::kBelow : Relation::kEqual);
    if (r.relation == implied) continue;
    r.relation = implied;
    if (!r.overridden) ++out.overridden;
    r.overridden = true;
  }
  return out;
}

}  // namespace hair25d::pipeline
