// Layering optimisation, paper §4.5 Eq. (2): one binary state x_i ∈ {−1, +1}
// per occluding boundary, minimising −Σ Φ_i x_i − Σ φ_ij σ_ij x_i x_j exactly
// with one s–t minimum cut (Boykov–Kolmogorov max-flow).
#pragma once

#include <vector>

namespace hair25d::layering {

// A pairwise term between boundary states i and j. `same` = true rewards
// x_i = x_j (σ = +1), false rewards x_i = −x_j (σ = −1): the states are
// oriented per boundary (left region above), so whether two boundaries "agree"
// depends on which side of each the region they share lies.
struct StateCoupling {
  int i = 0;
  int j = 0;
  double weight = 0.0;  // φ_ij ≥ 0
  bool same = true;
};

struct StateProblem {
  std::vector<double> unary;  // Φ_i, one per boundary state
  std::vector<StateCoupling> couplings;
};

struct StateSolution {
  std::vector<int> x;   // ±1 per state
  double energy = 0.0;  // of the whole problem, dropped couplings included
  // Couplings that contradict the others around a cycle (a frustrated cycle
  // cannot be made submodular by re-orienting states). The weakest of each
  // such cycle is left out of the cut; 0 means the solution is the exact
  // global minimum of the whole energy.
  int dropped_couplings = 0;
  bool exact() const { return dropped_couplings == 0; }
};

// E(x) = −Σ unary_i x_i − Σ weight_ij σ_ij x_i x_j.
double state_energy(const StateProblem& problem, const std::vector<int>& x);

// Re-orients states along a maximum-weight spanning forest of the couplings so
// every kept coupling rewards equal states (then φ ≥ 0 makes it submodular),
// and solves the result with one minimum cut.
// Throws hair25d::Error for a coupling naming a missing state, a negative or
// non-finite weight, or a non-finite unary.
StateSolution solve_states(const StateProblem& problem);

}  // namespace hair25d::layering
