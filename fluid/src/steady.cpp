#include <algorithm>
#include <cmath>
#include <sstream>

#include "hair25d/core/error.h"
#include "hair25d/fluid/solver.h"

namespace hair25d::fluid {

bool SteadyOptions::is_valid(std::string* error) const {
  std::ostringstream m;
  if (max_steps < 0)
    m << "fluid::SteadyOptions::max_steps = " << max_steps << "; must be >= 0";
  else if (check_every < 1)
    m << "fluid::SteadyOptions::check_every = " << check_every << "; must be >= 1";
  else if (!std::isfinite(tolerance) || !(tolerance > 0.0))
    m << "fluid::SteadyOptions::tolerance = " << tolerance << "; must be > 0";
  if (error) *error = m.str();
  return m.str().empty();
}

std::string SteadyResult::why() const {
  std::ostringstream m;
  if (stop == Stop::kConverged)
    m << "converged after " << steps << " steps (relative change " << last_change << ")";
  else
    m << "stopped at the step limit " << steps << " (relative change still " << last_change << ")";
  return m.str();
}

SteadyResult run_to_steady(Solver& solver, const SteadyOptions& options) {
  std::string error;
  if (!options.is_valid(&error)) throw Error(error);
  SteadyResult result;
  FlowField before = solver.field();
  while (result.steps < options.max_steps) {
    const int n = std::min(options.check_every, options.max_steps - result.steps);
    solver.step(n);
    result.steps += n;
    FlowField now = solver.field();
    const double scale = std::sqrt((now.ux.array().square() + now.uy.array().square()).maxCoeff());
    const double change = std::sqrt(
        ((now.ux - before.ux).array().square() + (now.uy - before.uy).array().square()).maxCoeff());
    result.last_change = scale > 0 ? change / scale : change;
    before = std::move(now);
    if (result.last_change <= options.tolerance) {
      result.stop = SteadyResult::Stop::kConverged;
      return result;
    }
  }
  result.stop = SteadyResult::Stop::kMaxSteps;
  return result;
}

SteadyFlow solve_steady(const Options& options, const SteadyOptions& steady) {
  Solver solver(options);
  SteadyFlow out;
  out.result = run_to_steady(solver, steady);
  out.field = solver.field();
  out.obstacle_forces = solver.obstacle_forces();
  return out;
}

}  // namespace hair25d::fluid
