// Wind settings in image units, their conversion to lattice units (and the refusals of
// unstable settings), the wind tunnel layout per direction, gusts and seeded turbulence.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "hair25d/core/error.h"
#include "hair25d/fluid/wind.h"

namespace hair25d::fluid {
namespace {

SceneUnits scene() {
  SceneUnits s;
  s.image_width = 640;
  s.image_height = 480;
  s.cell_size = 4.0;
  s.frame_time = 1.0 / 24.0;
  s.viscosity = 400.0;
  return s;
}

template <typename F>
void expect_error(F&& f, const std::string& words) {
  try {
    f();
    ADD_FAILURE() << "no error for: " << words;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(FluidWind, ToLatticeConvertsUnits) {
  WindSettings w;
  w.speed = 200.0;
  w.gust_strength = 0.3;
  w.turbulence = 0.1;
  const LatticeParameters p = to_lattice(w, scene());
  EXPECT_EQ(p.width, 160);
  EXPECT_EQ(p.height, 120);
  // Peak: 200 px/s * (1 + 0.3 + 0.1 sqrt 2) / 24 frames/s / 4 px = 3.003 cells per frame.
  const double peak_per_frame = 200.0 * (1.3 + 0.1 * std::sqrt(2.0)) / 24.0 / 4.0;
  EXPECT_EQ(p.steps_per_frame, static_cast<int>(std::ceil(peak_per_frame / 0.06)));
  EXPECT_NEAR(p.peak_speed, peak_per_frame / p.steps_per_frame, 1e-12);
  EXPECT_LE(p.peak_speed, 0.06);
  EXPECT_EQ(p.smagorinsky, 0.15);
  EXPECT_NEAR(p.dt, 1.0 / 24.0 / p.steps_per_frame, 1e-15);
  EXPECT_NEAR(p.viscosity, 400.0 * p.dt / 16.0, 1e-15);
  EXPECT_NEAR(p.tau, 3 * p.viscosity + 0.5, 1e-15);
  const Vec2 v(123.0, -45.0);
  EXPECT_LT((p.to_image_velocity(p.to_lattice_velocity(v)) - v).norm(), 1e-9);
  EXPECT_NEAR(p.to_lattice_velocity(Vec2(200, 0)).x(), 200 * p.dt / 4.0, 1e-15);
  EXPECT_EQ(p.to_grid(Vec2(8, 12)), Vec2(2, 3));
  EXPECT_EQ(p.to_image(Vec2(2, 3)), Vec2(8, 12));
  const Filament f = to_filament({Vec2(8, 12), Vec2(16, 12)}, {Vec2(200, 0), Vec2(0, 100)}, p);
  EXPECT_EQ(f.points[1], Vec2(4, 3));
  EXPECT_NEAR(f.velocities[0].x(), 200 * p.dt / 4.0, 1e-15);
  EXPECT_NEAR(f.velocities[1].y(), 100 * p.dt / 4.0, 1e-15);
  expect_error(
      [&] {
        to_filament({Vec2(8, 12), Vec2(16, 12)}, {Vec2(1, 0)}, p);
      },
      "fluid::to_filament: 1 velocities for 2 skeleton points");
  EXPECT_NEAR(p.pressure_to_image(1.0), std::pow(4.0 / p.dt, 2), 1e-6);
  // Explicit step count is kept.
  SceneUnits s = scene();
  s.steps_per_frame = 40;
  EXPECT_EQ(to_lattice(w, s).steps_per_frame, 40);
}

TEST(FluidWind, ToLatticeRefusesUnstableSettingsNamingThem) {
  WindSettings w;
  SceneUnits s = scene();
  s.steps_per_frame = 1;  // 3 cells per step: far beyond the speed of sound
  expect_error([&] { to_lattice(w, s); }, "fluid::SceneUnits::steps_per_frame = 1");
  expect_error([&] { to_lattice(w, s); }, "Mach");
  s = scene();
  s.viscosity = 1e-3;
  expect_error([&] { to_lattice(w, s); }, "fluid::SceneUnits::viscosity = 0.001");
  s.collision = Collision::kBgk;
  s.viscosity = 30.0;
  expect_error([&] { to_lattice(w, s); }, "with BGK");
  // Without the sub-grid model a low viscosity is refused by the cell Reynolds number.
  s = scene();
  s.smagorinsky = 0.0;
  s.viscosity = 20.0;
  expect_error([&] { to_lattice(w, s); }, "cell Reynolds");
  s.smagorinsky = 0.15;
  EXPECT_NO_THROW(to_lattice(w, s));
  s = scene();
  s.viscosity = 1e7;
  expect_error([&] { to_lattice(w, s); }, "must give tau <= 5");
  s = scene();
  w.speed = 1e6;
  s.cell_size = 0.01;
  expect_error([&] { to_lattice(w, s); }, "cell_size");
}

TEST(FluidWind, BadSettingsNameTheSetting) {
  WindSettings w;
  w.direction_deg = std::nan("");
  expect_error([&] { to_lattice(w, scene()); }, "fluid::WindSettings::direction_deg = nan");
  w = WindSettings();
  w.speed = -3;
  expect_error([&] { to_lattice(w, scene()); }, "fluid::WindSettings::speed = -3");
  w = WindSettings();
  w.gust_strength = 2;
  expect_error([&] { to_lattice(w, scene()); }, "fluid::WindSettings::gust_strength = 2");
  w = WindSettings();
  w.turbulence = -0.1;
  expect_error([&] { to_lattice(w, scene()); }, "fluid::WindSettings::turbulence = -0.1");
  w = WindSettings();
  w.gust_period = -1;
  expect_error([&] { WindField(w, LatticeParameters{}); }, "gust_period = -1");
  SceneUnits s = scene();
  s.image_width = -3;
  expect_error([&] { to_lattice(WindSettings(), s); }, "fluid::SceneUnits::image_width = -3");
  s = scene();
  s.cell_size = 0;
  expect_error([&] { to_lattice(WindSettings(), s); }, "fluid::SceneUnits::cell_size = 0");
  s = scene();
  s.cell_size = 1000;
  expect_error([&] { to_lattice(WindSettings(), s); }, "at least 2 x 2 cells");
  s = scene();
  s.frame_time = 0;
  expect_error([&] { to_lattice(WindSettings(), s); }, "fluid::SceneUnits::frame_time = 0");
  s = scene();
  s.steps_per_frame = -2;
  expect_error([&] { to_lattice(WindSettings(), s); }, "steps_per_frame = -2");
}

TEST(FluidWind, TunnelSidesFollowTheDirection) {
  WindSettings w;
  const LatticeParameters p = to_lattice(w, scene());
  auto sides = [&](double deg) {
    w.direction_deg = deg;
    return wind_tunnel_options(w, p);
  };
  Options o = sides(0);  // blowing right
  EXPECT_EQ(o.left.kind, SideKind::kInlet);
  EXPECT_EQ(o.right.kind, SideKind::kOutflow);
  EXPECT_EQ(o.top.kind, SideKind::kPeriodic);
  EXPECT_GT(o.left.velocity.x(), 0.0);
  EXPECT_TRUE(o.is_valid(nullptr));
  o = sides(180);
  EXPECT_EQ(o.right.kind, SideKind::kInlet);
  EXPECT_EQ(o.left.kind, SideKind::kOutflow);
  EXPECT_LT(o.right.velocity.x(), 0.0);
  o = sides(90);  // blowing down the image: comes in at the top (y = 0)
  EXPECT_EQ(o.top.kind, SideKind::kInlet);
  EXPECT_EQ(o.bottom.kind, SideKind::kOutflow);
  EXPECT_EQ(o.left.kind, SideKind::kPeriodic);
  EXPECT_GT(o.top.velocity.y(), 0.0);
  o = sides(-150);  // up and to the left
  EXPECT_EQ(o.right.kind, SideKind::kInlet);
  EXPECT_EQ(o.bottom.kind, SideKind::kInlet);
  EXPECT_EQ(o.left.kind, SideKind::kOutflow);
  EXPECT_EQ(o.top.kind, SideKind::kOutflow);
  const double a = -150 * std::numbers::pi / 180;
  const Vec2 expected = Vec2(std::cos(a), std::sin(a)) * w.speed * p.dt / p.cell_size;
  EXPECT_LT((o.right.velocity - expected).norm(), 1e-12);
  EXPECT_EQ(o.smagorinsky, p.smagorinsky);
  EXPECT_TRUE(o.is_valid(nullptr));
}

TEST(FluidWind, GustsAndSeededTurbulence) {
  WindSettings w;
  w.speed = 150;
  w.gust_period = 2.0;
  w.gust_strength = 0.4;
  w.turbulence = 0.0;
  const LatticeParameters p = to_lattice(w, scene());
  const double base = 150 * p.dt / p.cell_size;
  const WindField calm(w, p);
  EXPECT_NEAR(calm.velocity(0.5, 3).x(), base * 1.4, 1e-12);  // crest at a quarter period
  EXPECT_NEAR(calm.velocity(0.0, 3).x(), 0.0, 1e-15);         // still air at the start
  EXPECT_NEAR(calm.velocity(0.125, 3).x(),
              base * std::pow(0.25, 2) * (3 - 0.5) * (1 + 0.4 * std::sin(std::numbers::pi / 8)),
              1e-12);  // smooth ramp
  EXPECT_NEAR(calm.velocity(1.5, 3).x(), base * 0.6, 1e-12);
  EXPECT_NEAR(calm.velocity(1.0, 3).y(), 0.0, 1e-15);

  w.turbulence = 0.3;
  w.seed = 7;
  const LatticeParameters pt = to_lattice(w, scene());
  const WindField a(w, pt), b(w, pt);
  w.seed = 8;
  const WindField c(w, pt);
  double differ = 0, mean_x = 0, peak = 0;
  int n = 0;
  for (double t = 0; t < 16; t += 0.01)
    for (double s = 0; s < 768; s += 7.3) {
      const Vec2 va = a.velocity(t, s);
      EXPECT_EQ(va, b.velocity(t, s));
      differ = std::max(differ, (va - c.velocity(t, s)).norm());
      mean_x += va.x();
      peak = std::max(peak, va.norm());
      ++n;
    }
  mean_x /= n;
  const double base_t = 150 * pt.dt / pt.cell_size;
  EXPECT_GT(differ, 0.1 * base_t);          // another seed, other turbulence
  EXPECT_NEAR(mean_x / base_t, 1.0, 0.05);  // fluctuations average out
  EXPECT_LE(peak, pt.peak_speed + 1e-12);   // never past the peak to_lattice planned
  EXPECT_GT(peak, 1.3 * base_t);            // but gusts and turbulence do show
}

// A gust slams into a closed-off tunnel end: with the sponge the sound it makes is absorbed at
// the outlet; without it the wave keeps bouncing between inlet and outlet.
TEST(FluidWind, SpongeAbsorbsSound) {
  auto ringing = [](int sponge) {
    Options o;
    o.width = 120;
    o.height = 30;
    o.tau = 0.52;
    o.left.kind = SideKind::kInlet;
    o.left.velocity = Vec2(0.05, 0);
    o.right.kind = SideKind::kOutflow;
    o.sponge_width = sponge;
    o.sponge_velocity = Vec2(0.05, 0);
    Solver s(o);
    s.step(1500);  // the start-up pulse has crossed the tunnel several times
    const FlowField f = s.field();
    return f.density.maxCoeff() - f.density.minCoeff();
  };
  const double with = ringing(12), without = ringing(0);
  std::printf("[ info ] density range after the start-up pulse: %.4f with sponge, %.4f without\n",
              with, without);
  EXPECT_LT(with, 0.5 * without);
}

// End to end: wind from the right through a tunnel with a hanging hair: the hair is pushed
// left on average, the flow goes left, and the gusty inlet changes the force over time.
TEST(FluidWind, WindTunnelPushesHairDownwind) {
  WindSettings w;
  w.direction_deg = 180;
  w.speed = 120;
  w.gust_period = 1.0;
  w.gust_strength = 0.3;
  w.turbulence = 0.2;
  SceneUnits s;
  s.image_width = 300;
  s.image_height = 200;
  s.cell_size = 4;
  s.viscosity = 300;
  const LatticeParameters p = to_lattice(w, s);
  Options o = wind_tunnel_options(w, p);
  o.threads = 2;
  Solver solver(o);
  const WindField wind(w, p);
  Filament hair;
  Polyline skeleton;
  for (int k = 0; k <= 10; ++k) skeleton.push_back(Vec2(150 + 3 * k, 40 + 10 * k));
  hair = to_filament(skeleton, {}, p);
  EXPECT_EQ(hair.points[2], Vec2(156, 60) / s.cell_size);
  EXPECT_TRUE(hair.velocities.empty());
  solver.set_filaments({hair});
  double fmin = 1e9, fmax = -1e9, mean = 0;
  const int frames = 36;
  for (int f = 0; f < frames; ++f) {
    for (int k = 0; k < p.steps_per_frame; ++k) {
      wind.apply(solver, (f * p.steps_per_frame + k) * p.dt);
      solver.step();
    }
    Vec2 total = Vec2::Zero();
    for (const SegmentForce& sf : solver.filament_forces()[0]) total += sf.force;
    if (f >= frames / 3) {
      fmin = std::min(fmin, total.x());
      fmax = std::max(fmax, total.x());
      mean += total.x() / (frames - frames / 3);
    }
  }
  EXPECT_LT(mean, 0.0);                          // pushed to the left
  EXPECT_GT(fmax - fmin, 0.2 * std::abs(mean));  // and not always the same: gusts
  EXPECT_LT(solver.field().ux.mean(), 0.0);
  const FlowField f = solver.field();
  EXPECT_GT(f.density.minCoeff(), 0.9);  // the sponge keeps sound waves down
  EXPECT_LT(f.density.maxCoeff(), 1.1);
}

}  // namespace
}  // namespace hair25d::fluid
