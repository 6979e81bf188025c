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

// The root end (paper §6: the end by the head, or under the occluder) among
// `candidates` (#nodes), the axis ends: the one nearest to `hint` that is
// not a free tip. `free_corners` are the sharp corners lying above their
// whole neighbourhood (no covered outline within reach): those are the tips
// §6 asks for. A sharp corner next to an occluder (a bang's top where it
// goes under the crown) is where the strand comes from, so it may be the
// root; before, every sharp corner was a tip and such a bang took its root
// at its bottom. If every end is a free corner, the nearest of the other
// `leaves` (#nodes, leaves of the unpruned axis), else of the ends. -1 if
// there is no candidate.
int choose_root(const MedialGraph& g, const std::vector<bool>& candidates,
                const std::vector<bool>& leaves, const std::vector<int>& free_corners,
                const Vec2& hint);

}  // namespace hair25d::skeleton::detail
