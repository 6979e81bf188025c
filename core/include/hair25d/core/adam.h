// Adam (Kingma & Ba, 2015), the optimiser of the project's small learned
// models (the layering's junction-patch networks, the join scorer): one
// step with the usual moment decays 0.9 and 0.999 and epsilon 1e-8, in float,
// so that both trainers keep reproducing their weights files bit for bit.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace hair25d {

// The step size of step `step` (1, 2, ...) at base rate `rate`, both
// moments' bias corrections folded in.
inline float adam_rate(float rate, long step) {
  const float c1 = 1.0f - std::pow(0.9f, static_cast<float>(step));
  const float c2 = 1.0f - std::pow(0.999f, static_cast<float>(step));
  return rate * std::sqrt(c2) / c1;
}

// Moves the parameters `p` (an Eigen matrix or vector) against the gradient
// `g` by step size `lr`; `m` and `v`, of p's shape and zero at the start,
// are the moment estimates it keeps.
template <class P, class M, class V, class G>
void adam_step(P& p, M& m, V& v, const G& g, float lr) {
  m = 0.9f * m + 0.1f * g;
  v = 0.999f * v + 0.001f * g.cwiseProduct(g);
  p -= (lr * m.array() / (v.array().sqrt() + 1e-8f)).matrix();
}

// The same for one scalar parameter.
inline void adam_step(float& p, float& m, float& v, float g, float lr) {
  m = 0.9f * m + 0.1f * g;
  v = 0.999f * v + 0.001f * g * g;
  p -= lr * m / (std::sqrt(v) + 1e-8f);
}

}  // namespace hair25d
