// Mesh time and coverage for the folded strand outlines of tests/data/skeleton
// (one of a 1024² drawing, one of case5 scaled ×2 that used to need exact
// constructions). Counters: vertices, IoU of the mesh with the filled outline
// on a quarter-pixel raster, the largest distance (pixels) from the mesh
// boundary to the outline and from the filled outline's boundary to the mesh
// boundary, and the share of triangles with an angle under 19.5°.
#include <benchmark/benchmark.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "../../tests/skeleton/outline_file.h"
#include "hair25d/skeleton/strand_mesh.h"

namespace {

using namespace hair25d;

using hair25d::testing::read_outline;

double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * d)).norm();
}

// Largest distance from points every ~0.5 px along `from` segments to the
// nearest of `to` segments.
double max_distance(const std::vector<std::pair<Vec2, Vec2>>& from,
                    const std::vector<std::pair<Vec2, Vec2>>& to) {
  double worst = 0;
  for (const auto& [a, b] : from) {
    const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / 0.5)));
    for (int k = 0; k <= steps; ++k) {
      const Vec2 p = a + (b - a) * (static_cast<double>(k) / steps);
      double best = std::numeric_limits<double>::infinity();
      for (const auto& [c, d] : to) best = std::min(best, segment_distance(p, c, d));
      worst = std::max(worst, best);
    }
  }
  return worst;
}

struct Quality {
  double iou = 0, mesh_to_outline = 0, outline_to_mesh = 0, small_angles = 0;
};

Quality quality(const Polyline& outline, const TriMesh2& mesh) {
  constexpr double kScale = 4.0;
  double x0 = outline[0].x(), y0 = outline[0].y(), x1 = x0, y1 = y0;
  for (const Vec2& p : outline) {
    x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y());
    x1 = std::max(x1, p.x()), y1 = std::max(y1, p.y());
  }
  const int margin = 8;
  const cv::Size size(static_cast<int>((x1 - x0) * kScale) + 2 * margin,
                      static_cast<int>((y1 - y0) * kScale) + 2 * margin);
  auto cell = [&](const Vec2& p) {
    return cv::Point(static_cast<int>(std::lround((p.x() - x0) * kScale)) + margin,
                     static_cast<int>(std::lround((p.y() - y0) * kScale)) + margin);
  };
  cv::Mat strand = cv::Mat::zeros(size, CV_8U), meshed = cv::Mat::zeros(size, CV_8U);
  std::vector<cv::Point> ring;
  for (const Vec2& p : outline) ring.push_back(cell(p));
  cv::fillPoly(strand, std::vector<std::vector<cv::Point>>{ring}, cv::Scalar(255));
  std::vector<std::pair<Vec2, Vec2>> boundary, outline_edges;
  int small = 0;
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    std::vector<cv::Point> tri;
    for (int k = 0; k < 3; ++k) {
      tri.push_back(cell(mesh.V.row(mesh.F(t, k))));
      if (mesh.on_curve(t, k))
        boundary.emplace_back(mesh.V.row(mesh.F(t, k)), mesh.V.row(mesh.F(t, (k + 1) % 3)));
    }
    cv::fillConvexPoly(meshed, tri, cv::Scalar(255));
    for (int k = 0; k < 3; ++k) {
      const Vec2 a = mesh.V.row(mesh.F(t, k)), b = mesh.V.row(mesh.F(t, (k + 1) % 3)),
                 c = mesh.V.row(mesh.F(t, (k + 2) % 3));
      const double cosine = (b - a).normalized().dot((c - a).normalized());
      if (cosine > std::cos(19.5 * M_PI / 180.0)) {
        ++small;
        break;
      }
    }
  }
  for (std::size_t i = 0; i < outline.size(); ++i)
    outline_edges.emplace_back(outline[i], outline[(i + 1) % outline.size()]);
  // The boundary of the filled strand: a folded outline runs partly inside
  // its own shape, where no mesh boundary should follow it.
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(strand.clone(), contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
  std::vector<std::pair<Vec2, Vec2>> strand_edges;
  auto pixel = [&](const cv::Point& c) {
    return Vec2((c.x - margin) / kScale + x0, (c.y - margin) / kScale + y0);
  };
  for (const auto& contour : contours)
    for (std::size_t i = 0; i < contour.size(); ++i)
      strand_edges.emplace_back(pixel(contour[i]), pixel(contour[(i + 1) % contour.size()]));
  cv::Mat both, either;
  cv::bitwise_and(strand, meshed, both);
  cv::bitwise_or(strand, meshed, either);
  Quality q;
  q.iou = static_cast<double>(cv::countNonZero(both)) / std::max(1, cv::countNonZero(either));
  q.mesh_to_outline = max_distance(boundary, outline_edges);
  q.small_angles = static_cast<double>(small) / std::max(1, mesh.triangle_count());
  q.outline_to_mesh = max_distance(strand_edges, boundary);
  return q;
}

void BM_MeshFoldedOutline(benchmark::State& state, const char* file) {
  const Polyline outline = read_outline(file);
  if (outline.size() < 3) {
    state.SkipWithError("outline file missing");
    return;
  }
  skeleton::MeshResult r;
  for (auto _ : state) {
    r = skeleton::mesh_strand(outline);
    benchmark::DoNotOptimize(r.mesh.V.data());
  }
  const Quality q = quality(outline, r.mesh);
  state.counters["vertices"] = static_cast<double>(r.mesh.vertex_count());
  state.counters["iou"] = q.iou;
  state.counters["mesh_to_outline_px"] = q.mesh_to_outline;
  state.counters["outline_to_mesh_px"] = q.outline_to_mesh;
  state.counters["small_angle_share"] = q.small_angles;
}

BENCHMARK_CAPTURE(BM_MeshFoldedOutline, folded, "folded_outline.txt")
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);
BENCHMARK_CAPTURE(BM_MeshFoldedOutline, large_folded, "large_folded_outline.txt")
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

}  // namespace
