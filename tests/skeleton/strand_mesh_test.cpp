#include "hair25d/skeleton/strand_mesh.h"

#include <gtest/gtest.h>

#include <cmath>

#include "hair25d/core/error.h"
#include "shapes.h"

namespace hair25d::skeleton {
namespace {

double angle_at(const Vec2& a, const Vec2& b, const Vec2& c) {
  return std::acos(std::clamp((b - a).normalized().dot((c - a).normalized()), -1.0, 1.0));
}

TEST(StrandMesh, QualityMeshOfATaperedStrand) {
  const Polyline outline = test::tapered_strand({30, 40}, 260, 24, 30);
  MeshOptions options;
  options.max_edge = 10;
  const MeshResult r = mesh_strand(outline, options);
  EXPECT_EQ(r.status, MeshStatus::kRefined);
  const TriMesh2& m = r.mesh;
  EXPECT_NO_THROW(m.validate("strand mesh"));
  double area = 0;
  int good_angles = 0, angles = 0;
  for (int t = 0; t < m.triangle_count(); ++t) {
    const Vec2 a = m.V.row(m.F(t, 0)), b = m.V.row(m.F(t, 1)), c = m.V.row(m.F(t, 2));
    const double twice = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    EXPECT_GT(twice, 0.0) << "counter-clockwise in (x, y)";
    area += 0.5 * twice;
    EXPECT_TRUE(point_in_polygon(outline, (a + b + c) / 3.0));
    for (const auto& [p, q, s] : {std::tuple{a, b, c}, std::tuple{b, c, a}, std::tuple{c, a, b}}) {
      ++angles;
      good_angles += angle_at(p, q, s) > 19.5 * M_PI / 180.0;
    }
  }
  EXPECT_NEAR(area, std::abs(signed_area(outline)), 0.01 * std::abs(signed_area(outline)));
  // Only the corners of the sharp tip may keep small angles.
  EXPECT_GT(static_cast<double>(good_angles) / angles, 0.97);
  // Interior vertices exist: not just the outline triangulated.
  int interior = 0;
  for (int v = 0; v < m.vertex_count(); ++v) {
    double nearest = 1e9;
    for (std::size_t k = 0; k < outline.size(); ++k) {
      const Vec2 a = outline[k], b = outline[(k + 1) % outline.size()];
      const Vec2 p = m.V.row(v);
      const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      nearest = std::min(nearest, (a + t * (b - a) - p).norm());
    }
    interior += nearest > 1.0;
  }
  EXPECT_GT(interior, 10);
  // Outline edges are flagged and lie on the outline.
  int flagged = 0;
  for (int t = 0; t < m.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k)
      if (m.on_curve(t, k)) {
        ++flagged;
        const Vec2 mid = 0.5 * (Vec2(m.V.row(m.F(t, k))) + Vec2(m.V.row(m.F(t, (k + 1) % 3))));
        double nearest = 1e9;
        for (std::size_t j = 0; j < outline.size(); ++j) {
          const Vec2 a = outline[j], b = outline[(j + 1) % outline.size()];
          const double s = std::clamp((mid - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
          nearest = std::min(nearest, (a + s * (b - a) - mid).norm());
        }
        EXPECT_LT(nearest, 0.5);
      }
  EXPECT_GT(flagged, 20);
}

TEST(StrandMesh, EdgeLengthBoundedAndOrientationFree) {
  Polyline outline = test::forked_strand({10, 100});
  std::reverse(outline.begin(), outline.end());
  MeshOptions options;
  options.max_edge = 8;
  const TriMesh2 m = mesh_strand(outline, options).mesh;
  double longest = 0;
  for (int t = 0; t < m.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, (m.V.row(m.F(t, k)) - m.V.row(m.F(t, (k + 1) % 3))).norm());
  EXPECT_LE(longest, 8.0 + 1e-6);
}

TEST(StrandMesh, VertexLimitStopsRefinement) {
  MeshOptions options;
  options.max_edge = 1.0;
  options.outline_spacing = 20.0;
  options.max_vertices = 200;
  const MeshResult r = mesh_strand(test::tapered_strand({0, 0}, 300, 30, 0), options);
  EXPECT_EQ(r.status, MeshStatus::kVertexLimit);
  EXPECT_LE(r.mesh.vertex_count(), 220);
}

TEST(StrandMesh, BadInputThrows) {
  EXPECT_THROW(mesh_strand({{0, 0}, {1, 0}}), Error);
  EXPECT_THROW(mesh_strand({{0, 0}, {1, 0}, {2, 0}}), Error);
  MeshOptions bad;
  bad.min_angle_deg = 35;
  std::string why;
  EXPECT_FALSE(bad.is_valid(&why));
  EXPECT_NE(why.find("min_angle_deg"), std::string::npos);
  EXPECT_THROW(mesh_strand(test::forked_strand({0, 0}), bad), Error);
  // A one-pixel square still meshes.
  EXPECT_GT(mesh_strand({{5, 5}, {6, 5}, {6, 6}, {5, 6}}).mesh.triangle_count(), 0);
}

}  // namespace
}  // namespace hair25d::skeleton
