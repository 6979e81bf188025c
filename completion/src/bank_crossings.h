// Joins across the banks of one occluder (private, case 1 of §5.1 for wide
// pieces): a strand lying over the back hair or the cap cuts it into pieces
// whose cut edges face each other across the strand.
#pragma once

#include <map>
#include <set>
#include <tuple>
#include <vector>

#include "context.h"

namespace hair25d::completion::detail {

// A join is considered across the banks of an occluder when at least this
// share of the rays from each edge lands next to the other edge.
inline constexpr double kMinBankShare = 0.5;
// A ray across the occluders goes on through this many pixels of label 0
// between two hair regions: the light, anti-aliased rim of a drawn line that
// the outline assignment leaves unlabelled (only dark pixels are assigned).
// Longer runs are the face or the paper, where a ray stops.
inline constexpr double kMaxOutlineGap = 3.0;
// Its cost: base + weight × (1 − share) (+ the colour term of strand joins),
// so that a clear bank join (share ≈ 1) ranks with good strand joins.
inline constexpr double kBankBaseCost = 0.5;
inline constexpr double kBankShareWeight = 2.0;

// A ray from an edge pixel across the occluders: its index along the edge,
// start (on the edge) and end (on the far bank).
using BankRay = std::tuple<int, Vec2, Vec2>;

struct BankCrossings {
  int rays = 0;
  std::map<int, std::vector<BankRay>> hits;  // landed region -> rays that reached it
  double depth = 0.0;  // mean distance the piece reaches behind the edge, inwards
};

// Rays from every other pixel of `edge` along the outline's outward normal,
// through regions above the edge's region only, up to 0.6 edge lengths: a
// ray that then reaches a region which all crossed regions lie above as well
// lands on the far bank.
BankCrossings cross_occluders(const Context& ctx, const Edge& edge);

struct BankJoin {
  double share = 0.0;  // min over both edges of the share of rays landing next to the other
  std::vector<Polyline> bands;  // the hidden part: runs of consecutive rays from a
};

// The bank join of edges a and b (their crossings ca, cb). Zero share when
// either piece is thinner behind its edge than 1.5 × the width crossed: a
// strand piece lying on the back hair faces the back hair across an
// occluder too, but it is no wide piece cut in two.
BankJoin bank_join(const BankCrossings& ca, const BankCrossings& cb, const Edge& a, const Edge& b);

}  // namespace hair25d::completion::detail

namespace hair25d::completion::detail {

// Back hair seen between the strands lying over it and around the face: a
// wide piece under a fan of overlapping strands faces its other pieces
// across several occluders at once, so no single edge pair is a case-1 or
// bank candidate. Region level: rays from every outline pixel of a piece
// that lies above no region (or above tails only: lowest regions that only
// such pieces cover), along the outward normal, through regions above it,
// landing on another such piece that all crossed regions lie above as
// well. (The face is left to the face joins: rays across it also
// land on bangs lying on the face, which lie above no region either.)
struct MassJoin {
  int region_a = 0, region_b = 0;
  int rays = 0;                 // the fewer of the rays landing a -> b and b -> a
  double colour = 0.0;          // median RGB step across the cut (the larger way)
  std::vector<Polyline> bands;  // the hidden part: runs of consecutive landing rays
};
// Back hair with tails hanging from under it (`front` = regions above some
// region): the pieces lying above tails only, and the tails under them.
struct TailedHair {
  std::set<int> over_tails, tails;
};
TailedHair tailed_hair(const Context& ctx, const std::set<int>& front);
// Candidates, surest (most rays both ways) first.
std::vector<MassJoin> mass_join_candidates(const Context& ctx);

}  // namespace hair25d::completion::detail
