// Options of the D2Q9 lattice-Boltzmann wind solver that blows on the hair skeletons
// (Yeh et al. 2015, §6.1: "the lattice Boltzmann model ... with the hair skeleton as the
// boundary"). Everything here is in lattice units: one cell is 1 long, one step lasts 1 (see wind.h
// for image units).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "hair25d/core/geometry.h"

namespace hair25d::fluid {

// Grid coordinates: x right, y down (as in images). Cell (i, j) is the square
// [i, i+1) x [j, j+1); its lattice node sits at (i + 0.5, j + 0.5). "top" is y = 0.

enum class Collision {
  kBgk,  // single relaxation time; stable for tau well above 1/2
  kTrt,  // two relaxation times (Ginzburg); stays stable at low viscosity
};

enum class Precision { kFloat, kDouble };

// How the bulk pass writes the new populations. Out of cache an ordinary store first reads the
// destination line (write-allocate), so a step moves 108 bytes per cell over the bus (float)
// instead of the 72 it needs; non-temporal (streaming) stores write whole lines straight to
// memory. In cache they would throw away lines the next step reads again.
enum class Stores {
  kAuto,       // streaming when the two lattices (18 planes) exceed kStreamingStoresAbove
  kCached,     // ordinary stores
  kStreaming,  // non-temporal stores (x86 SSE2; ordinary stores elsewhere)
};

// kAuto switches to streaming stores above this many bytes of populations: the 32 MiB L3 of
// the development machine. A lattice that fits keeps its lines in cache from one step to the
// next, and streaming stores would evict them (docs/fluid.md: in cache they cost 60%).
inline constexpr double kStreamingStoresAbove = 32.0 * 1024 * 1024;

enum class SideKind {
  kPeriodic,  // leaves through this side, comes back through the opposite one (both must be
              // periodic)
  kWall,      // no-slip wall half a cell outside the grid; `velocity` makes it a moving wall (lid)
  kInlet,     // velocity inlet: `velocity` (times `profile`), imposed by moving-wall bounce-back
  kOutflow,   // open outlet at density 1 (pressure outlet, anti-bounce-back): flow leaves
              // freely; flow trying to come back in is stopped (vortices crossing it stay stable)
};

enum class SideName { kLeft, kRight, kTop, kBottom };

struct Side {
  SideKind kind = SideKind::kPeriodic;
  // Velocity of a moving wall or of the inlet flow, lattice units (cells per step); |v| <= 0.2.
  Vec2 velocity = Vec2::Zero();
  // Inlet only, optional: one factor per cell along the side (length = grid height for
  // left/right, width for top/bottom) multiplying `velocity`, e.g. a parabolic profile.
  std::vector<double> profile;
};

struct Options {
  int width = 0;   // cells along x, >= 2
  int height = 0;  // cells along y, >= 2
  // Relaxation time of the viscous (symmetric) moments; kinematic viscosity nu = (tau - 1/2) / 3.
  double tau = 0.6;
  Collision collision = Collision::kTrt;
  // TRT "magic" number Lambda = (tau+ - 1/2)(tau- - 1/2). 1/4 is the most stable choice;
  // 3/16 puts bounce-back walls exactly half-way between nodes for every tau.
  double trt_magic = 0.25;
  // Smagorinsky constant of a sub-grid eddy viscosity (Hou et al. 1996) added where the flow
  // is under-resolved; 0 = off (exact Navier-Stokes at the given viscosity, for validation).
  // 0.1 to 0.2 keeps gusty wind around sharp hair tips stable at low viscosity.
  double smagorinsky = 0.0;
  Precision precision = Precision::kFloat;
  int threads = 1;                // worker threads over rows, 1..64
  Stores stores = Stores::kAuto;  // results are identical bit for bit; only the speed differs

  Side left, right, top, bottom;  // default: periodic everywhere

  // Uniform body acceleration (cells / step^2), e.g. the pressure gradient of a periodic channel.
  Vec2 body_acceleration = Vec2::Zero();

  // Absorbing layer in front of every outflow side, this many cells deep (0 = none): the
  // density and velocity there are relaxed towards density 1 and `sponge_velocity`, so sound
  // waves (which gusts make, and which open sides reflect) and vortices fade out before they
  // reach the side instead of sloshing back and forth through the domain.
  int sponge_width = 0;
  Vec2 sponge_velocity = Vec2::Zero();  // lattice units, |v| <= kMaxLatticeSpeed

  // Static obstacles. `obstacle_labels` is empty or height x width (row y, column x):
  // 0 = fluid, k > 0 = solid cell of obstacle k. Each polygon of `obstacle_polygons` (grid
  // coordinates) becomes one more obstacle, labelled max(label) + 1 + its index; a cell is
  // solid when its node lies inside. Forces are reported per label.
  Eigen::MatrixXi obstacle_labels;
  std::vector<Polyline> obstacle_polygons;
  // Polygon obstacles: bounce back at the polygon's true boundary along each link
  // (interpolated bounce-back, Bouzidi et al. 2001), second-order accurate for curved walls.
  // false: half-way bounce-back on the staircase of solid cells, which conserves mass exactly.
  // Obstacles given as a mask always use the staircase.
  bool interpolated_walls = true;

  // Empty string or nullptr-safe: names the option, its value and the rule broken, e.g.
  // "fluid::Options::tau = 0.48; must be > 0.5".
  bool is_valid(std::string* error) const;

  const Side& side(SideName name) const;
  Side& side(SideName name);
};

// Lattice viscosity of a relaxation time and back: nu = (tau - 1/2) / 3.
double viscosity_of_tau(double tau);
double tau_of_viscosity(double nu);

// Largest lattice speed accepted anywhere (Mach 0.35); keep flows near 0.1 for accuracy.
inline constexpr double kMaxLatticeSpeed = 0.2;

}  // namespace hair25d::fluid
