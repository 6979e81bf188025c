// Neighbours that share no boundary (an addition to paper §4.5): regions
// separated only by a thick junction or a sliver strand.
#pragma once

#include "hair25d/layering/boundary_graph.h"
#include "hair25d/layering/layering.h"

namespace hair25d::layering::detail {

// Adds to `out.relations` (and `out.anchors`) every pair of hair regions that
// meet across a small island of unfilled line pixels (label-0 boundaries
// linked through junctions, under `island_perimeter` long, off the image
// border), at a junction only, or across a region thinner than
// `sliver_reach` pixels, and is not related yet: the relation the drawing
// order `out.depth` implies (higher depth above, same depth equal).
void add_island_neighbours(const BoundaryGraph& graph, double island_perimeter, double sliver_reach,
                           Result& out);

}  // namespace hair25d::layering::detail
