// Moving thin filaments (hair skeletons) as boundaries: no leaks at any angle, the right
// force by momentum exchange, resistance against motion, and clear errors for bad filaments.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "hair25d/core/error.h"
#include "hair25d/fluid/solver.h"

namespace hair25d::fluid {
namespace {

Polyline regular_polygon(const Vec2& centre, double radius, int n, double phase) {
  Polyline p;
  for (int k = 0; k <= n; ++k) {  // closed: the last point repeats the first
    const double a = phase + 2 * std::numbers::pi * (k % n) / n;
    p.push_back(centre + radius * Vec2(std::cos(a), std::sin(a)));
  }
  return p;
}

// A closed filament splits the fluid in two; the mass inside must stay inside to round-off,
// whatever the angles of its sides (thin slivers, 45 degrees, sides through lattice nodes).
TEST(FluidFilament, ClosedFilamentKeepsItsMassToRoundOff) {
  const int W = 46, H = 31;
  const std::vector<Polyline> shapes = {
      regular_polygon(Vec2(20.3, 15.1), 9.7, 24, 0.1),
      {Vec2(5.2, 4.9), Vec2(40.7, 9.3), Vec2(8.1, 6.6), Vec2(5.2, 4.9)},  // sliver
      {Vec2(22.5, 3.5), Vec2(34.5, 15.5), Vec2(22.5, 27.5), Vec2(10.5, 15.5), Vec2(22.5, 3.5)},
      regular_polygon(Vec2(23.0, 15.5), 11.0, 7, 0.33)};
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    Options o;
    o.width = W;
    o.height = H;
    o.tau = 0.62;
    o.precision = Precision::kDouble;
    Solver s(o);
    s.set_filaments({{shapes[k], {}}});
    Eigen::MatrixXd rho(H, W), ux(H, W), uy(H, W);
    for (int j = 0; j < H; ++j)
      for (int i = 0; i < W; ++i) {
        const bool in = point_in_polygon(shapes[k], Vec2(i + 0.5, j + 0.5));
        rho(j, i) = in ? 1.04 : 0.98;
        ux(j, i) = 0.05 * std::sin(0.4 * j);
        uy(j, i) = 0.05 * std::cos(0.3 * i);
      }
    s.initialize(rho, ux, uy);
    auto inside_mass = [&]() {
      const FlowField f = s.field();
      double m = 0;
      for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i)
          if (point_in_polygon(shapes[k], Vec2(i + 0.5, j + 0.5))) m += f.density(j, i);
      return m;
    };
    const double m0 = inside_mass(), total0 = s.total_mass();
    s.step(1500);
    EXPECT_NEAR(inside_mass() / m0, 1.0, 1e-11) << "shape " << k;
    EXPECT_NEAR(s.total_mass() / total0, 1.0, 1e-11) << "shape " << k;
    // Without the filament the pressure jump would have evened out long ago.
    const FlowField f = s.field();
    EXPECT_GT(f.density.maxCoeff() - f.density.minCoeff(), 0.03) << "shape " << k;
  }
}

// A plate spanning a force-driven channel at several angles: no flux passes, and at rest the
// plate carries the whole body force, g times the mass, as a pressure jump across it.
TEST(FluidFilament, SpanningPlateStopsTheFlowAndCarriesTheBodyForce) {
  const int W = 60, H = 22;
  const double g = 1e-5;
  for (double angle_deg : {90.0, 63.0, 45.0, 30.0}) {
    Options o;
    o.width = W;
    o.height = H;
    o.tau = 0.9;
    o.top.kind = o.bottom.kind = SideKind::kWall;
    o.body_acceleration = Vec2(g, 0);
    o.threads = 2;
    Solver s(o);
    // From beyond the bottom wall to beyond the top wall, in 6 pieces, through x = 30.
    const double slope = 1.0 / std::tan(angle_deg * std::numbers::pi / 180.0);
    Filament plate;
    for (int k = 0; k <= 6; ++k) {
      const double y = -1.0 + (H + 2.0) * k / 6.0;
      plate.points.push_back(Vec2(30.0 + (y - H / 2.0) * slope, y));
    }
    s.set_filaments({plate});
    // Free flux through the channel without the plate: g H^3 / (12 nu).
    const double nu = viscosity_of_tau(o.tau);
    const double free_flux = g * H * H * H / (12 * nu);
    s.step(6000);
    double worst_flux = 0;
    for (int x : {2, 15, 50}) {
      double q = 0;
      for (int y = 0; y < H; ++y) q += s.velocity(x, y).x();
      worst_flux = std::max(worst_flux, std::abs(q));
    }
    EXPECT_LT(worst_flux, 1e-3 * free_flux) << angle_deg << " degrees";
    Vec2 total = Vec2::Zero();
    for (const SegmentForce& f : s.filament_forces()[0]) total += f.force;
    const double weight = g * s.total_mass();
    std::printf("[ info ] spanning plate at %.0f deg: flux %.2g of free flux, Fx / (g M) = %.4f\n",
                angle_deg, worst_flux / free_flux, total.x() / weight);
    EXPECT_NEAR(total.x() / weight, 1.0, 0.02) << angle_deg << " degrees";
    // Pressure jump: p = rho / 3 and the density gradient is 3 g, so the jump across the plate
    // is g W. At rest there is no shear: each segment's force is (nearly) normal to it.
    for (std::size_t k = 1; k + 1 < s.filament_forces()[0].size(); ++k) {
      const SegmentForce& f = s.filament_forces()[0][k];
      const Vec2 d = (plate.points[k + 1] - plate.points[k]).normalized();
      EXPECT_NEAR(std::abs(f.pressure_difference) / (g * W), 1.0, 0.05) << angle_deg;
      // Link by link the staircase adds a little tangential force per segment.
      EXPECT_LT(std::abs(f.force.dot(d)), 0.1 * f.force.norm()) << angle_deg;
      EXPECT_GT(f.force.x(), 0.0);
    }
  }
}

Options stream(int W, int H, double u, double tau) {
  Options o;
  o.width = W;
  o.height = H;
  o.tau = tau;
  o.left.kind = SideKind::kInlet;
  o.left.velocity = Vec2(u, 0);
  o.right.kind = SideKind::kOutflow;
  o.top.kind = o.bottom.kind = SideKind::kWall;
  o.threads = 2;
  return o;
}

// A thin plate across a stream gets the drag of a plate: the same as a one-cell-thick solid
// plate of the same height (a different boundary code path), no lift, and a drag coefficient
// in the range of bluff bodies at this Reynolds number.
TEST(FluidFilament, PlateAcrossStreamGetsPlateDrag) {
  const int W = 120, H = 48;
  const double U = 0.05, L = 12;
  const double tau = 0.6;  // Re = U L / nu = 18
  Options thin = stream(W, H, U, tau);
  Solver s(thin);
  s.initialize_uniform(1.0, Vec2(U, 0));  // no start-up shock to wait out
  s.set_filaments({{{Vec2(40, 18), Vec2(40, 24), Vec2(40, 30)}, {}}});
  const SteadyResult r = run_to_steady(s, {40000, 500, 1e-4});
  EXPECT_EQ(r.stop, SteadyResult::Stop::kConverged) << r.why();
  Vec2 thin_force = Vec2::Zero();
  for (const SegmentForce& f : s.filament_forces()[0]) thin_force += f.force;

  Options solid = stream(W, H, U, tau);
  solid.obstacle_labels = Eigen::MatrixXi::Zero(H, W);
  solid.obstacle_labels.block(18, 39, 12, 1).setConstant(1);  // cells 18..29 of column 39
  Solver ss(solid);
  ss.initialize_uniform(1.0, Vec2(U, 0));
  run_to_steady(ss, {40000, 500, 1e-4});
  const Vec2 solid_force = ss.obstacle_forces().at(0).force;

  const double cd_thin = thin_force.x() / (0.5 * U * U * L);
  const double cd_solid = solid_force.x() / (0.5 * U * U * L);
  std::printf(
      "[ info ] plate across stream, Re %.0f: Cd thin filament %.3f, solid plate %.3f "
      "after %d steps\n",
      U * L / viscosity_of_tau(tau), cd_thin, cd_solid, r.steps);
  // The thin plate is slightly longer in effect: links that touch its ends are cut too.
  EXPECT_NEAR(cd_thin / cd_solid, 1.0, 0.12);
  // A 2D plate in free stream has Cd ~ 2 at high Re and more at low Re; this channel blocks a
  // quarter of the section, which raises it further.
  EXPECT_GT(cd_thin, 2.0);
  EXPECT_LT(cd_thin, 8.0);
  EXPECT_LT(std::abs(thin_force.y()), 1e-3 * thin_force.x());
  // Drawn with d = (0, +1), the plate's n = (-d.y, d.x) = (-1, 0) points upstream; the flow
  // pushes it downstream, so F.n / length < 0 on every segment.
  for (const SegmentForce& f : s.filament_forces()[0]) EXPECT_LT(f.pressure_difference, 0.0);
  // Flow goes around, not through: just behind the plate's middle the flow is slow or reversed.
  EXPECT_LT(s.velocity(40, 24).x(), 0.2 * U);
  EXPECT_GT(s.velocity(40, 5).x(), U);
}

// A plate moved through still fluid feels a force against its motion, larger when faster,
// and drags the fluid along; the fluid's momentum is what the plate gave it.
TEST(FluidFilament, MovingPlateFeelsResistanceAgainstItsMotion) {
  const int W = 96, H = 40;
  auto run = [&](const Vec2& v, double* fluid_momentum_x, double* impulse_x) {
    Options o;
    o.width = W;
    o.height = H;
    o.tau = 0.7;
    o.precision = Precision::kDouble;
    Solver s(o);
    Vec2 offset(30.0, 12.3);
    Vec2 mean = Vec2::Zero();
    *impulse_x = 0;
    const int steps = 600;
    for (int t = 0; t < steps; ++t) {
      Filament f;
      f.points = {offset, offset + Vec2(0.0, 8.0), offset + Vec2(0.0, 16.0)};
      f.velocities.assign(3, v);
      s.set_filaments({f});
      s.step();
      Vec2 total = Vec2::Zero();
      for (const SegmentForce& sf : s.filament_forces()[0]) total += sf.force;
      *impulse_x += total.x();
      if (t >= steps - 200) mean += total / 200.0;
      offset += v;
    }
    const FlowField field = s.field();
    *fluid_momentum_x = (field.density.array() * field.ux.array()).sum();
    return mean;
  };
  double p1, i1, p2, i2, p3, i3;
  const Vec2 slow = run(Vec2(0.02, 0), &p1, &i1);
  const Vec2 fast = run(Vec2(0.04, 0), &p2, &i2);
  const Vec2 along = run(Vec2(0, 0.02), &p3, &i3);
  std::printf(
      "[ info ] moving plate: Fx %.3g (v 0.02), %.3g (v 0.04), along-plate Fy %.3g; "
      "fluid momentum %.4g vs impulse %.4g\n",
      slow.x(), fast.x(), along.y(), p1, -i1);
  EXPECT_LT(slow.x(), 0.0);
  EXPECT_LT(fast.x(), 1.5 * slow.x());  // more negative: at least 1.5x the resistance
  EXPECT_LT(along.y(), 0.0);
  EXPECT_LT(std::abs(along.y()), 0.5 * std::abs(slow.x()));  // shear drag < pressure drag
  EXPECT_GT(p1, 0.0);
  // Momentum given to the fluid = minus the impulse of the flow on the plate.
  EXPECT_NEAR(p1 / -i1, 1.0, 0.1);
  EXPECT_NEAR(p2 / -i2, 1.0, 0.1);
}

TEST(FluidFilament, ForcesHaveOneEntryPerSegmentAndVanishOutsideTheGrid) {
  Options o;
  o.width = 30;
  o.height = 20;
  o.left.kind = SideKind::kInlet;
  o.left.velocity = Vec2(0.05, 0);
  o.right.kind = SideKind::kOutflow;
  Solver s(o);
  s.set_filaments({{{Vec2(10, 5), Vec2(10, 10), Vec2(12, 14), Vec2(13, 15)}, {}},
                   {{Vec2(-50, -50), Vec2(-40, -45)}, {}},
                   {{Vec2(25, 3), Vec2(25, 8)}, {}}});
  s.step(200);
  const auto& f = s.filament_forces();
  ASSERT_EQ(f.size(), 3u);
  EXPECT_EQ(f[0].size(), 3u);
  EXPECT_EQ(f[1].size(), 1u);
  EXPECT_EQ(f[2].size(), 1u);
  EXPECT_EQ(f[1][0].force.norm(), 0.0);
  EXPECT_GT(f[0][0].force.x(), 0.0);
  EXPECT_GT(f[2][0].force.x(), 0.0);
  s.set_filaments({});
  s.step();
  EXPECT_TRUE(s.filament_forces().empty());
}

// Two long crossing filaments (links cut by both belong to the first), an obstacle and an
// outflow sponge on a grid big enough for two lattice threads: one and two threads give the
// same flow and forces, so neither the owner of a link nor any boundary pass depends on how
// the rows are split.
TEST(FluidFilament, ThreadCountDoesNotChangeTheResult) {
  std::vector<std::vector<std::vector<SegmentForce>>> results;
  std::vector<FlowField> fields;
  std::vector<Vec2> obstacle;
  for (int threads : {1, 2}) {
    Options o;
    o.width = 200;
    o.height = 170;  // 34000 cells: two threads
    o.tau = 0.7;
    o.precision = Precision::kDouble;
    o.threads = threads;
    o.left.kind = SideKind::kInlet;
    o.left.velocity = Vec2(0.04, 0.01);
    o.right.kind = SideKind::kOutflow;
    o.sponge_width = 10;
    o.sponge_velocity = Vec2(0.04, 0);
    o.obstacle_polygons = {{Vec2(150, 80), Vec2(165, 84), Vec2(158, 100)}};
    Solver s(o);
    Filament a, b;
    for (int k = 0; k <= 160; ++k) {
      a.points.push_back(Vec2(40 + 0.5 * k, 10 + 0.6 * k + 3 * std::sin(0.2 * k)));
      b.points.push_back(Vec2(120 - 0.5 * k, 10 + 0.6 * k));
      a.velocities.push_back(Vec2(0.01, 0));
      b.velocities.push_back(Vec2(0, -0.01));
    }
    s.set_filaments({a, b});
    s.step(300);  // long enough for the inflow to reach the obstacle and the sponge
    results.push_back(s.filament_forces());
    fields.push_back(s.field());
    obstacle.push_back(s.obstacle_forces().at(0).force);
  }
  ASSERT_EQ(results[0].size(), results[1].size());
  double scale = 0;
  for (const auto& f : results[0])
    for (const SegmentForce& sf : f) scale = std::max(scale, sf.force.norm());
  EXPECT_GT(scale, 0.0);
  for (std::size_t k = 0; k < results[0].size(); ++k)
    for (std::size_t j = 0; j < results[0][k].size(); ++j)
      EXPECT_LT((results[0][k][j].force - results[1][k][j].force).norm(), 1e-12 * scale)
          << k << " " << j;
  EXPECT_LT((fields[0].ux - fields[1].ux).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((fields[0].density - fields[1].density).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((obstacle[0] - obstacle[1]).norm(), 1e-12 * obstacle[0].norm());
  EXPECT_GT(obstacle[0].x(), 0.0);
}

TEST(FluidFilament, BadFilamentsGiveClearErrorsAndKeepThePreviousOnes) {
  Options o;
  o.width = 24;
  o.height = 17;
  Solver s(o);
  s.set_filaments({{{Vec2(5, 5), Vec2(5, 12)}, {}}});
  const double nan = std::nan("");
  auto expect_error = [&](const std::vector<Filament>& f, const std::string& words) {
    try {
      s.set_filaments(f);
      ADD_FAILURE() << "no error for: " << words;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  expect_error({{{Vec2(1, 1), Vec2(nan, 3)}, {}}}, "point 1");
  expect_error({{{Vec2(1, 1), Vec2(1, 1)}, {}}}, "zero length");
  expect_error({{{Vec2(1, 1)}, {}}}, "must have >= 2");
  expect_error({{{Vec2(1, 1), Vec2(2, 3)}, {Vec2(0, 0)}}}, "velocities");
  expect_error({{{Vec2(1, 1), Vec2(2, 3)}, {Vec2(0, 0), Vec2(0.5, 0)}}}, "velocity 1");
  expect_error({{{Vec2(1, 1), Vec2(2, 3)}, {Vec2(0, 0), Vec2(0, nan)}}}, "velocity 1");
  expect_error({{{Vec2(1, 1), Vec2(1e9, 3)}, {}}}, "within");
  // The earlier filament is still there and works.
  s.step(3);
  ASSERT_EQ(s.filament_forces().size(), 1u);
  EXPECT_TRUE(s.velocity(3, 3).allFinite());
}

}  // namespace
}  // namespace hair25d::fluid
