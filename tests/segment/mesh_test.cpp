// The constrained Delaunay mesh (paper §3): it covers the image, keeps every
// curve segment as mesh edges flagged on_curve, and handles crossing curves.
#include <gtest/gtest.h>

#include <random>

#include "hair25d/core/error.h"
#include "hair25d/segment/mesh.h"

namespace hair25d::segment {
namespace {

double signed_area2(const TriMesh2& m, int t) {
  const Vec2 a = m.V.row(m.F(t, 0)), b = m.V.row(m.F(t, 1)), c = m.V.row(m.F(t, 2));
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

double total_area(const TriMesh2& m) {
  double s = 0.0;
  for (int t = 0; t < m.triangle_count(); ++t) s += 0.5 * signed_area2(m, t);
  return s;
}

bool on_segment(const Vec2& p, const Vec2& a, const Vec2& b, double tol) {
  const Vec2 d = b - a;
  const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * d)).norm() < tol;
}

// The summed length of curve-flagged mesh edges lying on segment a-b.
double covered_length(const TriMesh2& m, const Vec2& a, const Vec2& b) {
  double s = 0.0;
  for (int t = 0; t < m.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) {
      if (!m.on_curve(t, k)) continue;
      const Vec2 p = m.V.row(m.F(t, k)), q = m.V.row(m.F(t, (k + 1) % 3));
      if (on_segment(p, a, b, 1e-6) && on_segment(q, a, b, 1e-6)) s += (q - p).norm();
    }
  }
  return s / 2.0;  // interior edges are seen from both triangles
}

Curve polyline_curve(Polyline pts) {
  Curve c;
  c.points = std::move(pts);
  return c;
}

TEST(BuildMesh, EmptyDrawingCoversTheRectangleCounterClockwise) {
  const MeshResult r = build_mesh({}, 90, 40);
  r.mesh.validate("test");
  EXPECT_NEAR(total_area(r.mesh), 90.0 * 40.0, 1e-6);
  for (int t = 0; t < r.mesh.triangle_count(); ++t) EXPECT_GT(signed_area2(r.mesh, t), 0.0);
  EXPECT_FALSE(r.mesh.on_curve.any());    // the border is a constraint but not a drawn curve
  EXPECT_GT(r.mesh.triangle_count(), 2);  // refined so that regions have inner triangles
}

TEST(BuildMesh, EveryCurveSegmentIsMadeOfCurveEdges) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> ux(2.0, 148.0), uy(2.0, 98.0);
  std::vector<Curve> curves;
  for (int i = 0; i < 6; ++i) {
    Polyline p;
    for (int k = 0; k < 4; ++k) p.emplace_back(ux(rng), uy(rng));  // random: they cross
    curves.push_back(polyline_curve(p));
  }
  const MeshResult r = build_mesh(curves, 150, 100);
  r.mesh.validate("test");
  EXPECT_NEAR(total_area(r.mesh), 150.0 * 100.0, 1e-3);
  for (int t = 0; t < r.mesh.triangle_count(); ++t) EXPECT_GT(signed_area2(r.mesh, t), 0.0);
  for (const Curve& c : curves) {
    for (std::size_t i = 0; i + 1 < c.points.size(); ++i) {
      const Vec2 a = c.points[i], b = c.points[i + 1];
      // Crossings are computed inexactly: allow a hair of slack.
      EXPECT_NEAR(covered_length(r.mesh, a, b), (b - a).norm(), 1e-3 * (b - a).norm() + 1e-6);
    }
  }
}

TEST(BuildMesh, ClosedCurveAndCurvesLeavingTheImage) {
  Curve loop = polyline_curve({{20, 20}, {60, 20}, {60, 50}, {20, 50}});
  loop.closed = true;
  const Curve out = polyline_curve({{-30, 10}, {100, 10}});  // clipped to the rectangle
  const MeshResult r = build_mesh({loop, out}, 80, 70);
  EXPECT_NEAR(covered_length(r.mesh, {20, 50}, {20, 20}), 30.0, 1e-9);  // the closing segment
  EXPECT_NEAR(covered_length(r.mesh, {0, 10}, {80, 10}), 80.0, 1e-9);
  EXPECT_NEAR(total_area(r.mesh), 80.0 * 70.0, 1e-6);
}

TEST(BuildMesh, WithoutRefinementOnlyInputPointsAreVertices) {
  MeshOptions o;
  o.refine = false;
  const MeshResult r = build_mesh({polyline_curve({{10, 10}, {30, 25}})}, 40, 30, o);
  EXPECT_EQ(r.mesh.vertex_count(), 6);
  EXPECT_EQ(r.steiner_points, 0);
  EXPECT_EQ(r.constraint_segments, 1);
}

TEST(BuildMesh, RefinementStopsAtTheCapOnNearlyTouchingCurves) {
  // Two constraints 1e-3 px apart: a full refinement would split them finely.
  const std::vector<Curve> curves{polyline_curve({{10, 10}, {90, 10}}),
                                  polyline_curve({{10, 10.001}, {90, 10.001}})};
  MeshOptions o;
  o.max_steiner_points = 500;
  const MeshResult r = build_mesh(curves, 100, 40, o);
  EXPECT_LE(r.steiner_points, 500);
  r.mesh.validate("capped");
  EXPECT_NEAR(total_area(r.mesh), 4000.0, 1e-6);
  const MeshResult full = build_mesh({}, 100, 40);
  EXPECT_TRUE(full.refinement_complete);
}

TEST(BuildMesh, LinesAlongTheImageEdgeLieOnTheBorder) {
  // A line drawn along the bottom and left edges is traced in the last pixel
  // row and column, 2e-4 px inside: as constraints beside the border it made
  // the mesher split both down to that distance (the cap, 200000 points).
  const std::vector<Curve> curves{polyline_curve({{20, 50}, {40, 69.9998}, {110, 69.9998}}),
                                  polyline_curve({{0.0003, 10}, {0.0003, 60}, {30, 30}})};
  const MeshResult r = build_mesh(curves, 130, 70);
  EXPECT_TRUE(r.refinement_complete);
  EXPECT_LT(r.mesh.triangle_count(), 2000);
  EXPECT_NEAR(total_area(r.mesh), 130.0 * 70.0, 1e-6);
  for (int v = 0; v < r.mesh.vertex_count(); ++v) {
    const double x = r.mesh.V(v, 0), y = r.mesh.V(v, 1);
    EXPECT_TRUE(x == 0.0 || x >= 0.5) << x;
    EXPECT_TRUE(y == 70.0 || y <= 69.5) << y;
  }
  // Points half a pixel or more from the border stay where they are.
  const MeshResult kept = build_mesh({polyline_curve({{0.5, 10}, {0.5, 60}})}, 130, 70);
  EXPECT_NEAR(covered_length(kept.mesh, {0.5, 10}, {0.5, 60}), 50.0, 1e-6);
}

TEST(BuildMesh, BadInputIsRejected) {
  EXPECT_THROW(build_mesh({}, 0, 10), Error);
  EXPECT_THROW(build_mesh({}, 10, -1), Error);
  EXPECT_THROW(build_mesh({polyline_curve({{1, 1}, {std::nan(""), 2}})}, 10, 10), Error);
  MeshOptions o;
  o.shape_bound = 0.5;
  std::string why;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find("shape_bound"), std::string::npos);
  EXPECT_THROW(build_mesh({}, 10, 10, o), Error);
}

TEST(BuildMesh, TinyImages) {
  for (const auto& [w, h] : {std::pair{1, 1}, std::pair{3, 2}}) {
    const MeshResult r = build_mesh({}, w, h);
    EXPECT_NEAR(total_area(r.mesh), double(w) * h, 1e-9);
    const LabelMap tri = rasterize_triangles(r.mesh, w, h);
    for (std::size_t i = 0; i < tri.size(); ++i) EXPECT_GE(tri.data()[i], 0);
  }
}

TEST(RasterizeTriangles, EveryPixelCentreFindsItsTriangle) {
  const MeshResult r = build_mesh({polyline_curve({{5, 5}, {70, 40}})}, 77, 45);
  const LabelMap tri = rasterize_triangles(r.mesh, 77, 45);
  for (int y = 0; y < 45; ++y) {
    for (int x = 0; x < 77; ++x) {
      const int t = tri.at(x, y);
      ASSERT_GE(t, 0);
      // The pixel centre lies in (or on the edge of) its triangle.
      const Vec2 p(x + 0.5, y + 0.5);
      const Vec2 a = r.mesh.V.row(r.mesh.F(t, 0)), b = r.mesh.V.row(r.mesh.F(t, 1)),
                 c = r.mesh.V.row(r.mesh.F(t, 2));
      auto cross = [](Vec2 u, Vec2 v) { return u.x() * v.y() - u.y() * v.x(); };
      EXPECT_GE(cross(b - a, p - a), -1e-9);
      EXPECT_GE(cross(c - b, p - b), -1e-9);
      EXPECT_GE(cross(a - c, p - c), -1e-9);
    }
  }
  std::vector<int> values(r.mesh.triangle_count(), 7);
  const LabelMap v = rasterize_triangle_values(r.mesh, values, 77, 45);
  EXPECT_EQ(v.labels(), std::vector<int>{7});
  values.pop_back();
  EXPECT_THROW(rasterize_triangle_values(r.mesh, values, 77, 45), Error);
  EXPECT_THROW(rasterize_triangles(r.mesh, -1, 45), Error);
}

}  // namespace
}  // namespace hair25d::segment
