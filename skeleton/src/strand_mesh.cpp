#include "hair25d/skeleton/strand_mesh.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "hair25d/core/error.h"
#include "inside_test.h"
#include "polygon_sampling.h"
#include "simple_outline.h"
#include "simplify_outline.h"

namespace hair25d::skeleton {
namespace {

// An outline that crosses or touches itself (a completed strand can fold over
// itself where its grown part meets its visible part) makes the triangulation
// insert constraint intersections. With inexact constructions those points
// are rounded, the triangulation no longer agrees with its own geometry and
// the mesher fails an internal check (a crash in a release build); making the
// crossings explicit vertices is not enough, the refinement's own points
// between nearly touching edges fail the same way. Such an outline is first
// replaced by the boundaries of its filled shape (simple_outline.h). Every
// outline is then simplified without changing its topology
// (simplify_outline.h), so the polygon meshed is simple; should rounding
// still make it cross itself, it is meshed with exact constructions, correct
// but slow.
// Vertex limit under exact constructions (see mesh_strand).
constexpr int kExactMaxVertices = 3000;
// Pixels a simplified outline may leave out: the completed outlines are
// traced on the pixel grid, so half a pixel keeps the mesh on the strand's
// pixels.
constexpr double kSimplifyTolerance = 0.5;
// The resampled outline may cut it by up to a pixel (its dropped vertices
// are pixel steps); beyond that it is simplified instead.
constexpr double kResampleTolerance = 1.0;
// A retraced boundary (simple_outline.h) already runs through the centres of
// half-pixel cells, up to half a pixel inside the outline: it gets a quarter.
constexpr double kRetracedTolerance = 0.25;

struct InexactKernel {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Itag = CGAL::Exact_predicates_tag;
};
struct ExactKernel {
  using K = CGAL::Exact_predicates_exact_constructions_kernel;
  using Itag = CGAL::Exact_intersections_tag;
};

// Meshes the inside of disjoint closed loops (one, unless a pinched outline
// was split): inside means inside an odd number of them.
template <typename Kernel>
MeshResult mesh_samples(const std::vector<Polyline>& loops, const MeshOptions& options) {
  using K = typename Kernel::K;
  using Vb = CGAL::Delaunay_mesh_vertex_base_2<K>;
  using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, typename Kernel::Itag>;
  using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
  using Mesher = CGAL::Delaunay_mesher_2<Cdt, Criteria>;
  using Point = typename K::Point_2;

  MeshResult result;
  try {
    Cdt cdt;
    for (const Polyline& samples : loops) {
      std::vector<typename Cdt::Vertex_handle> handles;
      for (const Vec2& p : samples) handles.push_back(cdt.insert(Point(p.x(), p.y())));
      for (std::size_t i = 0; i < handles.size(); ++i) {
        typename Cdt::Vertex_handle a = handles[i], b = handles[(i + 1) % handles.size()];
        if (a != b) cdt.insert_constraint(a, b);
      }
    }
    // Binned edges: a large strand's outline has ~1000 samples and as many
    // initial triangles (same answers as point_in_polygon, inside_test.h).
    std::vector<detail::InsideTest> tests;
    for (const Polyline& loop : loops) tests.emplace_back(loop);
    auto inside = [&tests](const Vec2& p) {
      bool odd = false;
      for (const detail::InsideTest& t : tests) odd ^= t.contains(p);
      return odd;
    };
    // Seeds are points inside the outline: the domain is the components of
    // the plane (cut by the constraints) that hold them. The centroid of every
    // initial triangle inside the polygon is one: a simple outline has one
    // component, one pinched or folded by completion has several.
    std::vector<Point> seeds;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      const Point c =
          CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
      if (inside(Vec2(CGAL::to_double(c.x()), CGAL::to_double(c.y())))) seeds.push_back(c);
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

    std::map<typename Cdt::Vertex_handle, int> index;
    std::vector<std::array<int, 3>> faces;
    std::vector<std::array<bool, 3>> on_curve;
    std::vector<Vec2> vertices;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      if (!f->is_in_domain()) continue;
      std::array<int, 3> tri{};
      for (int k = 0; k < 3; ++k) {
        auto [it, inserted] = index.emplace(f->vertex(k), static_cast<int>(vertices.size()));
        if (inserted) {
          const Point& q = f->vertex(k)->point();
          vertices.emplace_back(CGAL::to_double(q.x()), CGAL::to_double(q.y()));
        }
        tri[k] = it->second;
      }
      // CGAL faces are counter-clockwise in (x, y); edge k of ours runs from
      // vertex k to k+1, which is opposite CGAL's vertex (k+2)%3.
      std::array<bool, 3> curve{};
      for (int k = 0; k < 3; ++k) curve[k] = cdt.is_constrained(typename Cdt::Edge(f, (k + 2) % 3));
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
  return result;
}

bool is_simple(const Polyline& samples) {
  std::vector<InexactKernel::K::Point_2> points;
  points.reserve(samples.size());
  for (const Vec2& p : samples) points.emplace_back(p.x(), p.y());
  return CGAL::is_simple_2(points.begin(), points.end(), InexactKernel::K());
}

// The farthest a vertex of `polygon` lies from the resampled outline
// `samples` (resample_closed's output, `source`: the input vertex nearest
// each sample, non-decreasing), measured against the chords next to it.
double deviation(const Polyline& polygon, const Polyline& samples, const std::vector<int>& source) {
  const int n = static_cast<int>(polygon.size()), m = static_cast<int>(samples.size());
  auto chord_distance = [&](const Vec2& p, int k) {
    const Vec2 a = samples[((k % m) + m) % m], b = samples[(((k + 1) % m) + m) % m];
    const double len2 = (b - a).squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(b - a) / len2, 0.0, 1.0) : 0.0;
    return (a + t * (b - a) - p).norm();
  };
  double worst = 0.0;
  int k = 0;
  for (int i = 0; i < n; ++i) {
    while (k < m && source[k] < i) ++k;
    double nearest = std::numeric_limits<double>::infinity();
    for (int j = k - 2; j <= k + 1; ++j) nearest = std::min(nearest, chord_distance(polygon[i], j));
    worst = std::max(worst, nearest);
  }
  return worst;
}

// Points every <= `spacing` px on each edge of a closed polygon, its own
// vertices kept: the same boundary, sampled for the mesher.
Polyline densify(const Polyline& loop, double spacing) {
  Polyline out;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec2 a = loop[i], b = loop[(i + 1) % loop.size()];
    const int parts = std::max(1, static_cast<int>(std::ceil((b - a).norm() / spacing)));
    for (int k = 0; k < parts; ++k) out.push_back(a + (b - a) * (static_cast<double>(k) / parts));
  }
  return out;
}

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
  // Usually the outline resampled every `spacing` px is a simple polygon
  // within half a pixel of it. Where it is not (parts that come within a
  // spacing of each other: a slit a pixel wide, the folds of case5 x2) the
  // cut corners can cross or bridge the gap; a topology-preserving
  // simplification keeps every loop simple and apart, and points added on its
  // edges at the spacing do not move it.
  std::vector<int> source;
  std::vector<Polyline> loops{detail::resample_closed(clean, spacing, &source)};
  bool retraced = false, simplified_path = false;
  if (deviation(clean, loops[0], source) > kResampleTolerance || !is_simple(loops[0])) {
    simplified_path = true;
    std::vector<Polyline> shape;
    if (is_simple(clean)) {
      shape.push_back(clean);
    } else {
      shape = detail::simple_outline(clean);
      retraced = true;
      if (shape.empty()) {
        throw Error("skeleton::mesh_strand: nothing of the outline is thicker than a pixel");
      }
    }
    const std::vector<Polyline> simplified =
        detail::simplify_loops(shape, retraced ? kRetracedTolerance : kSimplifyTolerance);
    loops.clear();
    for (const Polyline& loop : simplified) loops.push_back(densify(loop, spacing));
    if (!std::all_of(loops.begin(), loops.end(), is_simple)) loops = simplified;
  }
  const bool simple = std::all_of(loops.begin(), loops.end(), is_simple);
  // Exact constructions build each refinement point from earlier ones, so
  // their numbers, and the time per point, grow as the mesh does: a large
  // strand of a 1792 x 2324 drawing took 0.2 s for 3000 vertices and more
  // than five minutes for 10000. The refinement is the same sequence of
  // points under any limit, so a lower one only stops it sooner.
  MeshOptions exact = options;
  exact.max_vertices = std::min(options.max_vertices, kExactMaxVertices);
  MeshResult result = simple ? mesh_samples<InexactKernel>(loops, options)
                             : mesh_samples<ExactKernel>(loops, exact);
  if (result.mesh.triangle_count() == 0) {
    throw Error("skeleton::mesh_strand: the outline gave no triangles inside it");
  }
  result.exact = !simple;
  result.retraced = retraced;
  result.simplified = simplified_path;
  return result;
}

}  // namespace hair25d::skeleton
