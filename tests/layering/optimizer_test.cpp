// Eq. (2) solved by one minimum cut equals brute force on small graphs.
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "hair25d/core/error.h"
#include "hair25d/layering/optimizer.h"

namespace hair25d::layering {
namespace {

std::vector<int> brute_force(const StateProblem& p, double* best_energy) {
  const int n = static_cast<int>(p.unary.size());
  std::vector<int> best;
  *best_energy = std::numeric_limits<double>::infinity();
  for (unsigned mask = 0; mask < (1u << n); ++mask) {
    std::vector<int> x(n);
    for (int i = 0; i < n; ++i) x[i] = (mask >> i) & 1 ? 1 : -1;
    const double e = state_energy(p, x);
    if (e < *best_energy) *best_energy = e, best = x;
  }
  return best;
}

// Random couplings whose signs come from a hidden orientation, so the
// problem can be made submodular (what solve_states claims to solve exactly).
StateProblem random_balanced(std::mt19937& rng, int n, int m) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.0, 2.0);
  std::uniform_int_distribution<int> pick(0, n - 1);
  std::vector<int> hidden(n);
  for (int& h : hidden) h = pick(rng) % 2 ? 1 : -1;
  StateProblem p;
  for (int i = 0; i < n; ++i) p.unary.push_back(u(rng));
  for (int k = 0; k < m; ++k) {
    const int i = pick(rng), j = pick(rng);
    if (i == j) continue;
    p.couplings.push_back({i, j, w(rng), hidden[i] == hidden[j]});
  }
  return p;
}

TEST(SolveStates, EqualsBruteForceOnRandomBalancedGraphs) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 1 + trial % 12;
    const StateProblem p = random_balanced(rng, n, 2 * n);
    double best = 0;
    const std::vector<int> expect = brute_force(p, &best);
    const StateSolution got = solve_states(p);
    ASSERT_TRUE(got.exact()) << "trial " << trial;
    EXPECT_NEAR(got.energy, best, 1e-9) << "trial " << trial;
    EXPECT_NEAR(state_energy(p, got.x), got.energy, 1e-12);
    // Continuous random weights make the minimum unique.
    EXPECT_EQ(got.x, expect) << "trial " << trial;
  }
}

TEST(SolveStates, FrustratedTriangleDropsItsWeakestCoupling) {
  // Three states pairwise asked to differ cannot all be satisfied.
  StateProblem p;
  p.unary = {0.1, 0.0, 0.0};
  p.couplings = {{0, 1, 3.0, false}, {1, 2, 2.0, false}, {0, 2, 0.5, false}};
  const StateSolution s = solve_states(p);
  EXPECT_EQ(s.dropped_couplings, 1);
  EXPECT_FALSE(s.exact());
  EXPECT_EQ(s.x, (std::vector<int>{1, -1, 1}));  // keeps the two strong couplings
  double best = 0;
  brute_force(p, &best);
  EXPECT_NEAR(s.energy, best, 1e-12);  // here dropping the weakest is also optimal
}

TEST(SolveStates, UnaryAloneGivesItsSign) {
  StateProblem p;
  p.unary = {0.3, -0.2, 1e-3};
  EXPECT_EQ(solve_states(p).x, (std::vector<int>{1, -1, 1}));
}

TEST(SolveStates, StrongCouplingOverridesWeakUnary) {
  StateProblem p;
  p.unary = {1.0, -0.2};
  p.couplings = {{0, 1, 0.5, true}};
  EXPECT_EQ(solve_states(p).x, (std::vector<int>{1, 1}));
  p.couplings = {{0, 1, 0.5, false}};
  EXPECT_EQ(solve_states(p).x, (std::vector<int>{1, -1}));
}

TEST(SolveStates, EmptyProblemIsFine) { EXPECT_TRUE(solve_states({}).x.empty()); }

TEST(SolveStates, RejectsBadInput) {
  StateProblem p;
  p.unary = {0.0, 0.0};
  p.couplings = {{0, 2, 1.0, true}};
  EXPECT_THROW(solve_states(p), Error);
  p.couplings = {{0, 0, 1.0, true}};
  EXPECT_THROW(solve_states(p), Error);
  p.couplings = {{0, 1, -1.0, true}};
  EXPECT_THROW(solve_states(p), Error);
  p.couplings = {{0, 1, std::numeric_limits<double>::infinity(), true}};
  EXPECT_THROW(solve_states(p), Error);
  p.couplings.clear();
  p.unary[1] = std::numeric_limits<double>::quiet_NaN();
  try {
    solve_states(p);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("unary[1]"), std::string::npos);
  }
}

}  // namespace
}  // namespace hair25d::layering
