#include "hair25d/segment/regions.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "hair25d/core/error.h"
#include "hair25d/segment/mesh.h"
#include "mesh_topology.h"
#include "paper.h"

namespace hair25d::segment {
namespace {

void check_sizes(const TriMesh2& mesh, const std::vector<int>& labels, const char* what) {
  if (labels.size() != static_cast<std::size_t>(mesh.triangle_count()))
    throw Error(std::string(what) + ": " + std::to_string(labels.size()) + " labels for " +
                std::to_string(mesh.triangle_count()) + " triangles; must be one per triangle");
}

}  // namespace

std::vector<int> automatic_regions(const TriMesh2& mesh) {
  mesh.validate("segment::automatic_regions mesh");
  const int nf = mesh.triangle_count();
  const auto nb = detail::triangle_neighbours(mesh);
  detail::UnionFind uf(nf);
  for (int t = 0; t < nf; ++t)
    for (int k = 0; k < 3; ++k)
      if (nb[t][k] >= 0 && !detail::edge_on_curve(mesh, t, k)) uf.unite(t, nb[t][k]);
  std::vector<int> id(nf, 0), root_id(nf, 0);
  int next = 0;
  for (int t = 0; t < nf; ++t) {
    const int r = uf.find(t);
    if (root_id[r] == 0) root_id[r] = ++next;
    id[t] = root_id[r];
  }
  return id;
}

LabelMap region_map(const Image& image, const TriMesh2& mesh,
                    const std::vector<int>& triangle_regions) {
  check_sizes(mesh, triangle_regions, "segment::region_map");
  LabelMap out =
      rasterize_triangle_values(mesh, triangle_regions, image.width(), image.height(), 0);
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (detail::is_paper(image.at(x, y))) out.at(x, y) = 0;
  return out;
}

int clear_paper_regions(const Image& image, const TriMesh2& mesh,
                        std::vector<int>& triangle_regions) {
  check_sizes(mesh, triangle_regions, "segment::clear_paper_regions");
  const LabelMap regions =
      rasterize_triangle_values(mesh, triangle_regions, image.width(), image.height(), 0);
  std::map<int, std::array<int, 2>> count;  // id -> {paper, all}
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const int id = regions.at(x, y);
      if (id <= 0) continue;
      auto& c = count[id];
      c[0] += detail::is_paper(image.at(x, y));
      ++c[1];
    }
  std::set<int> cleared;
  for (const auto& [id, c] : count)
    if (2 * c[0] > c[1]) cleared.insert(id);
  for (int& id : triangle_regions)
    if (cleared.count(id)) id = 0;
  return static_cast<int>(cleared.size());
}

std::vector<RegionStats> region_stats(const Image& image, const TriMesh2& mesh,
                                      const std::vector<int>& triangle_regions,
                                      const LabelMap& line_mask) {
  check_sizes(mesh, triangle_regions, "segment::region_stats");
  if (!line_mask.empty() &&
      (line_mask.width() != image.width() || line_mask.height() != image.height()))
    throw Error("segment::region_stats: line mask size differs from the image");
  std::map<int, RegionStats> stats;
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const int id = triangle_regions[t];
    if (id <= 0) continue;
    const Vec2 a = mesh.V.row(mesh.F(t, 0)), b = mesh.V.row(mesh.F(t, 1)),
               c = mesh.V.row(mesh.F(t, 2));
    const double area = 0.5 * std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
    RegionStats& s = stats[id];
    s.id = id;
    s.centroid = (s.centroid * s.area + area * (a + b + c) / 3.0) / std::max(1e-300, s.area + area);
    s.area += area;
  }
  const LabelMap regions = region_map(image, mesh, triangle_regions);
  std::map<int, std::array<double, 3>> sum, line_sum;
  std::map<int, int> n, line_n;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const int id = regions.at(x, y);
      if (id <= 0) continue;
      const Rgba& p = image.at(x, y);
      const bool line = !line_mask.empty() && line_mask.at(x, y) != 0;
      auto& s = line ? line_sum[id] : sum[id];
      s[0] += p.r, s[1] += p.g, s[2] += p.b;
      ++(line ? line_n : n)[id];
    }
  }
  std::vector<RegionStats> out;
  for (auto& [id, s] : stats) {
    // A region that is all line keeps the line colour rather than none.
    const bool off = n[id] > 0;
    const auto& acc = off ? sum[id] : line_sum[id];
    const int count = off ? n[id] : line_n[id];
    if (count > 0)
      for (int k = 0; k < 3; ++k) s.mean[k] = acc[k] / count;
    s.pixels = count;
    out.push_back(s);
  }
  return out;
}

std::vector<int> label_regions_by_colour(const Image& image, const TriMesh2& mesh,
                                         const std::vector<int>& triangle_regions,
                                         const LabelMap& line_mask, const ColourPick& pick) {
  if (!(pick.tolerance >= 0.0 && std::isfinite(pick.tolerance))) {
    std::ostringstream o;
    o << "segment::ColourPick::tolerance = " << pick.tolerance << "; must be >= 0";
    throw Error(o.str());
  }
  if (!(pick.min_area >= 0.0))
    throw Error("segment::ColourPick::min_area = " + std::to_string(pick.min_area) +
                "; must be >= 0");
  const auto stats = region_stats(image, mesh, triangle_regions, line_mask);
  std::map<int, int> chosen;
  int next = 0;
  for (const RegionStats& s : stats) {
    if (s.pixels == 0 || s.area < pick.min_area) continue;
    const double d =
        std::hypot(s.mean[0] - pick.rgb[0], s.mean[1] - pick.rgb[1], s.mean[2] - pick.rgb[2]);
    if (d <= pick.tolerance) chosen[s.id] = ++next;
  }
  std::vector<int> labels(triangle_regions.size(), 0);
  for (std::size_t t = 0; t < labels.size(); ++t)
    if (auto it = chosen.find(triangle_regions[t]); it != chosen.end()) labels[t] = it->second;
  return labels;
}

Strokes strokes_from_labels(const TriMesh2& mesh, const std::vector<int>& triangle_labels,
                            double width) {
  check_sizes(mesh, triangle_labels, "segment::strokes_from_labels");
  if (!(width >= 1.0 && std::isfinite(width)))
    throw Error("segment::strokes_from_labels: width = " + std::to_string(width) +
                "; must be >= 1");
  // The dot goes in the label's largest triangle: inside by construction, and
  // as far from the region's border as one triangle allows.
  std::map<int, std::pair<double, int>> best;
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    const int l = triangle_labels[t];
    if (l <= 0) continue;
    const Vec2 a = mesh.V.row(mesh.F(t, 0)), b = mesh.V.row(mesh.F(t, 1)),
               c = mesh.V.row(mesh.F(t, 2));
    const double area = 0.5 * std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
    auto [it, fresh] = best.try_emplace(l, area, t);
    if (!fresh && area > it->second.first) it->second = {area, t};
  }
  Strokes out;
  for (const auto& [l, at] : best) {
    const int t = at.second;
    const Vec2 centre =
        (mesh.V.row(mesh.F(t, 0)) + mesh.V.row(mesh.F(t, 1)) + mesh.V.row(mesh.F(t, 2)))
            .transpose() /
        3.0;
    // Stroke points name pixels: pixel (i, j) has its centre at (i + 0.5, j + 0.5).
    out.strokes.push_back({l, width, {Vec2(std::floor(centre.x()), std::floor(centre.y()))}});
  }
  return out;
}

void merge_labels(std::vector<int>& triangle_labels, int from, int into) {
  if (from < 0 || into < 0)
    throw Error("segment::merge_labels: from = " + std::to_string(from) +
                ", into = " + std::to_string(into) + "; ids must be >= 0");
  std::replace(triangle_labels.begin(), triangle_labels.end(), from, into);
}

void relabel(std::vector<int>& triangle_labels, const std::map<int, int>& mapping) {
  for (const auto& [from, to] : mapping)
    if (to < 0)
      throw Error("segment::relabel: id " + std::to_string(from) + " -> " + std::to_string(to) +
                  "; new ids must be >= 0");
  for (int& l : triangle_labels)
    if (auto it = mapping.find(l); it != mapping.end()) l = it->second;
}

int compact_labels(std::vector<int>& triangle_labels) {
  std::set<int> ids;
  for (int l : triangle_labels)
    if (l > 0) ids.insert(l);
  std::map<int, int> mapping;
  int next = 0;
  for (int id : ids) mapping[id] = ++next;
  relabel(triangle_labels, mapping);
  return next;
}

std::vector<std::array<int, 2>> label_adjacency(const TriMesh2& mesh,
                                                const std::vector<int>& triangle_labels) {
  check_sizes(mesh, triangle_labels, "segment::label_adjacency");
  const auto nb = detail::triangle_neighbours(mesh);
  std::set<std::array<int, 2>> pairs;
  for (int t = 0; t < mesh.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int o = nb[t][k];
      if (o < 0) continue;
      const int a = triangle_labels[t], b = triangle_labels[o];
      if (a != b) pairs.insert({std::min(a, b), std::max(a, b)});
    }
  }
  return {pairs.begin(), pairs.end()};
}

}  // namespace hair25d::segment
