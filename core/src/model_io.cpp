#include "hair25d/core/model_io.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <future>
#include <set>
#include <utility>
#include <vector>

#include "hair25d/core/atomic_file.h"
#include "json_read.h"

namespace hair25d {

namespace fs = std::filesystem;
namespace jr = json_read;
using nlohmann::json;

inline constexpr const char* kModelFormat = "hair25d-model";

namespace {

// The model's arrays are built element by element and moved into place: an
// initializer list of named arrays, or a strand pushed by value, copies every
// node (three copies of each mesh made most of the time of a model write).
template <typename T, std::size_t N>
json tuple_json(const std::array<T, N>& values) {
  json::array_t out;
  out.reserve(N);
  for (const T& v : values) out.emplace_back(v);
  return json(std::move(out));
}

json points_json(const Polyline& points) {
  json::array_t out;
  out.reserve(points.size());
  for (const Vec2& p : points) out.push_back(tuple_json(std::array<double, 2>{p.x(), p.y()}));
  return json(std::move(out));
}

json mesh_json(const TriMesh2& mesh) {
  json::array_t vertices, triangles, on_curve;
  vertices.reserve(static_cast<std::size_t>(mesh.V.rows()));
  triangles.reserve(static_cast<std::size_t>(mesh.F.rows()));
  const bool curves = mesh.on_curve.rows() == mesh.F.rows();
  if (curves) on_curve.reserve(static_cast<std::size_t>(mesh.F.rows()));
  for (int i = 0; i < mesh.V.rows(); ++i)
    vertices.push_back(tuple_json(std::array<double, 2>{mesh.V(i, 0), mesh.V(i, 1)}));
  for (int t = 0; t < mesh.F.rows(); ++t) {
    triangles.push_back(tuple_json(std::array<int, 3>{mesh.F(t, 0), mesh.F(t, 1), mesh.F(t, 2)}));
    if (curves) {
      on_curve.push_back(tuple_json(
          std::array<bool, 3>{mesh.on_curve(t, 0), mesh.on_curve(t, 1), mesh.on_curve(t, 2)}));
    }
  }
  json out = json::object();
  out["vertices"] = std::move(vertices);
  out["triangles"] = std::move(triangles);
  if (!on_curve.empty()) out["on_curve"] = std::move(on_curve);
  return out;
}

// Model paths are relative and stay inside the model folder.
fs::path checked_path(const fs::path& folder, const json& value, const std::string& source,
                      const std::string& key) {
  const std::string rel = jr::as_string(value, source, key);
  const fs::path p(rel);
  bool escapes = rel.empty() || p.is_absolute() || p.has_root_name();
  for (const auto& part : p) escapes = escapes || part == "..";
  if (escapes) jr::fail(source, key, "a relative path that stays inside the model folder", &value);
  return folder / p;
}

Polyline read_points(const json& value, const std::string& source, const std::string& key) {
  jr::expect_array(value, source, key);
  Polyline out;
  out.reserve(value.size());
  for (std::size_t i = 0; i < value.size(); ++i)
    out.push_back(jr::as_point(value[i], source, jr::index(key, i)));
  return out;
}

TriMesh2 read_mesh(const json& value, const std::string& source, const std::string& key) {
  jr::expect_object(value, source, key);
  TriMesh2 mesh;
  const Polyline v =
      read_points(jr::member(value, source, key, "vertices"), source, jr::join(key, "vertices"));
  mesh.V.resize(static_cast<Eigen::Index>(v.size()), 2);
  for (std::size_t i = 0; i < v.size(); ++i)
    mesh.V.row(static_cast<Eigen::Index>(i)) = v[i].transpose();
  const std::string tkey = jr::join(key, "triangles");
  const json& tris = jr::member(value, source, key, "triangles");
  jr::expect_array(tris, source, tkey);
  mesh.F.resize(static_cast<Eigen::Index>(tris.size()), 3);
  for (std::size_t t = 0; t < tris.size(); ++t) {
    const std::string at = jr::index(tkey, t);
    if (!tris[t].is_array() || tris[t].size() != 3)
      jr::fail(source, at, "three vertex indices", &tris[t]);
    for (int k = 0; k < 3; ++k) {
      const int idx = jr::as_int(tris[t][k], source, jr::index(at, k));
      if (idx < 0 || idx >= static_cast<int>(v.size())) {
        jr::fail(source, jr::index(at, k), "a vertex index in 0.." + std::to_string(v.size() - 1),
                 &tris[t][k]);
      }
      mesh.F(static_cast<Eigen::Index>(t), k) = idx;
    }
  }
  if (const json* oc = jr::optional_member(value, source, key, "on_curve")) {
    const std::string okey = jr::join(key, "on_curve");
    jr::expect_array(*oc, source, okey);
    if (oc->size() != tris.size()) jr::fail(source, okey, "one entry per triangle", oc);
    mesh.on_curve.resize(static_cast<Eigen::Index>(tris.size()), 3);
    for (std::size_t t = 0; t < oc->size(); ++t) {
      if (!(*oc)[t].is_array() || (*oc)[t].size() != 3)
        jr::fail(source, jr::index(okey, t), "three booleans", &(*oc)[t]);
      for (int k = 0; k < 3; ++k)
        mesh.on_curve(static_cast<Eigen::Index>(t), k) =
            jr::as_bool((*oc)[t][k], source, jr::index(okey, t));
    }
  }
  try {
    mesh.validate(key.c_str());
  } catch (const Error& e) {
    throw Error(source + ": " + e.what());
  }
  return mesh;
}

}  // namespace

namespace {

void check_writable(const fs::path& folder, const HairModel& model) {
  if (model.width <= 0 || model.height <= 0) {
    throw Error(folder.string() + ": the model's size " + std::to_string(model.width) + "x" +
                std::to_string(model.height) + " is not positive");
  }
  for (const Strand& s : model.strands) {
    s.mesh.validate(("strand " + std::to_string(s.id) + " mesh").c_str());
  }
}

void write_contents(const fs::path& tmp, const HairModel& model) {
  // PNG compression is most of a model write: a second thread encodes the
  // images, largest first, from the start; the caller's thread writes the
  // JSON meanwhile, then takes the next image not yet taken as well.
  std::vector<std::pair<fs::path, const Image*>> images;
  if (!model.image.empty()) images.emplace_back(tmp / "image.png", &model.image);
  if (!model.background.empty()) images.emplace_back(tmp / "background.png", &model.background);
  for (const Strand& s : model.strands)
    if (!s.texture.empty())
      images.emplace_back(tmp / "strands" / (std::to_string(s.id) + ".png"), &s.texture);
  const std::size_t whole_images =
      (model.image.empty() ? 0u : 1u) + (model.background.empty() ? 0u : 1u);
  if (images.size() > whole_images) fs::create_directory(tmp / "strands");
  std::stable_sort(images.begin(), images.end(), [](const auto& a, const auto& b) {
    return std::int64_t{a.second->width()} * a.second->height() >
           std::int64_t{b.second->width()} * b.second->height();
  });
  std::atomic<std::size_t> next{0};
  const auto encode = [&images, &next] {
    for (std::size_t i = next++; i < images.size(); i = next++)
      save_image(images[i].first, *images[i].second);
  };
  auto encoded = std::async(std::launch::async, encode);
  {
    json doc;
    doc["format"] = kModelFormat;
    doc["version"] = kModelFormatVersion;
    doc["width"] = model.width;
    doc["height"] = model.height;
    if (!model.image.empty()) doc["image"] = "image.png";
    if (!model.background.empty()) doc["background"] = "background.png";
    if (model.head_center) doc["head_center"] = {model.head_center->x(), model.head_center->y()};
    json strands = json::array();
    for (const Strand& s : model.strands) {
      json js;
      js["id"] = s.id;
      js["name"] = s.name;
      js["regions"] = s.regions;
      js["depth"] = s.depth;
      js["outline"] = points_json(s.outline);
      if (!s.texture.empty()) {
        js["texture"] = "strands/" + std::to_string(s.id) + ".png";
        js["texture_origin"] = {s.texture_origin.x(), s.texture_origin.y()};
      }
      js["mesh"] = mesh_json(s.mesh);
      json skeleton = json::object();
      skeleton["nodes"] = points_json(s.skeleton.nodes);
      skeleton["parent"] = s.skeleton.parent;
      skeleton["tips"] = s.skeleton.tips;
      js["skeleton"] = std::move(skeleton);
      js["physics"] = {{"stiffness", s.physics.stiffness},
                       {"tau0", s.physics.tau0},
                       {"lambda", s.physics.lambda},
                       {"damping", s.physics.damping},
                       {"gravity", s.physics.gravity}};
      strands.push_back(std::move(js));
    }
    doc["strands"] = std::move(strands);
    json relations = json::array();
    for (const RegionRelation& r : model.relations) {
      json entry = {{"a", r.a},
                    {"b", r.b},
                    {"relation", to_string(r.relation)},
                    {"score", r.score},
                    {"user_fixed", r.user_fixed},
                    {"overridden", r.overridden}};
      if (r.equal_evidence)
        entry["equal_evidence"] = {{"log_odds", r.equal_evidence->log_odds},
                                   {"open", r.equal_evidence->open},
                                   {"open_fraction", r.equal_evidence->open_fraction}};
      relations.push_back(std::move(entry));
    }
    doc["relations"] = std::move(relations);
    write_text_atomically(tmp / "model.json", doc.dump(1) + "\n");
  }
  encode();
  encoded.get();
}

}  // namespace

void write_model_into(const fs::path& folder, const HairModel& model) {
  check_writable(folder, model);
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw Error(folder.string() + ": not an existing folder; write_model_into writes into one");
  write_contents(folder, model);
}

void write_model(const fs::path& folder, const HairModel& model) {
  check_writable(folder, model);
  write_folder_atomically(
      folder, [&](const fs::path& tmp) { write_contents(tmp, model); }, "model");
}

std::vector<std::string> model_folder_names() {
  return {"model.json", "image.png", "background.png", "strands"};
}

HairModel read_model(const fs::path& folder, const ImageLimits& limits) {
  const fs::path json_path = folder / "model.json";
  const std::string src = json_path.string();
  const json doc = jr::parse(read_text_file(json_path), src);
  jr::expect_object(doc, src, "");
  const std::string format = jr::as_string(jr::member(doc, src, "", "format"), src, "format");
  if (format != kModelFormat)
    jr::fail(src, "format", std::string("\"") + kModelFormat + "\"", &doc["format"]);
  const int version = jr::as_int(jr::member(doc, src, "", "version"), src, "version");
  if (version < 1 || version > kModelFormatVersion) {
    jr::fail(src, "version", "a version in 1.." + std::to_string(kModelFormatVersion),
             &doc["version"]);
  }
  HairModel m;
  m.width = jr::as_int(jr::member(doc, src, "", "width"), src, "width");
  m.height = jr::as_int(jr::member(doc, src, "", "height"), src, "height");
  if (m.width <= 0 || m.width > limits.max_side)
    jr::fail(src, "width", "a width in 1.." + std::to_string(limits.max_side), &doc["width"]);
  if (m.height <= 0 || m.height > limits.max_side)
    jr::fail(src, "height", "a height in 1.." + std::to_string(limits.max_side), &doc["height"]);
  if (std::int64_t{m.width} * m.height > limits.max_pixels) {
    throw Error(src + ": width x height = " + std::to_string(std::int64_t{m.width} * m.height) +
                " pixels; at most " + std::to_string(limits.max_pixels) + " are allowed");
  }
  auto read_sized = [&](const char* key) {
    Image img = load_image(checked_path(folder, doc[key], src, key), limits);
    if (img.width() != m.width || img.height() != m.height) {
      throw Error(src + ": key '" + key + "': image size " + std::to_string(img.width()) + "x" +
                  std::to_string(img.height()) + " differs from the model's " +
                  std::to_string(m.width) + "x" + std::to_string(m.height));
    }
    return img;
  };
  if (jr::optional_member(doc, src, "", "image")) m.image = read_sized("image");
  if (jr::optional_member(doc, src, "", "background")) m.background = read_sized("background");
  if (const json* h = jr::optional_member(doc, src, "", "head_center"))
    m.head_center = jr::as_point(*h, src, "head_center");

  const json& strands = jr::member(doc, src, "", "strands");
  jr::expect_array(strands, src, "strands");
  // Strands come from regions (at most max_regions of them); their textures
  // are crops of the drawing, all together at most kTextureBudget drawings'
  // worth of the pixel limit, so a forged file cannot fill memory with them.
  if (strands.size() > static_cast<std::size_t>(limits.max_regions)) {
    jr::fail(src, "strands", "at most " + std::to_string(limits.max_regions) + " strands",
             &strands);
  }
  constexpr std::int64_t kTextureBudget = 4;
  std::int64_t texture_pixels = 0;
  std::set<int> ids, region_ids;
  for (std::size_t i = 0; i < strands.size(); ++i) {
    const std::string at = jr::index("strands", i);
    const json& js = strands[i];
    jr::expect_object(js, src, at);
    Strand s;
    s.id = jr::as_int(jr::member(js, src, at, "id"), src, jr::join(at, "id"));
    if (!ids.insert(s.id).second)
      jr::fail(src, jr::join(at, "id"), "a strand id not used before", &js["id"]);
    if (const json* n = jr::optional_member(js, src, at, "name"))
      s.name = jr::as_string(*n, src, jr::join(at, "name"));
    const std::string rkey = jr::join(at, "regions");
    const json& regions = jr::member(js, src, at, "regions");
    jr::expect_array(regions, src, rkey);
    for (std::size_t k = 0; k < regions.size(); ++k) {
      const int r = jr::as_int(regions[k], src, jr::index(rkey, k));
      if (r <= 0) jr::fail(src, jr::index(rkey, k), "a region id > 0", &regions[k]);
      s.regions.push_back(r);
      region_ids.insert(r);
    }
    s.depth = jr::as_int(jr::member(js, src, at, "depth"), src, jr::join(at, "depth"));
    s.outline = read_points(jr::member(js, src, at, "outline"), src, jr::join(at, "outline"));
    if (const json* t = jr::optional_member(js, src, at, "texture")) {
      const std::string tkey = jr::join(at, "texture");
      s.texture = load_image(checked_path(folder, *t, src, tkey), limits);
      if (s.texture.width() > m.width || s.texture.height() > m.height) {
        throw Error(src + ": key '" + tkey + "': texture " + std::to_string(s.texture.width()) +
                    "x" + std::to_string(s.texture.height()) + " is larger than the model's " +
                    std::to_string(m.width) + "x" + std::to_string(m.height) +
                    "; a strand's texture is a part of the drawing");
      }
      texture_pixels += std::int64_t{s.texture.width()} * s.texture.height();
      if (texture_pixels > kTextureBudget * limits.max_pixels) {
        throw Error(src + ": key '" + tkey + "': the strands' textures hold more than " +
                    std::to_string(kTextureBudget * limits.max_pixels) +
                    " pixels together; at most " + std::to_string(kTextureBudget) +
                    " times the image pixel limit are allowed");
      }
      const std::string okey = jr::join(at, "texture_origin");
      const json& origin = jr::member(js, src, at, "texture_origin");
      const Vec2 o = jr::as_point(origin, src, okey);
      // The texture is a crop of the drawing, completed parts reaching at
      // most one drawing size beyond it (checked before the cast to int).
      if (o.x() < -m.width || o.x() > m.width || o.y() < -m.height || o.y() > m.height) {
        jr::fail(src, okey,
                 "an origin within one model size of the drawing (x in " +
                     std::to_string(-m.width) + ".." + std::to_string(m.width) + ", y in " +
                     std::to_string(-m.height) + ".." + std::to_string(m.height) + ")",
                 &origin);
      }
      s.texture_origin = {static_cast<int>(o.x()), static_cast<int>(o.y())};
    }
    s.mesh = read_mesh(jr::member(js, src, at, "mesh"), src, jr::join(at, "mesh"));
    const std::string skey = jr::join(at, "skeleton");
    const json& sk = jr::member(js, src, at, "skeleton");
    jr::expect_object(sk, src, skey);
    s.skeleton.nodes =
        read_points(jr::member(sk, src, skey, "nodes"), src, jr::join(skey, "nodes"));
    const int n = static_cast<int>(s.skeleton.nodes.size());
    for (const char* list : {"parent", "tips"}) {
      const std::string lkey = jr::join(skey, list);
      const json& arr = jr::member(sk, src, skey, list);
      jr::expect_array(arr, src, lkey);
      std::vector<int>& out = std::string(list) == "parent" ? s.skeleton.parent : s.skeleton.tips;
      for (std::size_t k = 0; k < arr.size(); ++k) {
        const int v = jr::as_int(arr[k], src, jr::index(lkey, k));
        const bool root_ok = std::string(list) == "parent" && v == -1;
        if (!root_ok && (v < 0 || v >= n))
          jr::fail(src, jr::index(lkey, k), "a node index in 0.." + std::to_string(n - 1), &arr[k]);
        out.push_back(v);
      }
    }
    if (static_cast<int>(s.skeleton.parent.size()) != n) {
      jr::fail(src, jr::join(skey, "parent"), "one parent per node (" + std::to_string(n) + ")",
               &sk["parent"]);
    }
    // A tree stored root first, every parent before its child: walking up
    // from any node ends at the root, so no reader or solver loops forever.
    for (int k = 0; k < n; ++k) {
      const int p = s.skeleton.parent[static_cast<std::size_t>(k)];
      if (k == 0 ? p != -1 : (p < 0 || p >= k)) {
        jr::fail(src, jr::index(jr::join(skey, "parent"), static_cast<std::size_t>(k)),
                 k == 0 ? std::string("-1 (node 0 is the root)")
                        : "a node index in 0.." + std::to_string(k - 1) +
                              " (parent[i] < i: a parent comes before its child)",
                 &sk["parent"][static_cast<std::size_t>(k)]);
      }
    }
    if (const json* ph = jr::optional_member(js, src, at, "physics")) {
      const std::string pkey = jr::join(at, "physics");
      jr::expect_object(*ph, src, pkey);
      for (auto [key, field] :
           {std::pair{"stiffness", &s.physics.stiffness}, std::pair{"tau0", &s.physics.tau0},
            std::pair{"lambda", &s.physics.lambda}, std::pair{"damping", &s.physics.damping},
            std::pair{"gravity", &s.physics.gravity}}) {
        if (const json* v = jr::optional_member(*ph, src, pkey, key))
          *field = jr::as_number(*v, src, jr::join(pkey, key));
      }
    }
    m.strands.push_back(std::move(s));
  }

  const json& relations = jr::member(doc, src, "", "relations");
  jr::expect_array(relations, src, "relations");
  for (std::size_t i = 0; i < relations.size(); ++i) {
    const std::string at = jr::index("relations", i);
    const json& jr_rel = relations[i];
    jr::expect_object(jr_rel, src, at);
    RegionRelation r;
    for (auto [key, field] : {std::pair{"a", &r.a}, std::pair{"b", &r.b}}) {
      *field = jr::as_int(jr::member(jr_rel, src, at, key), src, jr::join(at, key));
      if (!region_ids.count(*field))
        jr::fail(src, jr::join(at, key), "a region id of some strand", &jr_rel[key]);
    }
    const auto parsed = parse_relation(
        jr::as_string(jr::member(jr_rel, src, at, "relation"), src, jr::join(at, "relation")));
    if (!parsed)
      jr::fail(src, jr::join(at, "relation"), "\"above\", \"below\" or \"equal\"",
               &jr_rel["relation"]);
    r.relation = *parsed;
    if (const json* v = jr::optional_member(jr_rel, src, at, "score"))
      r.score = jr::as_number(*v, src, jr::join(at, "score"));
    if (const json* v = jr::optional_member(jr_rel, src, at, "user_fixed"))
      r.user_fixed = jr::as_bool(*v, src, jr::join(at, "user_fixed"));
    if (const json* v = jr::optional_member(jr_rel, src, at, "overridden"))
      r.overridden = jr::as_bool(*v, src, jr::join(at, "overridden"));
    if (const json* v = jr::optional_member(jr_rel, src, at, "equal_evidence")) {
      const std::string ev = jr::join(at, "equal_evidence");
      jr::expect_object(*v, src, ev);
      EqualEvidence e;
      e.log_odds =
          jr::as_number(jr::member(*v, src, ev, "log_odds"), src, jr::join(ev, "log_odds"));
      e.open = jr::as_bool(jr::member(*v, src, ev, "open"), src, jr::join(ev, "open"));
      e.open_fraction = jr::as_number(jr::member(*v, src, ev, "open_fraction"), src,
                                      jr::join(ev, "open_fraction"));
      r.equal_evidence = e;
    }
    m.relations.push_back(r);
  }
  return m;
}

}  // namespace hair25d
