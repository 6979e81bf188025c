// The ends of a strand's medial axis (paper §6: the skeleton runs from the
// root to the tips): short spurs that outline wiggles add to the chordal axis
// pruned, and rounded tips (tapering ends without a sharp corner) found.
#pragma once

#include <vector>

#include "medial_graph.h"

namespace hair25d::skeleton::detail {

// The axis with spurs removed: a leaf whose branch ends at a junction within
// twice that junction's half-width is a bump of the outline, not an end of
// the strand. Shortest spurs go first, so of the ears
// of a rounded end the one straight ahead stays and the axis still reaches
// the outline. `keep` nodes (sharp tips) are never pruned.
struct PrunedAxis {
  std::vector<bool> active;  // #nodes: survives the pruning
  std::vector<int> ends;     // active nodes with at most one active neighbour
};
PrunedAxis prune_spurs(const MedialGraph& g, const std::vector<int>& keep);

// Ends of the pruned axis that are rounded tips: at least `min_distance`
// along the axis from the root (`dist`: axis distances from it, `parent`:
// the tree towards it), visible (`visible_end`, #nodes), and tapering: just
// past the end's cap (two half-widths back) the strand is narrower than it
// gets within max(4 half-widths, 6 `arm`) further back, by 1.3 times.
std::vector<int> rounded_tips(const MedialGraph& g, const PrunedAxis& axis,
                              const std::vector<double>& dist, const std::vector<int>& parent,
                              const std::vector<bool>& visible_end, double min_distance,
                              double arm);

}  // namespace hair25d::skeleton::detail
