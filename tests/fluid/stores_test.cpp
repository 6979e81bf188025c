// Non-temporal (streaming) stores in the bulk pass only change how the new populations reach
// memory: the flow must be the same bit for bit as with ordinary stores (forces to round-off),
// in float and double, with forcing and the sub-grid model, on rows that end in a partial block.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hair25d/fluid/solver.h"

namespace hair25d::fluid {
namespace {

struct Outcome {
  FlowField field;
  std::vector<std::vector<SegmentForce>> filaments;
  Vec2 obstacle;
  bool streaming = false;
};

Options scene(Precision precision, bool forced, double smagorinsky) {
  Options o;
  o.width = 203;   // 3 blocks of 64 floats + 11: a short block and a scalar tail
  o.height = 170;  // 34510 cells: two lattice threads
  o.tau = 0.62;
  o.precision = precision;
  o.smagorinsky = smagorinsky;
  o.threads = 2;
  o.left.kind = SideKind::kInlet;
  o.left.velocity = Vec2(0.05, 0.01);
  o.right.kind = SideKind::kOutflow;
  o.top.kind = SideKind::kWall;
  o.bottom.kind = SideKind::kWall;
  o.sponge_width = 8;
  o.sponge_velocity = Vec2(0.05, 0);
  if (forced) o.body_acceleration = Vec2(2e-6, -1e-6);
  o.obstacle_polygons = {{Vec2(140, 70), Vec2(156, 76), Vec2(147, 95)}};
  return o;
}

Outcome run(Options o, Stores stores) {
  o.stores = stores;
  Solver s(o);
  Filament f;
  for (int k = 0; k <= 60; ++k) {
    f.points.push_back(Vec2(50 + 0.4 * k, 30 + 1.5 * k + 3 * std::sin(0.3 * k)));
    f.velocities.push_back(Vec2(0.01 * std::cos(0.1 * k), 0));
  }
  Outcome r;
  for (int step = 0; step < 120; ++step) {
    for (Vec2& p : f.points) p.x() += 0.01;  // the filament moves and is re-cut every step
    s.set_filaments({f});
    s.step();
  }
  r.field = s.field();
  r.filaments = s.filament_forces();
  r.obstacle = s.obstacle_forces().at(0).force;
  r.streaming = s.streaming_stores();
  return r;
}

TEST(FluidStores, StreamingStoresGiveTheSameFlow) {
  struct Case {
    Precision precision;
    bool forced;
    double smagorinsky;
  };
  for (const Case c :
       {Case{Precision::kFloat, false, 0.0}, Case{Precision::kFloat, true, 0.15},
        Case{Precision::kDouble, true, 0.0}, Case{Precision::kDouble, false, 0.15}}) {
    SCOPED_TRACE(testing::Message() << (c.precision == Precision::kFloat ? "float" : "double")
                                    << " forced " << c.forced << " smagorinsky " << c.smagorinsky);
    const Options o = scene(c.precision, c.forced, c.smagorinsky);
    const Outcome cached = run(o, Stores::kCached);
    const Outcome streaming = run(o, Stores::kStreaming);
    EXPECT_FALSE(cached.streaming);
    EXPECT_TRUE(streaming.streaming);
    // The flow has developed: not a trivial field that any kernel would reproduce.
    EXPECT_GT(cached.field.ux.cwiseAbs().maxCoeff(), 0.03);
    EXPECT_TRUE((cached.field.ux.array() == streaming.field.ux.array()).all());
    EXPECT_TRUE((cached.field.uy.array() == streaming.field.uy.array()).all());
    EXPECT_TRUE((cached.field.density.array() == streaming.field.density.array()).all());
    // Forces are summed per thread and the threads claim row chunks in whatever order they
    // wake up, so a force that spans two chunks may be added in another order: round-off.
    EXPECT_LT((cached.obstacle - streaming.obstacle).norm(), 1e-12 * cached.obstacle.norm());
    ASSERT_EQ(cached.filaments.size(), 1u);
    ASSERT_EQ(streaming.filaments.size(), 1u);
    ASSERT_EQ(cached.filaments[0].size(), streaming.filaments[0].size());
    double largest = 0;
    for (const SegmentForce& f : cached.filaments[0]) largest = std::max(largest, f.force.norm());
    EXPECT_GT(largest, 0.0);
    for (std::size_t j = 0; j < cached.filaments[0].size(); ++j)
      EXPECT_LT((cached.filaments[0][j].force - streaming.filaments[0][j].force).norm(),
                1e-12 * largest)
          << j;
  }
}

TEST(FluidStores, AutomaticChoiceFollowsTheLatticeSize) {
  Options o;
  o.width = 512;
  o.height = 384;  // 18 planes of floats: 14 MiB, in the L3
  EXPECT_FALSE(Solver(o).streaming_stores());
  o.width = 1000;
  o.height = 600;  // 41 MiB
  EXPECT_TRUE(Solver(o).streaming_stores());
  o.precision = Precision::kDouble;
  o.width = 512;
  o.height = 384;  // 27 MiB in double
  EXPECT_FALSE(Solver(o).streaming_stores());
  o.stores = Stores::kStreaming;
  EXPECT_TRUE(Solver(o).streaming_stores());
  o.width = 1000;
  o.height = 600;
  o.stores = Stores::kCached;
  EXPECT_FALSE(Solver(o).streaming_stores());
}

}  // namespace
}  // namespace hair25d::fluid
