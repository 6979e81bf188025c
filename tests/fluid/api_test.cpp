// Bad input for every public entry point of the solver: a clear error naming the thing, the
// value and the rule; never a crash or a NaN field.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hair25d/core/error.h"
#include "hair25d/fluid/solver.h"

namespace hair25d::fluid {
namespace {

Options small() {
  Options o;
  o.width = 13;
  o.height = 7;
  return o;
}

void expect_invalid(const Options& o, const std::string& words) {
  std::string error;
  EXPECT_FALSE(o.is_valid(&error)) << words;
  EXPECT_NE(error.find(words), std::string::npos) << "message: " << error;
  try {
    Solver s(o);
    ADD_FAILURE() << "Solver accepted: " << words;
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), error);
  }
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

TEST(FluidApi, ValidOptionsPass) {
  std::string error = "stale";
  EXPECT_TRUE(small().is_valid(&error));
  EXPECT_TRUE(error.empty());
  EXPECT_TRUE(small().is_valid(nullptr));
}

TEST(FluidApi, OptionsNameOptionValueAndRule) {
  Options o = small();
  o.tau = 0.48;
  expect_invalid(o, "fluid::Options::tau = 0.48; must be > 0.5");
  o = small();
  o.tau = std::nan("");
  expect_invalid(o, "fluid::Options::tau = nan");
  o = small();
  o.collision = Collision::kBgk;
  o.tau = 0.501;
  expect_invalid(o, "fluid::Options::tau = 0.501; must be >= 0.505 with BGK");
  o = small();
  o.width = -5;
  expect_invalid(o, "fluid::Options::width = -5");
  o = small();
  o.height = 0;
  expect_invalid(o, "fluid::Options::height = 0");
  o = small();
  o.width = 100000;
  expect_invalid(o, "fluid::Options::width = 100000");
  o = small();
  o.threads = 0;
  expect_invalid(o, "fluid::Options::threads = 0");
  o = small();
  o.trt_magic = -1;
  expect_invalid(o, "fluid::Options::trt_magic = -1");
  o = small();
  o.left.kind = SideKind::kInlet;
  o.left.velocity = Vec2(0.5, 0);
  o.right.kind = SideKind::kOutflow;
  expect_invalid(o, "fluid::Options::left.velocity = (0.5, 0)");
  o = small();
  o.left.kind = SideKind::kWall;  // right stays periodic
  expect_invalid(o, "left/right");
  o = small();
  o.top.kind = SideKind::kWall;
  expect_invalid(o, "top/bottom");
  o = small();
  o.left.kind = SideKind::kInlet;
  o.right.kind = SideKind::kOutflow;
  o.left.velocity = Vec2(0.05, 0);
  o.left.profile = {1.0, 2.0};
  expect_invalid(o, "fluid::Options::left.profile has 2 values; must have 7");
  o.left.profile.assign(7, 1.0);
  o.left.profile[3] = std::nan("");
  expect_invalid(o, "fluid::Options::left.profile[3] = nan");
  o = small();
  o.top.velocity = Vec2(0.1, 0);  // periodic side
  expect_invalid(o, "periodic side has no velocity");
  o = small();
  o.body_acceleration = Vec2(1.0, 0);
  expect_invalid(o, "fluid::Options::body_acceleration = (1, 0)");
  o = small();
  o.obstacle_labels = Eigen::MatrixXi::Zero(13, 7);  // transposed
  expect_invalid(
      o, "fluid::Options::obstacle_labels is 13 x 7; must be empty or height x width = 7 x 13");
  o = small();
  o.obstacle_labels = Eigen::MatrixXi::Zero(7, 13);
  o.obstacle_labels(2, 2) = -3;
  expect_invalid(o, "fluid::Options::obstacle_labels has -3");
  o = small();
  o.sponge_width = 4;  // half of the 7-cell height is 3
  expect_invalid(o, "fluid::Options::sponge_width = 4; must be in [0, 3]");
  o = small();
  o.sponge_velocity = Vec2(0, 0.3);
  expect_invalid(o, "fluid::Options::sponge_velocity = (0, 0.3)");
  o = small();
  o.smagorinsky = -0.1;
  expect_invalid(o, "fluid::Options::smagorinsky = -0.1");
  o = small();
  o.obstacle_polygons = {{Vec2(1, 1), Vec2(2, 2)}};
  expect_invalid(o, "fluid::Options::obstacle_polygons[0] has 2 points");
  o.obstacle_polygons = {{Vec2(1, 1), Vec2(2, 2), Vec2(INFINITY, 1)}};
  expect_invalid(o, "fluid::Options::obstacle_polygons[0][2]");
}

TEST(FluidApi, SolverCallsRejectBadArguments) {
  Options o = small();
  o.left.kind = SideKind::kInlet;
  o.left.velocity = Vec2(0.05, 0);
  o.right.kind = SideKind::kOutflow;
  Solver s(o);
  expect_error([&] { s.step(-1); }, "steps = -1");
  expect_error([&] { s.set_inlet_velocity(SideName::kTop, Vec2(0.1, 0)); }, "not an inlet");
  expect_error([&] { s.set_inlet_velocities(SideName::kLeft, {Vec2(0.1, 0)}); },
               "1 velocities; must be 7");
  expect_error([&] { s.set_inlet_velocities(SideName::kLeft, std::vector<Vec2>(7, Vec2(1, 0))); },
               "velocity 0 = (1, 0)");
  expect_error([&] { s.set_body_acceleration(Vec2(std::nan(""), 0)); }, "body_acceleration");
  expect_error([&] { s.set_sponge_velocity(Vec2(1, 0)); }, "sponge_velocity = (1, 0)");
  expect_error([&] { s.velocity(13, 0); }, "cell (13, 0) is outside the 13 x 7 grid");
  expect_error([&] { s.density(0, -1); }, "cell (0, -1)");
  const Eigen::MatrixXd ones = Eigen::MatrixXd::Ones(7, 13), zero = Eigen::MatrixXd::Zero(7, 13);
  expect_error([&] { s.initialize(Eigen::MatrixXd::Ones(13, 7), zero, zero); },
               "density is 13 x 7; must be height x width = 7 x 13");
  Eigen::MatrixXd bad = zero;
  bad(3, 3) = std::nan("");
  expect_error([&] { s.initialize(ones, bad, zero); }, "ux has a NaN");
  expect_error([&] { s.initialize(-ones, zero, zero); }, "density ranges over");
  expect_error([&] { s.initialize(ones, zero, 0.5 * ones); }, "max |u| = 0.5");
  SteadyOptions so;
  so.check_every = 0;
  expect_error([&] { run_to_steady(s, so); }, "fluid::SteadyOptions::check_every = 0");
  // After all that the solver still works and its field is finite.
  s.set_inlet_velocity(SideName::kLeft, Vec2(0.03, 0.01));
  s.step(50);
  const FlowField f = s.field();
  EXPECT_TRUE(f.ux.allFinite() && f.uy.allFinite() && f.density.allFinite());
  EXPECT_GT(f.ux.mean(), 0.01);
  EXPECT_EQ(s.steps_done(), 50);
}

// A flow far beyond what the lattice resolves blows up; the solver says so instead of
// handing out NaN, and refuses to go on.
TEST(FluidApi, DivergenceIsReportedNotReturnedAsNaN) {
  Options o;
  o.width = 48;
  o.height = 40;
  o.collision = Collision::kBgk;
  o.tau = 0.505;
  o.left.kind = o.right.kind = o.bottom.kind = o.top.kind = SideKind::kWall;
  o.top.velocity = Vec2(0.2, 0);
  Solver s(o);
  std::string message;
  try {
    s.step(20000);
  } catch (const Error& e) {
    message = e.what();
  }
  ASSERT_FALSE(message.empty()) << "expected this flow to diverge";
  EXPECT_NE(message.find("diverged at step"), std::string::npos) << message;
  EXPECT_NE(message.find("tau"), std::string::npos) << message;
  expect_error([&] { s.step(); }, "diverged earlier");
}

TEST(FluidApi, TinyAndNonSquareGridsRun) {
  for (auto [w, h] : {std::pair{2, 3}, std::pair{3, 2}, std::pair{17, 5}, std::pair{5, 17}}) {
    Options o;
    o.width = w;
    o.height = h;
    o.left.kind = o.right.kind = SideKind::kWall;
    o.top.kind = SideKind::kInlet;
    o.top.velocity = Vec2(0.0, 0.02);
    o.bottom.kind = SideKind::kOutflow;
    Solver s(o);
    s.step(100);
    const FlowField f = s.field();
    EXPECT_EQ(f.ux.rows(), h);
    EXPECT_EQ(f.ux.cols(), w);
    EXPECT_TRUE(f.uy.allFinite());
    EXPECT_GT(f.uy.mean(), 0.0);
  }
}

TEST(FluidApi, ObstacleForcesListEveryLabelOnce) {
  Options o;
  o.width = 40;
  o.height = 21;
  o.left.kind = SideKind::kInlet;
  o.left.velocity = Vec2(0.05, 0);
  o.right.kind = SideKind::kOutflow;
  o.obstacle_labels = Eigen::MatrixXi::Zero(21, 40);
  o.obstacle_labels.block(8, 10, 4, 3).setConstant(4);  // labels need not be consecutive
  o.obstacle_polygons = {{Vec2(25, 5), Vec2(30, 5), Vec2(30, 9), Vec2(25, 9)}};
  Solver s(o);
  s.step(300);
  const auto forces = s.obstacle_forces();
  ASSERT_EQ(forces.size(), 2u);
  EXPECT_EQ(forces[0].label, 4);
  EXPECT_EQ(forces[1].label, 5);
  EXPECT_GT(forces[0].force.x(), 0.0);
  EXPECT_GT(forces[1].force.x(), 0.0);
  EXPECT_EQ(s.field().labels(10, 11), 4);
  EXPECT_EQ(s.field().labels(7, 27), 5);
  EXPECT_EQ(s.velocity(11, 10), Vec2::Zero());
}

}  // namespace
}  // namespace hair25d::fluid
