// D2Q9 lattice-Boltzmann solver with static obstacles and moving thin filaments (the hair
// skeletons) as boundaries, reporting the force of the flow on each filament segment and on
// each obstacle (Yeh et al. 2015, §6.1). Lattice units throughout; see wind.h for image units.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hair25d/core/geometry.h"
#include "hair25d/fluid/options.h"

namespace hair25d::fluid {

// A thin moving boundary: an open polyline in grid coordinates (cells, x right, y down) and
// the velocity of each of its nodes (cells per step; empty = at rest). Every lattice link the
// polyline crosses is bounced back with the wall velocity at the crossing, so no fluid passes
// through it at any angle.
struct Filament {
  Polyline points;               // >= 2 points, finite, no zero-length segment
  std::vector<Vec2> velocities;  // empty, or one per point, |v| <= kMaxLatticeSpeed
};

// Force of the flow on one filament segment during the last step (lattice units: momentum per
// step per unit depth). `pressure_difference` = force . n / length with n = (-d.y, d.x)/|d|,
// d = points[k+1] - points[k]: the jump in pressure across the segment pushing along n.
struct SegmentForce {
  Vec2 force = Vec2::Zero();
  double pressure_difference = 0.0;
};

// Force of the flow on one static obstacle during the last step; with the flow along +x,
// force.x() is the drag and force.y() the lift (y down).
struct ObstacleForce {
  int label = 0;
  Vec2 force = Vec2::Zero();
};

// Macroscopic fields, each height x width (row y, column x).
struct FlowField {
  Eigen::MatrixXd density;
  Eigen::MatrixXd ux;
  Eigen::MatrixXd uy;
  Eigen::MatrixXi labels;  // 0 fluid, k > 0 obstacle k (velocity 0 there)
};

class LatticeBase;  // private implementation, templated on the scalar type

// Allocates once, then step()s. Not copyable; movable.
class Solver {
 public:
  // Throws hair25d::Error when !options.is_valid(). The fluid starts at rest, density 1.
  explicit Solver(const Options& options);
  ~Solver();
  Solver(Solver&&) noexcept;
  Solver& operator=(Solver&&) noexcept;
  Solver(const Solver&) = delete;
  Solver& operator=(const Solver&) = delete;

  // Advances `steps` >= 0 time steps. Throws hair25d::Error if the flow diverges (the message
  // names the step and what to change); the solver then refuses further steps.
  void step(int steps = 1);

  // Replaces all filaments. Call it whenever they move: every step, or once per animation
  // frame when they move less than a cell per frame (the node velocities then carry the
  // motion in between, at a fraction of the cost). Throws hair25d::Error on NaN or
  // infinite points, zero-length segments, fewer than 2 points, wrong velocity count or
  // velocities above kMaxLatticeSpeed; the previous filaments stay in place then.
  void set_filaments(const std::vector<Filament>& filaments);

  // Per filament, per segment: the force of the flow during the last step.
  const std::vector<std::vector<SegmentForce>>& filament_forces() const;
  // Per obstacle label (ascending): the force of the flow during the last step.
  std::vector<ObstacleForce> obstacle_forces() const;

  // Inlet velocity of a side of kind kInlet: uniform (times the side's profile) or per cell.
  void set_inlet_velocity(SideName side, const Vec2& velocity);
  void set_inlet_velocities(SideName side, const std::vector<Vec2>& per_cell);
  void set_body_acceleration(const Vec2& acceleration);
  // Far-field velocity the outflow sponge relaxes towards (Options::sponge_velocity).
  void set_sponge_velocity(const Vec2& velocity);

  // Sets every fluid cell to equilibrium at the given density and velocity (height x width).
  void initialize(const Eigen::MatrixXd& density, const Eigen::MatrixXd& ux,
                  const Eigen::MatrixXd& uy);
  void initialize_uniform(double density, const Vec2& velocity);

  FlowField field() const;
  double density(int x, int y) const;
  Vec2 velocity(int x, int y) const;
  double total_mass() const;  // sum of density over fluid cells, in double
  // Whether the bulk pass writes with non-temporal stores (Options::stores, kAuto resolved).
  bool streaming_stores() const;
  std::int64_t steps_done() const;
  const Options& options() const;

 private:
  Options options_;
  std::unique_ptr<LatticeBase> lattice_;
  std::vector<int> first_segment_;       // global id of each filament's first segment, + total
  std::vector<Vec2> segment_normals_;    // unit, by global segment id
  std::vector<double> segment_lengths_;  // by global segment id
  std::vector<std::vector<SegmentForce>> segment_forces_;
  std::vector<int> obstacle_ids_;  // labels present, ascending
  std::int64_t steps_ = 0;
  bool diverged_ = false;
};

// Runs until the velocity field stops changing or `max_steps` is reached.
struct SteadyOptions {
  int max_steps = 200000;
  int check_every = 200;  // steps between two looks at the field
  // Converged when max |u_now - u_before| over the field <= tolerance * max |u_now| (per check).
  double tolerance = 1e-6;
  bool is_valid(std::string* error) const;
};

struct SteadyResult {
  enum class Stop { kConverged, kMaxSteps };
  Stop stop = Stop::kMaxSteps;
  int steps = 0;
  double last_change = 0.0;  // relative change at the last check
  std::string why() const;
};

SteadyResult run_to_steady(Solver& solver, const SteadyOptions& options = {});

// One-off: builds a solver, runs it to a steady state and returns the field and forces.
struct SteadyFlow {
  SteadyResult result;
  FlowField field;
  std::vector<ObstacleForce> obstacle_forces;
};
SteadyFlow solve_steady(const Options& options, const SteadyOptions& steady = {});

}  // namespace hair25d::fluid
