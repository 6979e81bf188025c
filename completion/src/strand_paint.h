// The paint of a strand judged as a whole (private, case 1 of §5.1): the
// pair tests of every join compare only the two pieces it links, so a
// chain of joins can gather pieces that are plainly two paints (a1 joined
// to a2, a2 to b1, while a1 and b1 step far apart). Before two groups of
// pieces become one strand, every piece of one is compared with every
// piece of the other by the rules the pair tests trust.
#pragma once

#include <optional>
#include <vector>

#include "bank_crossings.h"
#include "join_paint.h"

namespace hair25d::completion::detail {

// Two pieces, one of each group, measured as painted apart.
struct PaintClash {
  int a = 0, b = 0;
};

// The first pair (x of `group_a`, y of `group_b`) painted apart:
// - on screentone, two tones by the dots (`two_paints`: the dots measured
//   and differing, or a paper-white piece with room for dots beside a
//   toned one);
// - on a cel drawing (RegionCels::cel_drawing), flat paint stepping over
//   kMinTwoPaintStep that no shadow explains: a flat colour of one piece
//   that is the other's shade (every channel kMinShade-kMaxShade of it,
//   the channels within kShadeSpread) is the same paint, as the back
//   hair's base and band below its level are one mass;
// - elsewhere, two linear pieces the joint linear field misses by more
//   than kMinStrandFieldStep (two gradients; strand_paint.cpp).
// Nothing measured (a piece too small, no flat paint, no gradient) says
// nothing. None when no pair is measured apart.
// With `but`, that pair (of group_a's and group_b's) is not compared: a
// relation's own two pieces are judged by the relation's rules.
std::optional<PaintClash> painted_apart(RegionTones& tones, RegionFields& fields,
                                        const std::vector<int>& group_a,
                                        const std::vector<int>& group_b,
                                        std::optional<PaintClash> but = std::nullopt);

}  // namespace hair25d::completion::detail
