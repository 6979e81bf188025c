#include "hair25d/fluid/wind.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>

#include "hair25d/core/error.h"
#include "stability.h"

namespace hair25d::fluid {
namespace {

// Peak inlet speed the automatic step count aims at (Mach 0.1). Between dense strands the flow
// runs 3-4 times faster than the inlet; measured on a comb of 8 hair filaments blocking 60% of
// the tunnel with gusts and turbulence, 0.063 stays stable and 0.095 blows up (docs/fluid.md).
constexpr double kTargetSpeed = 0.06;
// Hard limit for a user-chosen step count: Mach 0.17 at the inlet.
constexpr double kMaxWindSpeed = 0.1;
constexpr int kMaxStepsPerFrame = 10000;
constexpr int kSpongeCells = 12;
constexpr int kTimeKnots = 64;
constexpr int kSpaceKnots = 64;
constexpr double kNoiseCells = 12.0;    // correlation length of the turbulence along the inlet
constexpr double kNoiseSeconds = 0.25;  // correlation time of the turbulence

double peak_factor(const WindSettings& w) {
  return 1.0 + (w.gust_period > 0 ? w.gust_strength : 0.0) + std::sqrt(2.0) * w.turbulence;
}

double smooth(double t) { return t * t * (3.0 - 2.0 * t); }

}  // namespace

bool WindSettings::is_valid(std::string* error) const {
  std::ostringstream m;
  if (!std::isfinite(direction_deg))
    m << "fluid::WindSettings::direction_deg = " << direction_deg << "; must be finite";
  else if (!std::isfinite(speed) || speed < 0 || speed > 1e6)
    m << "fluid::WindSettings::speed = " << speed << " px/s; must be in [0, 1e6]";
  else if (!std::isfinite(gust_period) || gust_period < 0)
    m << "fluid::WindSettings::gust_period = " << gust_period << " s; must be >= 0 (0 = none)";
  else if (!std::isfinite(gust_strength) || gust_strength < 0 || gust_strength > 1)
    m << "fluid::WindSettings::gust_strength = " << gust_strength << "; must be in [0, 1]";
  else if (!std::isfinite(turbulence) || turbulence < 0 || turbulence > 1)
    m << "fluid::WindSettings::turbulence = " << turbulence << "; must be in [0, 1]";
  else if (!std::isfinite(ramp_time) || ramp_time < 0)
    m << "fluid::WindSettings::ramp_time = " << ramp_time << " s; must be >= 0";
  if (error) *error = m.str();
  return m.str().empty();
}

bool SceneUnits::is_valid(std::string* error) const {
  std::ostringstream m;
  if (image_width < 1 || image_width > 1 << 20)
    m << "fluid::SceneUnits::image_width = " << image_width << "; must be in [1, 2^20] pixels";
  else if (image_height < 1 || image_height > 1 << 20)
    m << "fluid::SceneUnits::image_height = " << image_height << "; must be in [1, 2^20] pixels";
  else if (!std::isfinite(cell_size) || !(cell_size > 0))
    m << "fluid::SceneUnits::cell_size = " << cell_size << "; must be > 0 pixels";
  else if (std::ceil(image_width / cell_size) < 2 || std::ceil(image_height / cell_size) < 2)
    m << "fluid::SceneUnits::cell_size = " << cell_size
      << "; must give at least 2 x 2 cells over the " << image_width << " x " << image_height
      << " image";
  else if (std::ceil(image_width / cell_size) > kMaxGridSide ||
           std::ceil(image_height / cell_size) > kMaxGridSide ||
           std::ceil(image_width / cell_size) * std::ceil(image_height / cell_size) > kMaxGridCells)
    m << "fluid::SceneUnits::cell_size = " << cell_size << "; gives more than " << kMaxGridCells
      << " cells (or a side over " << kMaxGridSide << ") over the " << image_width << " x "
      << image_height << " image";
  else if (!std::isfinite(frame_time) || !(frame_time > 0) || frame_time > 10)
    m << "fluid::SceneUnits::frame_time = " << frame_time << " s; must be in (0, 10]";
  else if (!std::isfinite(viscosity) || !(viscosity > 0))
    m << "fluid::SceneUnits::viscosity = " << viscosity << " px^2/s; must be > 0";
  else if (!std::isfinite(smagorinsky) || smagorinsky < 0 || smagorinsky > 0.5)
    m << "fluid::SceneUnits::smagorinsky = " << smagorinsky << "; must be in [0, 0.5] (0 = off)";
  else if (steps_per_frame < 0 || steps_per_frame > kMaxStepsPerFrame)
    m << "fluid::SceneUnits::steps_per_frame = " << steps_per_frame << "; must be in [0, "
      << kMaxStepsPerFrame << "] (0 = automatic)";
  if (error) *error = m.str();
  return m.str().empty();
}

Vec2 LatticeParameters::to_lattice_velocity(const Vec2& v) const { return v * dt / cell_size; }
Vec2 LatticeParameters::to_image_velocity(const Vec2& v) const { return v * cell_size / dt; }
Vec2 LatticeParameters::to_grid(const Vec2& p) const { return p / cell_size; }
Vec2 LatticeParameters::to_image(const Vec2& p) const { return p * cell_size; }
double LatticeParameters::pressure_to_image(double p) const {
  const double c = cell_size / dt;
  return p * c * c;
}

Filament to_filament(const Polyline& skeleton, const std::vector<Vec2>& velocities,
                     const LatticeParameters& lattice) {
  if (!velocities.empty() && velocities.size() != skeleton.size())
    throw Error("fluid::to_filament: " + std::to_string(velocities.size()) + " velocities for " +
                std::to_string(skeleton.size()) + " skeleton points; must be 0 or one per point");
  Filament f;
  f.points.reserve(skeleton.size());
  for (const Vec2& p : skeleton) f.points.push_back(lattice.to_grid(p));
  f.velocities.reserve(velocities.size());
  for (const Vec2& v : velocities) f.velocities.push_back(lattice.to_lattice_velocity(v));
  return f;
}

LatticeParameters to_lattice(const WindSettings& wind, const SceneUnits& scene) {
  std::string error;
  if (!wind.is_valid(&error) || !scene.is_valid(&error)) throw Error(error);
  LatticeParameters p;
  p.cell_size = scene.cell_size;
  p.width = static_cast<int>(std::ceil(scene.image_width / scene.cell_size));
  p.height = static_cast<int>(std::ceil(scene.image_height / scene.cell_size));
  p.collision = scene.collision;
  p.smagorinsky = scene.smagorinsky;
  // Peak wind in cells per frame; the step count divides it down to lattice speed.
  const double peak_cells_per_frame =
      wind.speed * peak_factor(wind) * scene.frame_time / scene.cell_size;
  std::ostringstream m;
  if (scene.steps_per_frame == 0) {
    const double n = std::ceil(peak_cells_per_frame / kTargetSpeed);
    if (n > kMaxStepsPerFrame) {
      m << "fluid::WindSettings::speed = " << wind.speed << " px/s needs " << n
        << " lattice steps per frame at fluid::SceneUnits::cell_size = " << scene.cell_size
        << " px; must need <= " << kMaxStepsPerFrame << " (lower the speed or raise cell_size)";
      throw Error(m.str());
    }
    p.steps_per_frame = std::max(1, static_cast<int>(n));
  } else {
    p.steps_per_frame = scene.steps_per_frame;
  }
  p.dt = scene.frame_time / p.steps_per_frame;
  p.peak_speed = peak_cells_per_frame / p.steps_per_frame;
  if (p.peak_speed > kMaxWindSpeed) {
    m << "fluid::WindSettings::speed = " << wind.speed << " px/s peaks (with gusts and "
      << "turbulence) at " << p.peak_speed
      << " cells/step with fluid::SceneUnits::steps_per_frame = " << p.steps_per_frame
      << "; must be <= " << kMaxWindSpeed
      << " cells/step (Mach too high): raise steps_per_frame (or 0 = automatic) or cell_size";
    throw Error(m.str());
  }
  p.viscosity = scene.viscosity * p.dt / (scene.cell_size * scene.cell_size);
  p.tau = tau_of_viscosity(p.viscosity);
  const bool bgk = scene.collision == Collision::kBgk;
  const double min_tau = bgk ? kMinTauBgk : kMinTauTrt;
  const double max_re = bgk ? kMaxCellReynoldsBgk : kMaxCellReynoldsTrt;
  if (p.tau < min_tau) {
    m << "fluid::SceneUnits::viscosity = " << scene.viscosity << " px^2/s gives tau = " << p.tau
      << "; must give tau >= " << min_tau << (bgk ? " with BGK" : " with TRT")
      << " (too close to 1/2 is unstable): raise viscosity or cell_size";
    throw Error(m.str());
  }
  if (scene.smagorinsky == 0.0 && p.peak_speed / p.viscosity > max_re) {
    m << "fluid::SceneUnits::viscosity = " << scene.viscosity << " px^2/s gives a cell Reynolds "
      << "number (peak speed / viscosity, lattice units) of " << p.peak_speed / p.viscosity
      << "; must be <= " << max_re << (bgk ? " with BGK" : " with TRT")
      << " without a sub-grid model or the flow blows up: raise viscosity or cell_size, lower "
         "the wind speed, or set fluid::SceneUnits::smagorinsky (e.g. 0.15)";
    throw Error(m.str());
  }
  if (p.tau > kMaxTau) {
    m << "fluid::SceneUnits::viscosity = " << scene.viscosity << " px^2/s gives tau = " << p.tau
      << "; must give tau <= " << kMaxTau << ": lower viscosity or raise steps_per_frame";
    throw Error(m.str());
  }
  return p;
}

Options wind_tunnel_options(const WindSettings& wind, const LatticeParameters& lattice) {
  std::string error;
  if (!wind.is_valid(&error)) throw Error(error);
  Options o;
  o.width = lattice.width;
  o.height = lattice.height;
  o.tau = lattice.tau;
  o.collision = lattice.collision;
  o.smagorinsky = lattice.smagorinsky;
  const double a = wind.direction_deg * std::numbers::pi / 180.0;
  const Vec2 d(std::cos(a), std::sin(a));
  const Vec2 u = d * wind.speed * lattice.dt / lattice.cell_size;
  constexpr double kParallel = 1e-9;
  auto pair = [&](Side& upwind_if_positive, Side& other, double component) {
    if (std::abs(component) <= kParallel) return;  // both stay periodic
    Side& in = component > 0 ? upwind_if_positive : other;
    Side& out = component > 0 ? other : upwind_if_positive;
    in.kind = SideKind::kInlet;
    in.velocity = u;
    out.kind = SideKind::kOutflow;
  };
  pair(o.left, o.right, d.x());
  pair(o.top, o.bottom, d.y());
  // Gusts send sound waves through the tunnel; a sponge in front of the outlets absorbs them.
  o.sponge_width = std::min(kSpongeCells, std::min(o.width, o.height) / 4);
  o.sponge_velocity = u;
  return o;
}

WindField::WindField(const WindSettings& wind, const LatticeParameters& lattice)
    : wind_(wind), lattice_(lattice) {
  std::string error;
  if (!wind.is_valid(&error)) throw Error(error);
  const double a = wind.direction_deg * std::numbers::pi / 180.0;
  direction_ = Vec2(std::cos(a), std::sin(a));
  std::mt19937_64 rng(wind.seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  knots_.resize(2 * kTimeKnots * kSpaceKnots);
  for (double& k : knots_) k = uniform(rng);
}

double WindField::noise(int channel, double t, double s) const {
  // Smooth value noise, periodic over kTimeKnots x kSpaceKnots knots.
  const double tt = t / kNoiseSeconds, ss = s / kNoiseCells;
  const double ft = std::floor(tt), fs = std::floor(ss);
  const auto it = static_cast<long long>(ft), is = static_cast<long long>(fs);
  const double wt = smooth(tt - ft), ws = smooth(ss - fs);
  auto knot = [&](long long i, long long j) {
    const auto ti = static_cast<std::size_t>(((i % kTimeKnots) + kTimeKnots) % kTimeKnots);
    const auto sj = static_cast<std::size_t>(((j % kSpaceKnots) + kSpaceKnots) % kSpaceKnots);
    return knots_[(static_cast<std::size_t>(channel) * kTimeKnots + ti) * kSpaceKnots + sj];
  };
  const double a = knot(it, is) * (1 - ws) + knot(it, is + 1) * ws;
  const double b = knot(it + 1, is) * (1 - ws) + knot(it + 1, is + 1) * ws;
  return a * (1 - wt) + b * wt;
}

double WindField::strength(double t) const {
  double factor = 1.0;
  if (wind_.gust_period > 0)
    factor += wind_.gust_strength * std::sin(2.0 * std::numbers::pi * t / wind_.gust_period);
  if (wind_.ramp_time > 0 && t < wind_.ramp_time)
    factor *= smooth(std::max(0.0, t) / wind_.ramp_time);
  return factor;
}

Vec2 WindField::velocity(double t, double s) const {
  const double factor = strength(t);
  const double base = wind_.speed * lattice_.dt / lattice_.cell_size;
  Vec2 v = direction_ * base * factor;
  if (wind_.turbulence > 0) v += base * wind_.turbulence * Vec2(noise(0, t, s), noise(1, t, s));
  return v;
}

void WindField::apply(Solver& solver, double t) const {
  const Options& o = solver.options();
  for (SideName side : {SideName::kLeft, SideName::kRight, SideName::kTop, SideName::kBottom}) {
    if (o.side(side).kind != SideKind::kInlet) continue;
    const bool vertical = side == SideName::kLeft || side == SideName::kRight;
    const int n = vertical ? o.height : o.width;
    // Distinct offsets so the sides of an oblique wind do not carry the same pattern.
    const double offset = vertical ? 0.0 : 1000.0;
    std::vector<Vec2> cells(n);
    for (int k = 0; k < n; ++k) cells[k] = velocity(t, offset + k + 0.5);
    solver.set_inlet_velocities(side, cells);
  }
  // The sponge relaxes towards the wind without its turbulence.
  if (o.sponge_width > 0)
    solver.set_sponge_velocity(direction_ * wind_.speed * lattice_.dt / lattice_.cell_size *
                               strength(t));
}

}  // namespace hair25d::fluid
