// The drawing order of completed strands (paper §4.5 applied after §5): the
// region relations summed per pair of strands, ordered by layering's
// topological sort, and the region relations the order contradicts overridden.
#pragma once

#include <map>
#include <vector>

#include "hair25d/core/hair_model.h"

namespace hair25d::pipeline {

struct StrandOrder {
  std::vector<int> depth;    // per strand (index into the strands given), 0 = back-most
  int strand_relations = 0;  // pairs of strands related by at least one region relation
  int overridden = 0;        // region relations this order flipped and marked overridden
};

// Orders `strands` (the region ids of each) so that the region relations
// between two strands, summed, decide which lies above: user-fixed relations
// first, then Σ ±|score| of the others, then their count, then relations
// already overridden, then `region_depth` (front-most piece) for an exact tie.
// A cycle among strands is broken at its weakest strand relation by
// layering::order_regions. Every relation in `relations` between regions of
// two different strands is made to agree with the strand depths: one that
// disagrees is flipped and marked `overridden` (its score keeps its sign), as
// layering does for regions. Relations within one strand, or naming a region
// in no strand, are left as they are.
StrandOrder order_strands(const std::vector<std::vector<int>>& strands,
                          const std::map<int, int>& region_depth,
                          std::vector<RegionRelation>* relations);

}  // namespace hair25d::pipeline
