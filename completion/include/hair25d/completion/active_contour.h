// Algorithm 1 of paper §5.2: an open curve from p to q pushed by the external
// force F_ext = Ω(x)(t F_p + (1 − t) F_q) along its normals, smoothed by the
// semi-implicit pentadiagonal (elasticity + rigidity) step of Kass et al.,
// until it would leave the allowed area (the occluders) or stops moving.
#pragma once

#include <functional>
#include <string>

#include "hair25d/completion/hamiltonian.h"
#include "hair25d/core/geometry.h"

namespace hair25d::completion {

struct ContourOptions {
  double alpha = 0.05;     // elasticity weight of the internal energy
  double beta = 0.2;       // rigidity weight (the fourth-difference band)
  double step = 1.0;       // time step τ of the semi-implicit update
  double max_speed = 1.0;  // pixels per iteration a point may move
  double epsilon = 0.02;   // stop when the largest |V| falls below this (pixels)
  double spacing = 2.0;    // pixels between curve samples (resampled as it grows)
  int max_iterations = 400;
  double omega_gain = 0.05;  // Ω(x) = tanh(gain · Υ_p Υ_q), 0 outside the wedge
  // No point grows farther from the chord p q than this many |p − q|: what
  // lies under a wide occluder is unknown, and a root would otherwise fill it.
  double max_reach = 2.0;
  // Algorithm 1 returns C_{i−1} when the curve would leave the occluders.
  // C₀ lies on the occluding boundary, so points still within
  // `hold_distance` px of it only stay where they are; a point farther out
  // has grown under the occluders and meets their edge. When more than
  // `stop_share` of the free points have, the curve stops: its front has
  // reached the end of the occluders (a root's round end under a long one).
  double hold_distance = 4.0;
  double stop_share = 0.2;
  // False, with a message naming the option, its value and the rule, if unusable.
  bool is_valid(std::string* error) const;
};

enum class ContourStop {
  // Some points stopped where their next step would leave the allowed area
  // (or pass `max_reach`), the others stopped moving; or more than
  // `stop_share` of them had grown up to the occluders' edge.
  kLeftAllowed,
  kConverged,     // |V| < ε
  kIterationCap,  // max_iterations reached
};

const char* to_string(ContourStop stop);

struct ContourResult {
  Polyline curve;  // from p to q
  ContourStop stop = ContourStop::kConverged;
  int iterations = 0;
};

// The two fields at the ends and the sides of the strand they keep the growth in.
struct ContourFields {
  HamiltonianField at_p, at_q;
  // +1 or −1: Υ_p(x) = max(sign_p (H_p(p) − H_p(x)), 0), Υ_q likewise, so that
  // Υ > 0 on the strand's side of the extended outline at p and at q.
  double sign_p = 1.0, sign_q = 1.0;
};

// Grows `initial` (from p = front() to q = back(), at least 2 points) under the
// fields. `allowed(x)` says whether a point may be there (inside the occluders
// or the strand itself); a point whose step would leave it stays where it is
// while the others go on, until more than `stop_share` of the points that
// grew farther than `hold_distance` from `initial` would leave it. Endpoints stay fixed; the
// neighbours of the ends follow the tangents `tangent_p`, `tangent_q` (unit, pointing into the
// hidden part). Throws hair25d::Error for invalid options or a curve of < 2 points.
ContourResult grow_contour(const Polyline& initial, const Vec2& tangent_p, const Vec2& tangent_q,
                           const ContourFields& fields,
                           const std::function<bool(const Vec2&)>& allowed,
                           const ContourOptions& options = {});

}  // namespace hair25d::completion
