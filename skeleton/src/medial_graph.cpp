#include "medial_graph.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <deque>
#include <map>
#include <string>

#include "hair25d/core/error.h"

namespace hair25d::skeleton::detail {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
struct VertexInfo {
  int sample = -1;  // -1 for points CGAL adds where constraints cross
};
struct FaceInfo {
  int nesting = -1;  // -1 unvisited; odd = inside the outline
  int id = -1;
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, K>;
using Fb0 = CGAL::Constrained_triangulation_face_base_2<K>;
using Fb = CGAL::Triangulation_face_base_with_info_2<FaceInfo, K, Fb0>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Point = K::Point_2;

Vec2 to_vec(const Point& p) { return {p.x(), p.y()}; }

// Nesting level by flood fill across constrained edges, as in CGAL's
// polygon_triangulation example (CGAL 5.5 has no mark_domain_in_triangulation).
void mark_nesting(Cdt& cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info().nesting = -1;
  std::deque<Cdt::Face_handle> border{cdt.infinite_face()};
  int level = 0;
  while (!border.empty()) {
    std::deque<Cdt::Face_handle> next;
    while (!border.empty()) {
      std::deque<Cdt::Face_handle> queue{border.front()};
      border.pop_front();
      while (!queue.empty()) {
        Cdt::Face_handle f = queue.front();
        queue.pop_front();
        if (f->info().nesting != -1) continue;
        f->info().nesting = level;
        for (int i = 0; i < 3; ++i) {
          Cdt::Face_handle n = f->neighbor(i);
          if (n->info().nesting != -1) continue;
          if (cdt.is_constrained(Cdt::Edge(f, i)))
            next.push_back(n);
          else
            queue.push_back(n);
        }
      }
    }
    border = std::move(next);
    ++level;
  }
}

bool inside(const Cdt& cdt, Cdt::Face_handle f) {
  return !cdt.is_infinite(f) && f->info().nesting % 2 == 1;
}

}  // namespace

MedialGraph build_medial_graph(const Polyline& samples) {
  MedialGraph g;
  g.apex_of_sample.assign(samples.size(), -1);
  try {
    Cdt cdt;
    std::vector<Cdt::Vertex_handle> handles;
    handles.reserve(samples.size());
    Cdt::Face_handle hint;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      Cdt::Vertex_handle v = cdt.insert(Point(samples[i].x(), samples[i].y()), hint);
      v->info().sample = static_cast<int>(i);
      hint = v->face();
      handles.push_back(v);
    }
    for (std::size_t i = 0; i < handles.size(); ++i) {
      Cdt::Vertex_handle a = handles[i], b = handles[(i + 1) % handles.size()];
      if (a != b) cdt.insert_constraint(a, b);
    }
    if (cdt.dimension() < 2) return g;
    mark_nesting(cdt);

    int face_count = 0;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      if (inside(cdt, f)) f->info().id = face_count++;

    std::map<std::pair<int, int>, int> edge_node;
    auto add_node = [&](const Vec2& p, double r) {
      g.nodes.push_back(p);
      g.adjacent.emplace_back();
      g.radius.push_back(r);
      return static_cast<int>(g.nodes.size()) - 1;
    };
    auto link = [&](int a, int b) {
      g.adjacent[a].push_back(b);
      g.adjacent[b].push_back(a);
    };
    auto inner_edge_node = [&](Cdt::Face_handle f, int i) {
      const int a = f->info().id, b = f->neighbor(i)->info().id;
      const auto key = std::minmax(a, b);
      auto it = edge_node.find(key);
      if (it != edge_node.end()) return it->second;
      const Vec2 p = to_vec(f->vertex(Cdt::ccw(i))->point());
      const Vec2 q = to_vec(f->vertex(Cdt::cw(i))->point());
      const int id = add_node(0.5 * (p + q), 0.5 * (p - q).norm());
      edge_node.emplace(key, id);
      return id;
    };

    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      if (!inside(cdt, f)) continue;
      std::vector<int> inner;
      for (int i = 0; i < 3; ++i)
        if (!cdt.is_constrained(Cdt::Edge(f, i)) && inside(cdt, f->neighbor(i))) inner.push_back(i);
      const Vec2 a = to_vec(f->vertex(0)->point());
      const Vec2 b = to_vec(f->vertex(1)->point());
      const Vec2 c = to_vec(f->vertex(2)->point());
      if (inner.size() == 3) {
        // Junction: the circumcentre is the true medial-axis vertex, but for
        // obtuse triangles it leaves the triangle (and maybe the shape).
        const Vec2 cc = to_vec(CGAL::circumcenter(f->vertex(0)->point(), f->vertex(1)->point(),
                                                  f->vertex(2)->point()));
        const bool acute =
            (b - a).dot(c - a) > 0 && (a - b).dot(c - b) > 0 && (a - c).dot(b - c) > 0;
        const Vec2 centre = acute ? cc : (a + b + c) / 3.0;
        const int j = add_node(centre, acute ? (cc - a).norm() : ((a + b + c) / 3.0 - a).norm());
        for (int i : inner) link(j, inner_edge_node(f, i));
      } else if (inner.size() == 2) {
        link(inner_edge_node(f, inner[0]), inner_edge_node(f, inner[1]));
      } else if (inner.size() == 1) {
        const Cdt::Vertex_handle apex = f->vertex(inner[0]);
        const int j = add_node(to_vec(apex->point()), 0.0);
        link(j, inner_edge_node(f, inner[0]));
        const int sample = apex->info().sample;
        if (sample >= 0 && sample < static_cast<int>(samples.size()) &&
            g.apex_of_sample[sample] < 0)
          g.apex_of_sample[sample] = j;
      } else {
        add_node((a + b + c) / 3.0, 0.0);
      }
    }
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(std::string("skeleton: medial axis triangulation failed: ") + e.what());
  }
  return g;
}

}  // namespace hair25d::skeleton::detail
