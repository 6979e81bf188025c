// Wind in units an animator understands (image pixels, seconds, degrees) and their conversion
// to the lattice units of the solver, refusing settings that would make the flow unstable
// (Yeh et al. 2015, §6.1: "a single wind source is used to simulate the wind").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hair25d/core/geometry.h"
#include "hair25d/fluid/options.h"
#include "hair25d/fluid/solver.h"

namespace hair25d::fluid {

struct WindSettings {
  // Where the wind blows TO, in degrees from image +x (right) turning towards image +y (down):
  // 0 blows right, 90 blows down, 180 blows left.
  double direction_deg = 0.0;
  double speed = 200.0;        // mean speed, image pixels per second, >= 0
  double gust_period = 2.0;    // seconds per gust cycle; 0 = steady wind
  double gust_strength = 0.3;  // speed swings by +- this fraction over a gust cycle, [0, 1]
  double turbulence = 0.1;     // random fluctuations, as a fraction of the speed, [0, 1]
  std::uint64_t seed = 1;      // the same seed gives the same turbulence
  // The wind rises smoothly from still air over this many seconds (an abrupt start sends a
  // pressure wave through the scene that slaps the hair); 0 = starts at full strength.
  double ramp_time = 0.5;
  bool is_valid(std::string* error) const;
};

// The scene the wind blows through, in image units.
struct SceneUnits {
  int image_width = 0;             // pixels, >= 1
  int image_height = 0;            // pixels, >= 1
  double cell_size = 4.0;          // image pixels per lattice cell, > 0
  double frame_time = 1.0 / 24.0;  // seconds per animation frame, > 0
  // Kinematic viscosity, image pixels^2 per second. Real air at cartoon scale would be
  // unresolvable; this is an artistic knob: lower gives livelier, more turbulent wind.
  double viscosity = 400.0;
  // Lattice steps per frame; 0 picks the fewest that keep the peak wind at <= 0.06 cells/step
  // (flow squeezed between strands runs several times faster than the wind itself).
  int steps_per_frame = 0;
  Collision collision = Collision::kTrt;
  // Smagorinsky constant of the sub-grid eddy viscosity (see Options::smagorinsky); with it the
  // wind stays stable down to tau -> 1/2. 0 turns it off, and then the cell Reynolds number
  // (peak speed / viscosity in lattice units) must stay small.
  double smagorinsky = 0.15;
  bool is_valid(std::string* error) const;
};

// What to_lattice() chose. Image points map to grid coordinates by dividing by cell_size.
struct LatticeParameters {
  int width = 0, height = 0;  // grid cells covering the image
  double cell_size = 1.0;     // pixels per cell
  int steps_per_frame = 1;
  double dt = 1.0;          // seconds per lattice step
  double tau = 0.6;         // relaxation time
  double viscosity = 0.0;   // lattice units
  double peak_speed = 0.0;  // lattice units: the fastest the wind gets (gusts + turbulence)
  Collision collision = Collision::kTrt;
  double smagorinsky = 0.15;  // sub-grid model constant for Options::smagorinsky

  // Image velocity (pixels/s) <-> lattice velocity (cells/step).
  Vec2 to_lattice_velocity(const Vec2& pixels_per_second) const;
  Vec2 to_image_velocity(const Vec2& cells_per_step) const;
  // Image point (pixels) <-> grid coordinates (cells).
  Vec2 to_grid(const Vec2& image_point) const;
  Vec2 to_image(const Vec2& grid_point) const;
  // Lattice pressure (or force per unit length) -> image units for a fluid of density 1 per
  // pixel^2: pixels^2 / s^2 (times pixels for a force per unit length).
  double pressure_to_image(double lattice_pressure) const;
};

// A hair skeleton in image pixels with its node velocities in pixels per second (empty = at
// rest) as a filament in grid coordinates and cells per step, ready for Solver::set_filaments.
// Throws hair25d::Error when the velocity count is neither 0 nor the point count.
Filament to_filament(const Polyline& skeleton, const std::vector<Vec2>& velocities,
                     const LatticeParameters& lattice);

// Converts to lattice units. Throws hair25d::Error naming the setting when the result would
// be unstable: wind too fast for the steps per frame (Mach), viscosity so low that tau comes
// too close to 1/2 or the cell Reynolds number gets too high, or so high that tau explodes.
LatticeParameters to_lattice(const WindSettings& wind, const SceneUnits& scene);

// Solver options for a wind tunnel over the image: the sides the wind comes from are inlets,
// the sides it leaves by are outflows, sides parallel to it are periodic.
Options wind_tunnel_options(const WindSettings& wind, const LatticeParameters& lattice);

// The inlet wind over time: mean speed, gusts and seeded turbulence that varies along the
// inlet and in time (smooth value noise). Deterministic for a given seed.
class WindField {
 public:
  WindField(const WindSettings& wind, const LatticeParameters& lattice);
  // Wind velocity (cells/step) at time t (seconds) at position s (cells) along a side.
  Vec2 velocity(double t, double s) const;
  // Sets the inlet velocities of every inlet side of `solver` for time t (seconds).
  void apply(Solver& solver, double t) const;

 private:
  double noise(int channel, double t, double s) const;
  double strength(double t) const;  // gusts and start-up ramp, 1 = mean wind
  WindSettings wind_;
  LatticeParameters lattice_;
  Vec2 direction_;
  std::vector<double> knots_;  // 2 channels x kTimeKnots x kSpaceKnots values in [-1, 1]
};

}  // namespace hair25d::fluid
