#include "hair25d/skeleton/strand_mesh.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <map>
#include <string>

#include "hair25d/core/error.h"
#include "polygon_sampling.h"

namespace hair25d::skeleton {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Mesher = CGAL::Delaunay_mesher_2<Cdt, Criteria>;
using Point = K::Point_2;

}  // namespace

MeshResult mesh_strand(const Polyline& outline, const MeshOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw Error(why);
  const Polyline clean = detail::clean_polygon(outline, "skeleton::mesh_strand", nullptr);
  if (std::abs(signed_area(clean)) < 1e-6) {
    throw Error("skeleton::mesh_strand: outline encloses zero area; a mesh needs a 2D shape");
  }
  const double spacing =
      options.outline_spacing > 0 ? options.outline_spacing : 0.5 * options.max_edge;
  const Polyline samples = detail::resample_closed(clean, spacing, nullptr);

  MeshResult result;
  try {
    Cdt cdt;
    std::vector<Cdt::Vertex_handle> handles;
    for (const Vec2& p : samples) handles.push_back(cdt.insert(Point(p.x(), p.y())));
    for (std::size_t i = 0; i < handles.size(); ++i) {
      Cdt::Vertex_handle a = handles[i], b = handles[(i + 1) % handles.size()];
      if (a != b) cdt.insert_constraint(a, b);
    }
    // The seed is a point inside the outline: the domain is the component of
    // the plane (cut by the constraints) that holds it. The centroid of the
    // largest initial triangle inside the polygon is safely interior.
    std::vector<Point> seeds;
    double best = 0.0;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      const Point c =
          CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
      const double a = std::abs(cdt.triangle(f).area());
      if (a > best && point_in_polygon(samples, Vec2(c.x(), c.y()))) {
        best = a;
        seeds = {c};
      }
    }
    if (seeds.empty()) {
      throw Error("skeleton::mesh_strand: no triangle lies inside the outline");
    }
    // CGAL's shape bound is sin² of the smallest angle wanted (0.125 ≈ 20.7°).
    const double shape = std::pow(std::sin(options.min_angle_deg * M_PI / 180.0), 2);
    Mesher mesher(cdt, Criteria(shape, options.max_edge));
    mesher.set_seeds(seeds.begin(), seeds.end(), true);
    mesher.init();
    // Refinement one point at a time so that the vertex limit is honoured.
    while (!mesher.is_refinement_done()) {
      if (static_cast<int>(cdt.number_of_vertices()) >= options.max_vertices) {
        result.status = MeshStatus::kVertexLimit;
        break;
      }
      mesher.step_by_step_refine_mesh();
    }

    std::map<Cdt::Vertex_handle, int> index;
    std::vector<std::array<int, 3>> faces;
    std::vector<std::array<bool, 3>> on_curve;
    std::vector<Vec2> vertices;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      if (!f->is_in_domain()) continue;
      std::array<int, 3> tri{};
      for (int k = 0; k < 3; ++k) {
        auto [it, inserted] = index.emplace(f->vertex(k), static_cast<int>(vertices.size()));
        if (inserted) vertices.emplace_back(f->vertex(k)->point().x(), f->vertex(k)->point().y());
        tri[k] = it->second;
      }
      // CGAL faces are counter-clockwise in (x, y); edge k of ours runs from
      // vertex k to k+1, which is opposite CGAL's vertex (k+2)%3.
      std::array<bool, 3> curve{};
      for (int k = 0; k < 3; ++k) curve[k] = cdt.is_constrained(Cdt::Edge(f, (k + 2) % 3));
      faces.push_back(tri);
      on_curve.push_back(curve);
    }
    result.mesh.V.resize(static_cast<Eigen::Index>(vertices.size()), 2);
    for (std::size_t i = 0; i < vertices.size(); ++i) result.mesh.V.row(i) = vertices[i];
    result.mesh.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
    result.mesh.on_curve.resize(static_cast<Eigen::Index>(faces.size()), 3);
    for (std::size_t t = 0; t < faces.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        result.mesh.F(t, k) = faces[t][k];
        result.mesh.on_curve(t, k) = on_curve[t][k];
      }
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(std::string("skeleton::mesh_strand: CGAL mesher failed: ") + e.what());
  }
  if (result.mesh.triangle_count() == 0) {
    throw Error("skeleton::mesh_strand: the outline gave no triangles inside it");
  }
  return result;
}

}  // namespace hair25d::skeleton
