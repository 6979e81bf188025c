// CGAL stays in this file: its headers are slow to compile and its types
// never leave the module.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <unordered_map>

#include "hair25d/core/error.h"
#include "hair25d/segment/mesh.h"

namespace hair25d::segment {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Exact predicates with approximate intersection points: crossing curves are
// split where they cross instead of being rejected.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Point = K::Point_2;

// A line drawn along the image's edge is traced in the last pixel row, a
// hair's breadth inside the border: two constraints that close make the
// mesher split both down to their distance (150000 vertices for one such
// line). Within half a pixel of the border a point is on it.
double snap_to_border(double v, double size) {
  constexpr double kSnap = 0.5;
  if (v < kSnap) return 0.0;
  if (v > size - kSnap) return size;
  return v;
}

}  // namespace

bool MeshOptions::is_valid(std::string* error) const {
  std::ostringstream o;
  if (!(max_edge_fraction > 0.0 && max_edge_fraction <= 1.0))
    o << "segment::MeshOptions::max_edge_fraction = " << max_edge_fraction << "; must be in (0, 1]";
  else if (!(min_edge_px >= 1.0 && min_edge_px <= 1e6))
    o << "segment::MeshOptions::min_edge_px = " << min_edge_px << "; must be in [1, 1e6]";
  else if (max_steiner_points < 0)
    o << "segment::MeshOptions::max_steiner_points = " << max_steiner_points << "; must be >= 0";
  else if (!(shape_bound >= 0.0 && shape_bound <= 0.125))
    o << "segment::MeshOptions::shape_bound = " << shape_bound
      << "; must be in [0, 0.125] (larger bounds may not terminate)";
  if (o.str().empty()) return true;
  if (error) *error = o.str();
  return false;
}

MeshResult build_mesh(const std::vector<Curve>& curves, int width, int height,
                      const MeshOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw Error(why);
  if (width <= 0 || height <= 0)
    throw Error("segment::build_mesh: image size " + std::to_string(width) + "x" +
                std::to_string(height) + "; both sides must be > 0");
  const double W = width, H = height;
  std::vector<Point> points{Point(0, 0), Point(W, 0), Point(W, H), Point(0, H)};
  std::vector<std::pair<std::size_t, std::size_t>> segments{{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  for (const Curve& c : curves) {
    const std::size_t first = points.size();
    for (const Vec2& p : c.points) {
      if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
        throw Error("segment::build_mesh: a curve holds a non-finite point");
      points.emplace_back(snap_to_border(p.x(), W), snap_to_border(p.y(), H));
    }
    const std::size_t n = c.points.size();
    for (std::size_t i = 0; i + 1 < n; ++i) segments.emplace_back(first + i, first + i + 1);
    if (c.closed && n >= 3) segments.emplace_back(first + n - 1, first);
  }
  // Zero-length constraints are not segments.
  std::erase_if(segments, [&](const auto& s) { return points[s.first] == points[s.second]; });

  MeshResult result;
  result.constraint_segments = static_cast<int>(segments.size()) - 4;
  Cdt cdt;
  try {
    cdt.insert_constraints(points.begin(), points.end(), segments.begin(), segments.end());
    const std::size_t before = cdt.number_of_vertices();
    if (options.refine) {
      const double edge =
          std::max(options.min_edge_px, options.max_edge_fraction * std::sqrt(W * H));
      // Step by step with a cap: nearly touching constraints would make the
      // mesher split them down to their tiny distance.
      CGAL::Delaunay_mesher_2<Cdt, Criteria> mesher(cdt, Criteria(options.shape_bound, edge));
      mesher.init();
      const std::size_t cap = before + static_cast<std::size_t>(options.max_steiner_points);
      while (!mesher.is_refinement_done() && cdt.number_of_vertices() < cap)
        mesher.step_by_step_refine_mesh();
      result.refinement_complete = mesher.is_refinement_done();
    }
    result.steiner_points = static_cast<int>(cdt.number_of_vertices() - before);
  } catch (const std::exception& e) {
    throw Error(std::string("segment::build_mesh: CGAL failed: ") + e.what());
  }

  std::unordered_map<Cdt::Vertex_handle, int> index;
  TriMesh2& mesh = result.mesh;
  mesh.V.resize(static_cast<Eigen::Index>(cdt.number_of_vertices()), 2);
  int nv = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    mesh.V(nv, 0) = v->point().x();
    mesh.V(nv, 1) = v->point().y();
    index[v] = nv++;
  }
  mesh.F.resize(static_cast<Eigen::Index>(cdt.number_of_faces()), 3);
  mesh.on_curve.resize(mesh.F.rows(), 3);
  auto on_border = [&](const Point& a, const Point& b) {
    return (a.x() == 0 && b.x() == 0) || (a.x() == W && b.x() == W) || (a.y() == 0 && b.y() == 0) ||
           (a.y() == H && b.y() == H);
  };
  int nf = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    for (int k = 0; k < 3; ++k) mesh.F(nf, k) = index.at(f->vertex(k));
    for (int k = 0; k < 3; ++k) {
      // Edge k runs from vertex k to k+1: CGAL names it by the opposite vertex.
      const int cgal_edge = (k + 2) % 3;
      const bool constrained = cdt.is_constrained(Cdt::Edge(f, cgal_edge));
      mesh.on_curve(nf, k) =
          constrained && !on_border(f->vertex(k)->point(), f->vertex((k + 1) % 3)->point());
    }
    ++nf;
  }
  mesh.F.conservativeResize(nf, 3);
  mesh.on_curve.conservativeResize(nf, 3);
  return result;
}

}  // namespace hair25d::segment
