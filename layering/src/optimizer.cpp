#include "hair25d/layering/optimizer.h"

#include <maxflow.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "hair25d/core/error.h"

namespace hair25d::layering {
namespace {

void check(const StateProblem& p) {
  const int n = static_cast<int>(p.unary.size());
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(p.unary[i]))
      throw Error("layering::solve_states: unary[" + std::to_string(i) +
                  "] = " + std::to_string(p.unary[i]) + "; must be finite");
  for (std::size_t k = 0; k < p.couplings.size(); ++k) {
    const StateCoupling& c = p.couplings[k];
    if (c.i < 0 || c.j < 0 || c.i >= n || c.j >= n || c.i == c.j)
      throw Error("layering::solve_states: coupling " + std::to_string(k) + " joins states " +
                  std::to_string(c.i) + " and " + std::to_string(c.j) +
                  "; must be two different states in [0, " + std::to_string(n) + ")");
    if (!(c.weight >= 0.0) || !std::isfinite(c.weight))
      throw Error("layering::solve_states: coupling " + std::to_string(k) +
                  " weight = " + std::to_string(c.weight) + "; must be finite and >= 0");
  }
}

// Union-find that also tracks each element's parity relative to its root.
struct ParityForest {
  explicit ParityForest(int n) : parent(n), parity(n, 0) {
    std::iota(parent.begin(), parent.end(), 0);
  }
  int find(int a) {
    if (parent[a] == a) return a;
    const int root = find(parent[a]);
    parity[a] ^= parity[parent[a]];
    parent[a] = root;
    return root;
  }
  std::vector<int> parent;
  std::vector<int> parity;  // 1: the state is flipped relative to its root
};

}  // namespace

double state_energy(const StateProblem& problem, const std::vector<int>& x) {
  double e = 0.0;
  for (std::size_t i = 0; i < problem.unary.size(); ++i) e -= problem.unary[i] * x[i];
  for (const StateCoupling& c : problem.couplings)
    e -= c.weight * (c.same ? 1.0 : -1.0) * x[c.i] * x[c.j];
  return e;
}

StateSolution solve_states(const StateProblem& problem) {
  check(problem);
  const int n = static_cast<int>(problem.unary.size());
  StateSolution out;
  out.x.assign(n, 1);
  if (n == 0) return out;

  // Kruskal on decreasing weight: a coupling either joins two trees (fixing
  // the relative orientation of its states) or closes a cycle, and then it
  // agrees with the orientation the stronger couplings already chose, or not.
  std::vector<int> order(problem.couplings.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return problem.couplings[a].weight > problem.couplings[b].weight;
  });
  ParityForest forest(n);
  std::vector<char> kept(problem.couplings.size(), 1);
  for (int k : order) {
    const StateCoupling& c = problem.couplings[k];
    const int want = c.same ? 0 : 1;  // parity between x_i and x_j
    const int ri = forest.find(c.i);
    const int rj = forest.find(c.j);
    if (ri != rj) {
      forest.parent[rj] = ri;
      forest.parity[rj] = forest.parity[c.i] ^ forest.parity[c.j] ^ want;
    } else if ((forest.parity[c.i] ^ forest.parity[c.j]) != want) {
      kept[k] = 0;
      if (c.weight > 0) ++out.dropped_couplings;
    }
  }
  std::vector<int> flip(n);
  for (int i = 0; i < n; ++i) {
    forest.find(i);
    flip[i] = forest.parity[i] ? -1 : 1;
  }

  // In flipped states y_i = flip_i x_i every kept coupling rewards y_i = y_j.
  // With y = +1 on the source side: a state on the source side pays its
  // sink capacity. Cost(y=+1) = −Φ', cost(y=−1) = +Φ', shifted to be >= 0;
  // a disagreeing pair pays 2φ.
  using Graph = maxflow::Graph_DDD;
  int kept_count = 0;
  for (char k : kept) kept_count += k;
  Graph graph(n, std::max(1, kept_count));
  graph.add_node(n);
  for (int i = 0; i < n; ++i) {
    const double phi = problem.unary[i] * flip[i];
    const double cost_plus = phi > 0 ? 0.0 : -2.0 * phi;
    const double cost_minus = phi > 0 ? 2.0 * phi : 0.0;
    graph.add_tweights(i, cost_minus, cost_plus);
  }
  for (std::size_t k = 0; k < problem.couplings.size(); ++k) {
    if (!kept[k]) continue;
    const StateCoupling& c = problem.couplings[k];
    graph.add_edge(c.i, c.j, 2.0 * c.weight, 2.0 * c.weight);
  }
  graph.maxflow();
  for (int i = 0; i < n; ++i) {
    const bool source = graph.what_segment(i, Graph::SOURCE) == Graph::SOURCE;
    out.x[i] = (source ? 1 : -1) * flip[i];
  }
  out.energy = state_energy(problem, out.x);
  return out;
}

}  // namespace hair25d::layering
