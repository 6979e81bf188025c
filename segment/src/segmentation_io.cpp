#include "hair25d/segment/segmentation_io.h"

#include <nlohmann/json.hpp>

#include "hair25d/core/atomic_file.h"
#include "hair25d/core/error.h"

namespace hair25d::segment {
namespace {

using json = nlohmann::json;
constexpr const char* kFormat = "hair25d-segmentation/1";

const char* end_name(CurveEnd e) {
  switch (e) {
    case CurveEnd::kFree:
      return "free";
    case CurveEnd::kEndpoint:
      return "endpoint";
    case CurveEnd::kJunction:
      return "junction";
  }
  return "free";
}

[[noreturn]] void fail(const std::string& source, const std::string& key, const std::string& what) {
  throw Error(source + ": key \"" + key + "\": " + what);
}

const json& need(const json& obj, const char* key, const std::string& source,
                 const std::string& path) {
  if (!obj.is_object() || !obj.contains(key)) fail(source, path + key, "missing");
  return obj.at(key);
}

Vec2 read_point(const json& p, const std::string& source, const std::string& key) {
  if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
    fail(source, key, "expected a point [x, y] of two numbers");
  const Vec2 v(p[0].get<double>(), p[1].get<double>());
  if (!v.allFinite()) fail(source, key, "expected finite coordinates");
  return v;
}

int read_int(const json& v, const std::string& source, const std::string& key) {
  if (!v.is_number_integer()) fail(source, key, "expected an integer");
  return v.get<int>();
}

}  // namespace

std::string segmentation_to_json(const Segmentation& s) {
  json doc;
  doc["format"] = kFormat;
  doc["width"] = s.width;
  doc["height"] = s.height;
  json curves = json::array();
  for (const Curve& c : s.curves) {
    json pts = json::array();
    for (const Vec2& p : c.points) pts.push_back({p.x(), p.y()});
    curves.push_back({{"points", pts},
                      {"ends", {end_name(c.ends[0]), end_name(c.ends[1])}},
                      {"closed", c.closed}});
  }
  doc["curves"] = curves;
  json vertices = json::array(), triangles = json::array(), flags = json::array();
  for (int v = 0; v < s.mesh.vertex_count(); ++v)
    vertices.push_back({s.mesh.V(v, 0), s.mesh.V(v, 1)});
  const bool has_flags = s.mesh.on_curve.rows() == s.mesh.F.rows();
  for (int t = 0; t < s.mesh.triangle_count(); ++t) {
    triangles.push_back({s.mesh.F(t, 0), s.mesh.F(t, 1), s.mesh.F(t, 2)});
    int bits = 0;
    for (int k = 0; k < 3 && has_flags; ++k) bits |= s.mesh.on_curve(t, k) ? (1 << k) : 0;
    flags.push_back(bits);
  }
  doc["mesh"] = {{"vertices", vertices}, {"triangles", triangles}, {"curve_edges", flags}};
  doc["triangle_region"] = s.triangle_region;
  json adj = json::array();
  for (const auto& a : s.adjacency) adj.push_back({a[0], a[1]});
  doc["adjacency"] = adj;
  return doc.dump() + "\n";
}

Segmentation segmentation_from_json(const std::string& text, const std::string& source) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    throw Error(source + ": not valid JSON: " + e.what());
  }
  const json& format = need(doc, "format", source, "");
  if (!format.is_string() || format.get<std::string>() != kFormat)
    fail(source, "format", std::string("expected \"") + kFormat + "\"");
  Segmentation s;
  s.width = read_int(need(doc, "width", source, ""), source, "width");
  s.height = read_int(need(doc, "height", source, ""), source, "height");
  if (s.width <= 0 || s.height <= 0) fail(source, "width", "expected a positive size");
  const json& curves = need(doc, "curves", source, "");
  if (!curves.is_array()) fail(source, "curves", "expected an array");
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const std::string key = "curves[" + std::to_string(i) + "].";
    Curve c;
    const json& pts = need(curves[i], "points", source, key);
    if (!pts.is_array() || pts.size() < 2)
      fail(source, key + "points", "expected at least two points");
    for (std::size_t k = 0; k < pts.size(); ++k)
      c.points.push_back(read_point(pts[k], source, key + "points[" + std::to_string(k) + "]"));
    const json& ends = need(curves[i], "ends", source, key);
    if (!ends.is_array() || ends.size() != 2) fail(source, key + "ends", "expected two end kinds");
    for (int e = 0; e < 2; ++e) {
      const std::string name = ends[e].is_string() ? ends[e].get<std::string>() : "";
      if (name == "free")
        c.ends[e] = CurveEnd::kFree;
      else if (name == "endpoint")
        c.ends[e] = CurveEnd::kEndpoint;
      else if (name == "junction")
        c.ends[e] = CurveEnd::kJunction;
      else
        fail(source, key + "ends", "expected \"free\", \"endpoint\" or \"junction\"");
    }
    const json& closed = need(curves[i], "closed", source, key);
    if (!closed.is_boolean()) fail(source, key + "closed", "expected true or false");
    c.closed = closed.get<bool>();
    s.curves.push_back(std::move(c));
  }
  const json& mesh = need(doc, "mesh", source, "");
  const json& vertices = need(mesh, "vertices", source, "mesh.");
  const json& triangles = need(mesh, "triangles", source, "mesh.");
  const json& flags = need(mesh, "curve_edges", source, "mesh.");
  if (!vertices.is_array()) fail(source, "mesh.vertices", "expected an array");
  if (!triangles.is_array()) fail(source, "mesh.triangles", "expected an array");
  if (!flags.is_array() || flags.size() != triangles.size())
    fail(source, "mesh.curve_edges", "expected one integer per triangle");
  s.mesh.V.resize(static_cast<Eigen::Index>(vertices.size()), 2);
  for (std::size_t v = 0; v < vertices.size(); ++v)
    s.mesh.V.row(v) = read_point(vertices[v], source, "mesh.vertices[" + std::to_string(v) + "]");
  s.mesh.F.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  s.mesh.on_curve.resize(s.mesh.F.rows(), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const std::string key = "mesh.triangles[" + std::to_string(t) + "]";
    if (!triangles[t].is_array() || triangles[t].size() != 3)
      fail(source, key, "expected three vertex indices");
    for (int k = 0; k < 3; ++k) s.mesh.F(t, k) = read_int(triangles[t][k], source, key);
    const int bits = read_int(flags[t], source, "mesh.curve_edges[" + std::to_string(t) + "]");
    if (bits < 0 || bits > 7) fail(source, "mesh.curve_edges", "expected bit masks in [0, 7]");
    for (int k = 0; k < 3; ++k) s.mesh.on_curve(t, k) = (bits >> k) & 1;
  }
  s.mesh.validate((source + ": mesh").c_str());
  const json& regions = need(doc, "triangle_region", source, "");
  if (!regions.is_array() || regions.size() != triangles.size())
    fail(source, "triangle_region",
         "expected one region id per triangle (" + std::to_string(triangles.size()) + ")");
  for (std::size_t t = 0; t < regions.size(); ++t) {
    const int r = read_int(regions[t], source, "triangle_region[" + std::to_string(t) + "]");
    if (r < 0) fail(source, "triangle_region", "expected ids >= 0");
    s.triangle_region.push_back(r);
  }
  const json& adj = need(doc, "adjacency", source, "");
  if (!adj.is_array()) fail(source, "adjacency", "expected an array of pairs");
  for (std::size_t i = 0; i < adj.size(); ++i) {
    const std::string key = "adjacency[" + std::to_string(i) + "]";
    if (!adj[i].is_array() || adj[i].size() != 2) fail(source, key, "expected a pair [a, b]");
    const int a = read_int(adj[i][0], source, key), b = read_int(adj[i][1], source, key);
    if (a < 0 || b <= a) fail(source, key, "expected 0 <= a < b");
    s.adjacency.push_back({a, b});
  }
  return s;
}

void write_segmentation(const std::filesystem::path& path, const Segmentation& segmentation) {
  write_text_atomically(path, segmentation_to_json(segmentation));
}

Segmentation read_segmentation(const std::filesystem::path& path) {
  return segmentation_from_json(read_text_file(path), path.string());
}

}  // namespace hair25d::segment
