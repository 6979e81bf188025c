#include "hair25d/core/annotation.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "hair25d/core/atomic_file.h"
#include "json_read.h"

namespace hair25d {

namespace fs = std::filesystem;
namespace jr = json_read;
using nlohmann::json;

inline constexpr const char* kAnnotationFormat = "hair25d-layering-annotation/1";

const char* to_string(Relation r) {
  switch (r) {
    case Relation::kAbove:
      return "above";
    case Relation::kBelow:
      return "below";
    case Relation::kEqual:
      return "equal";
  }
  return "equal";
}

std::optional<Relation> parse_relation(const std::string& text) {
  if (text == "above") return Relation::kAbove;
  if (text == "below") return Relation::kBelow;
  if (text == "equal") return Relation::kEqual;
  return std::nullopt;
}

Relation reversed(Relation r) { return static_cast<Relation>(-static_cast<int>(r)); }

namespace {

// A relative path inside the case folder: no absolute paths, no "..".
fs::path inside(const fs::path& folder, const std::string& rel, const std::string& source,
                const std::string& key) {
  const fs::path p(rel);
  if (rel.empty() || p.is_absolute() ||
      std::any_of(p.begin(), p.end(), [](const fs::path& part) { return part == ".."; })) {
    const json got = rel;
    jr::fail(source, key, "a relative path inside the case folder", &got);
  }
  return folder / p;
}

}  // namespace

AnnotatedCase read_annotated_case(const fs::path& folder, const ImageLimits& limits) {
  const fs::path json_path = folder / "layering.json";
  const std::string source = json_path.string();
  const json doc = jr::parse(read_text_file(json_path), source);
  jr::expect_object(doc, source, "");
  const std::string format = jr::as_string(jr::member(doc, source, "", "format"), source, "format");
  if (format != kAnnotationFormat) {
    jr::fail(source, "format", std::string("\"") + kAnnotationFormat + "\"", &doc["format"]);
  }
  AnnotatedCase c;
  c.folder = folder;
  c.name = annotated_case_name(folder);

  std::string image_rel = "image.png", regions_rel = "regions.png";
  if (const json* v = jr::optional_member(doc, source, "", "image"))
    image_rel = jr::as_string(*v, source, "image");
  if (const json* v = jr::optional_member(doc, source, "", "regions_image")) {
    regions_rel = jr::as_string(*v, source, "regions_image");
  }
  c.image = load_image(inside(folder, image_rel, source, "image"), limits);
  const fs::path regions_path = inside(folder, regions_rel, source, "regions_image");
  c.regions = load_label_map(regions_path, limits);
  if (c.regions.width() != c.image.width() || c.regions.height() != c.image.height()) {
    throw Error(regions_path.string() + ": size " + std::to_string(c.regions.width()) + "x" +
                std::to_string(c.regions.height()) + " differs from the image's " +
                std::to_string(c.image.width()) + "x" + std::to_string(c.image.height()) +
                "; they must be equal");
  }
  if (const json* v = jr::optional_member(doc, source, "", "head_center")) {
    c.head_center = jr::as_point(*v, source, "head_center");
  }

  const json& regions = jr::member(doc, source, "", "regions");
  jr::expect_array(regions, source, "regions");
  std::set<int> ids;
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const std::string at = jr::index("regions", i);
    jr::expect_object(regions[i], source, at);
    AnnotatedRegion r;
    r.id = jr::as_int(jr::member(regions[i], source, at, "id"), source, jr::join(at, "id"));
    if (r.id <= 0 || r.id > 65535)
      jr::fail(source, jr::join(at, "id"), "an id in 1..65535", &regions[i]["id"]);
    if (!ids.insert(r.id).second)
      jr::fail(source, jr::join(at, "id"), "an id not used before", &regions[i]["id"]);
    r.strand =
        jr::as_int(jr::member(regions[i], source, at, "strand"), source, jr::join(at, "strand"));
    if (const json* n = jr::optional_member(regions[i], source, at, "name")) {
      r.name = jr::as_string(*n, source, jr::join(at, "name"));
    }
    c.region_list.push_back(r);
  }

  const json& pairs = jr::member(doc, source, "", "pairs");
  jr::expect_array(pairs, source, "pairs");
  const std::vector<int> drawn = c.regions.labels();
  // Each unordered pair of regions once: a repeat would count twice in the
  // accuracy and a contradiction has no right answer. Value: the index of
  // the pair that listed it and its relation, seen from the smaller id.
  std::map<std::pair<int, int>, std::pair<std::size_t, Relation>> listed;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const std::string at = jr::index("pairs", i);
    jr::expect_object(pairs[i], source, at);
    AnnotatedPair p;
    for (auto [key, field] : {std::pair{"a", &p.a}, std::pair{"b", &p.b}}) {
      *field = jr::as_int(jr::member(pairs[i], source, at, key), source, jr::join(at, key));
      if (!ids.count(*field)) {
        jr::fail(source, jr::join(at, key), "the id of a region listed in 'regions'",
                 &pairs[i][key]);
      }
      if (!std::binary_search(drawn.begin(), drawn.end(), *field)) {
        jr::fail(source, jr::join(at, key),
                 "the id of a region drawn in " + regions_path.filename().string() +
                     " (no pixel has this label)",
                 &pairs[i][key]);
      }
    }
    if (p.a == p.b) jr::fail(source, at, "two different regions", &pairs[i]);
    const std::string rel = jr::as_string(jr::member(pairs[i], source, at, "relation"), source,
                                          jr::join(at, "relation"));
    const auto parsed = parse_relation(rel);
    if (!parsed)
      jr::fail(source, jr::join(at, "relation"), "\"above\", \"below\" or \"equal\"",
               &pairs[i]["relation"]);
    p.relation = *parsed;
    const bool swapped = p.a > p.b;
    const Relation seen = swapped ? reversed(p.relation) : p.relation;
    const auto [it, fresh] = listed.try_emplace({std::min(p.a, p.b), std::max(p.a, p.b)}, i, seen);
    if (!fresh) {
      const std::string before = jr::index("pairs", it->second.first);
      jr::fail(source, at,
               it->second.second == seen
                   ? "each pair of regions listed once; " + before + " lists it already"
                   : "a relation that agrees with " + before +
                         " (the same two regions with another relation)",
               &pairs[i]);
    }
    c.pairs.push_back(p);
  }

  const fs::path strokes_path = folder / "strokes.json";
  if (fs::exists(strokes_path)) c.strokes = read_strokes(strokes_path);

  const fs::path strands = folder / "strands";
  if (fs::is_directory(strands)) {
    for (const auto& entry : fs::directory_iterator(strands)) {
      if (entry.path().extension() != ".png") continue;
      int strand = 0;
      try {
        std::size_t used = 0;
        strand = std::stoi(entry.path().stem().string(), &used);
        if (used != entry.path().stem().string().size()) continue;
      } catch (const std::exception&) {
        continue;  // not a strand mask (S.png names a strand id)
      }
      const Image mask = load_image(entry.path(), limits);
      if (mask.width() != c.image.width() || mask.height() != c.image.height()) {
        throw Error(entry.path().string() +
                    ": size differs from the image's; strand masks must match it");
      }
      LabelMap m(mask.width(), mask.height());
      for (int y = 0; y < mask.height(); ++y) {
        for (int x = 0; x < mask.width(); ++x) m.at(x, y) = mask.at(x, y).r > 127 ? 1 : 0;
      }
      c.strand_masks.emplace(strand, std::move(m));
    }
  }
  return c;
}

std::string annotated_case_name(const fs::path& folder) {
  return folder.has_filename() ? folder.filename().string()
                               : folder.parent_path().filename().string();
}

std::vector<fs::path> find_annotated_cases(const fs::path& root) {
  std::error_code ec;
  if (!fs::is_directory(root, ec)) throw Error(root.string() + ": not a folder of annotated cases");
  std::vector<fs::path> out;
  if (fs::exists(root / "layering.json")) out.push_back(root);
  for (const auto& entry : fs::directory_iterator(root)) {
    if (entry.is_directory() && fs::exists(entry.path() / "layering.json"))
      out.push_back(entry.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

void write_annotated_case(const fs::path& folder, const AnnotatedCase& c) {
  write_folder_atomically(
      folder,
      [&](const fs::path& tmp) {
        save_image(tmp / "image.png", c.image);
        save_label_map(tmp / "regions.png", c.regions);
        json doc;
        doc["format"] = kAnnotationFormat;
        doc["image"] = "image.png";
        doc["regions_image"] = "regions.png";
        if (c.head_center) doc["head_center"] = {c.head_center->x(), c.head_center->y()};
        json regions = json::array();
        for (const AnnotatedRegion& r : c.region_list) {
          regions.push_back({{"id", r.id}, {"strand", r.strand}, {"name", r.name}});
        }
        doc["regions"] = regions;
        json pairs = json::array();
        for (const AnnotatedPair& p : c.pairs) {
          pairs.push_back({{"a", p.a}, {"b", p.b}, {"relation", to_string(p.relation)}});
        }
        doc["pairs"] = pairs;
        write_text_atomically(tmp / "layering.json", doc.dump(1) + "\n");
        if (c.strokes) write_strokes(tmp / "strokes.json", *c.strokes);
        if (!c.strand_masks.empty()) {
          fs::create_directory(tmp / "strands");
          for (const auto& [strand, mask] : c.strand_masks) {
            save_mask(tmp / "strands" / (std::to_string(strand) + ".png"), mask);
          }
        }
      },
      "annotated case");
}

}  // namespace hair25d
