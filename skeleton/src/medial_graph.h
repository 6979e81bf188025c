// The medial axis of a sampled closed outline as a graph, from the constrained
// Delaunay triangulation of the samples (chordal-axis construction): a node at
// the midpoint of every inner edge, one at the centre of every junction
// triangle, one at the apex of every end triangle. Always inside the shape.
#pragma once

#include <vector>

#include "hair25d/core/geometry.h"

namespace hair25d::skeleton::detail {

struct MedialGraph {
  std::vector<Vec2> nodes;
  std::vector<std::vector<int>> adjacent;  // #nodes, neighbour node ids
  std::vector<double> radius;              // #nodes, half the width of the shape there
  std::vector<int> apex_of_sample;         // #samples: end-triangle node at that sample, or -1
};

// `samples`: a closed outline, at least 3 distinct points. Throws hair25d::Error
// if CGAL fails.
MedialGraph build_medial_graph(const Polyline& samples);

}  // namespace hair25d::skeleton::detail
