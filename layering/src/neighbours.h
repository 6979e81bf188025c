// Neighbours that share no boundary (an addition to paper §4.5): regions
// separated only by a thick junction or a sliver strand.
#pragma once

#include <cstddef>
#include <vector>

#include "hair25d/layering/boundary_graph.h"
#include "hair25d/layering/layering.h"

namespace hair25d::layering::detail {

// The groups of hair regions add_island_neighbours relates: those meeting
// across a small island of unfilled line pixels (label-0 boundaries linked
// through junctions, under `island_perimeter` long, off the image border),
// at a junction only, or across a region thinner than `sliver_reach` pixels
// of `labels`. They need only the traced map, not the relations, so the
// layering finds them on a second core while it measures.
struct IslandGroups {
  // Group g is members[starts[g]] .. members[starts[g + 1] − 1]: labels
  // that are neighbours of each other, sorted, without repeats.
  std::vector<int> members;
  std::vector<std::size_t> starts{0};
};
IslandGroups island_groups(const BoundaryGraph& graph, const LabelMap& labels,
                           double island_perimeter, double sliver_reach);

// Adds to `out.relations` (and `out.anchors`) every pair of a group that is
// not related yet: the relation the drawing order `out.depth` implies
// (higher depth above, same depth equal), group by group.
void add_island_neighbours(const IslandGroups& groups, Result& out);

}  // namespace hair25d::layering::detail
