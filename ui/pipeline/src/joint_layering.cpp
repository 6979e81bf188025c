#include "hair25d/pipeline/joint_layering.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "hair25d/layering/depth_order.h"

namespace hair25d::pipeline {
namespace {

constexpr double kUserSum = 1e6;  // the summed evidence of one user-fixed relation

// Evidence that r.a lies above r.b: the measured score (its sign is the
// layering's reading even where the order flipped the relation), or ±0 for
// an unmeasured order.
double evidence(const RegionRelation& r) {
  if (r.relation == Relation::kEqual && !r.overridden) return 0.0;
  return r.score;
}

Relation relation_of(int sign) {
  return sign > 0 ? Relation::kAbove : sign < 0 ? Relation::kBelow : Relation::kEqual;
}

}  // namespace

std::vector<std::vector<int>> join_strand_groups(const Image& image, const LabelMap& regions,
                                                 const std::vector<RegionRelation>& relations,
                                                 completion::Options options) {
  options.inpaint_strands = false;
  options.inpaint_background = false;
  completion::Input in;
  in.image = &image;
  in.regions = &regions;
  in.relations = relations;
  const completion::Result r = completion::complete_strands(in, options);
  std::vector<std::vector<int>> out;
  for (const completion::CompletedStrand& s : r.strands) {
    std::vector<int> ids = s.regions;
    std::sort(ids.begin(), ids.end());
    out.push_back(std::move(ids));
  }
  return out;
}

JointRevision revise_with_strands(const std::vector<int>& region_ids,
                                  const std::vector<std::vector<int>>& strands,
                                  const JointOptions& options,
                                  std::vector<RegionRelation>* relations,
                                  std::map<int, int>* depth) {
  JointRevision out;
  std::map<int, int> group_of;  // region → strand index; a region alone is its own group
  for (std::size_t s = 0; s < strands.size(); ++s)
    for (int id : strands[s]) group_of[id] = static_cast<int>(s);
  int next = static_cast<int>(strands.size());
  for (const RegionRelation& r : *relations)
    for (int id : {r.a, r.b})
      if (!group_of.contains(id)) group_of[id] = next++;

  std::vector<RegionRelation>& rel = *relations;
  const std::vector<RegionRelation> before = rel;
  std::vector<char> revised(rel.size(), 0);
  std::vector<double> strength(rel.size(), 0.0);  // of a revision's evidence
  const auto weak = [&](const RegionRelation& r) {
    return !r.user_fixed && std::abs(r.score) < options.weak_score;
  };

  // Pieces of one strand: one depth where the layering measured an order.
  if (options.same_depth) {
    for (std::size_t k = 0; k < rel.size(); ++k) {
      RegionRelation& r = rel[k];
      if (group_of[r.a] != group_of[r.b] || r.relation == Relation::kEqual) continue;
      if (r.score == 0.0 || !weak(r)) continue;
      r.relation = Relation::kEqual;
      revised[k] = 1;
      strength[k] = 0.0;
      ++out.to_equal;
    }
  }

  // Two strands: every relation between their pieces in the direction of
  // their summed evidence.
  if (options.agree) {
    struct Tally {
      double sum = 0.0, fixed_sum = 0.0;
      bool any_fixed = false;
      int orders = 0;
    };
    std::map<std::pair<int, int>, Tally> tallies;  // (lower group, higher group)
    for (const RegionRelation& r : rel) {
      const int ga = group_of[r.a], gb = group_of[r.b];
      if (ga == gb) continue;
      const double e = (ga < gb ? 1.0 : -1.0) * evidence(r);
      Tally& t = tallies[{std::min(ga, gb), std::max(ga, gb)}];
      if (r.user_fixed) {
        t.any_fixed = true;
        t.fixed_sum += r.relation == Relation::kEqual                  ? 0.0
                       : (r.relation == Relation::kAbove) == (ga < gb) ? 1.0
                                                                       : -1.0;
      }
      t.sum += e;
      t.orders += r.relation != Relation::kEqual;
    }
    for (std::size_t k = 0; k < rel.size(); ++k) {
      RegionRelation& r = rel[k];
      const int ga = group_of[r.a], gb = group_of[r.b];
      if (ga == gb || r.relation == Relation::kEqual || !weak(r)) continue;
      const Tally& t = tallies[{std::min(ga, gb), std::max(ga, gb)}];
      if (t.orders < 2) continue;
      // The user's relations between the two strands decide alone, as firmly
      // as can be.
      const double sum = t.any_fixed ? kUserSum * t.fixed_sum : t.sum;
      if (std::abs(sum) <= options.agree_min_sum || sum == 0.0) continue;
      const int dir_lo = sum > 0 ? 1 : -1;  // lower group above
      const Relation want = relation_of(ga < gb ? dir_lo : -dir_lo);
      if (r.relation == want) continue;
      r.relation = want;
      r.overridden = true;
      revised[k] = 1;
      strength[k] = std::abs(sum);
      ++out.flipped;
    }
  }
  if (out.to_equal == 0 && out.flipped == 0) return out;

  // The layering's relations were consistent among themselves: they go
  // first, the revisions after them, strongest summed evidence first, so a
  // revision that contradicts the rest of the order is undone rather than
  // the order changed round it.
  std::vector<RegionRelation> ordered = rel;
  for (std::size_t k = 0; k < rel.size(); ++k) {
    ordered[k].user_fixed = !revised[k];
    if (revised[k]) ordered[k].score = strength[k];
  }
  std::vector<int> ids = region_ids;
  for (const auto& [id, g] : group_of)
    if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
  layering::DepthOrder order = layering::order_regions(ids, ordered);
  for (std::size_t k = 0; k < rel.size(); ++k) {
    const RegionRelation& o = order.relations[k];
    if (!revised[k] || o.relation == rel[k].relation) continue;
    // Undone: back to the layering's relation (or the one the order implies).
    if (rel[k].relation == Relation::kEqual)
      --out.to_equal;
    else
      --out.flipped;
    ++out.undone;
    rel[k] = o.relation == before[k].relation ? before[k] : o;
    rel[k].user_fixed = before[k].user_fixed;
    rel[k].score = before[k].score;
  }
  if (depth != nullptr) *depth = std::move(order.depth);
  return out;
}

JointLayering layer_with_joins(const Image& image, const LabelMap& regions,
                               const layering::Options& layering_options,
                               const completion::Options& completion_options,
                               const JointOptions& options, Progress* progress) {
  JointLayering out;
  out.layering = layering::layer_regions(image, regions, layering_options, progress);
  out.strands = join_strand_groups(image, regions, out.layering.relations, completion_options);
  out.revision = revise_with_strands(regions.labels(), out.strands, options,
                                     &out.layering.relations, &out.layering.depth);
  return out;
}

}  // namespace hair25d::pipeline
