#include "simplify_outline.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyline_simplification_2/simplify.h>

#include <string>
#include <utility>
#include <vector>

#include "hair25d/core/error.h"

namespace hair25d::skeleton::detail {

namespace {

namespace PS = CGAL::Polyline_simplification_2;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = PS::Vertex_base_2<K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Exact_predicates_tag: the loops do not cross, so no intersection point is
// ever constructed and inexact constructions are safe here.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Ct = CGAL::Constrained_triangulation_plus_2<Cdt>;

}  // namespace

std::vector<Polyline> simplify_loops(const std::vector<Polyline>& loops, double tolerance) {
  std::vector<Polyline> out;
  try {
    Ct ct;
    std::vector<Ct::Constraint_id> ids;
    for (const Polyline& loop : loops) {
      std::vector<K::Point_2> points;
      points.reserve(loop.size());
      for (const Vec2& p : loop) points.emplace_back(p.x(), p.y());
      ids.push_back(ct.insert_constraint(points.begin(), points.end(), /*close=*/true));
    }
    // The cost of dropping a vertex is the largest squared distance of the
    // original vertices it stood for to the new edge; the simplifier refuses
    // a removal whose new edge would cross another constraint.
    // One loop at a time, in the caller's order: simplifying all constraints
    // at once walks them in the order of their addresses in memory, and equal
    // costs (common on pixel outlines) are then taken in that order, so the
    // same outline gave a different mesh from run to run.
    for (const Ct::Constraint_id& id : ids) {
      PS::simplify(ct, id, PS::Squared_distance_cost(),
                   PS::Stop_above_cost_threshold(tolerance * tolerance));
    }
    for (const Ct::Constraint_id& id : ids) {
      Polyline loop;
      for (auto v = ct.vertices_in_constraint_begin(id); v != ct.vertices_in_constraint_end(id);
           ++v)
        loop.emplace_back((*v)->point().x(), (*v)->point().y());
      // A closed constraint repeats its first vertex at the end.
      if (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
      // A loop thinner than the tolerance may collapse; it stays as it was
      // (it was a constraint throughout, so no other loop crosses it).
      out.push_back(loop.size() >= 3 ? std::move(loop) : loops[out.size()]);
    }
  } catch (const std::exception& e) {
    throw Error(std::string("skeleton::mesh_strand: CGAL polyline simplification failed: ") +
                e.what());
  }
  return out;
}

}  // namespace hair25d::skeleton::detail
