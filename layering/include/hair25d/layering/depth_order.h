// From pairwise relations to a drawing order (paper §4.5, "apply topological
// sort"): regions at the same depth are merged, the strongest relations are
// kept, and any relation that would close a cycle is overridden.
#pragma once

#include <map>
#include <utility>
#include <vector>

#include "hair25d/core/hair_model.h"

namespace hair25d::layering {

struct DepthOrder {
  // Region id → depth: 0 is drawn first (back-most); a region above another
  // always has a larger depth, regions related by kEqual share one.
  std::map<int, int> depth;
  // The relations, with those contradicting the order flipped to agree with it
  // and marked `overridden` (their score keeps the original sign).
  std::vector<RegionRelation> relations;
  std::vector<std::pair<int, int>> overridden;  // (a, b) of overridden relations
};

// Orders `regions` (ids; every id named by a relation must be listed) by the
// relations. Relations are taken strongest first (user-fixed ones before all,
// then above/below by |score|, then equal); one that would close a cycle, or
// an equal between regions already ordered, is overridden. Depth is the
// longest chain of "below" relations under a region, so it does not depend on
// how regions are numbered. Throws hair25d::Error for a relation naming an
// unlisted region or a region related to itself.
DepthOrder order_regions(const std::vector<int>& regions,
                         const std::vector<RegionRelation>& relations);

// The same, with `firm` (empty, or one flag per relation): an "equal" flagged
// firm is taken right after the user-fixed relations, before every
// above/below one, so stronger orders do not override it (the layering flags
// the same-depth claims its junction-patch networks are sure of); an
// above/below relation ordering two regions a firm "equal" merged is
// overridden to equal. Throws hair25d::Error if `firm` is neither empty nor
// as long as `relations`.
DepthOrder order_regions(const std::vector<int>& regions,
                         const std::vector<RegionRelation>& relations,
                         const std::vector<char>& firm);

}  // namespace hair25d::layering
