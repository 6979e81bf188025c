// Annotated layering cases ("hair25d-layering-annotation/1", FORMATS.md): the
// input of eval-layering and the ground truth of accuracy tests.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hair25d/core/geometry.h"
#include "hair25d/core/image.h"
#include "hair25d/core/image_io.h"
#include "hair25d/core/strokes.h"

namespace hair25d {

enum class Relation { kBelow = -1, kEqual = 0, kAbove = 1 };

const char* to_string(Relation r);
// Parses "above" / "below" / "equal"; nullopt otherwise.
std::optional<Relation> parse_relation(const std::string& text);
// The relation of b to a given the relation of a to b.
Relation reversed(Relation r);

struct AnnotatedRegion {
  int id = 0;
  int strand = 0;
  std::string name;
};

struct AnnotatedPair {
  int a = 0;
  int b = 0;
  Relation relation = Relation::kEqual;  // where a lies relative to b
};

struct AnnotatedCase {
  std::string name;  // the folder's name
  std::filesystem::path folder;
  Image image;
  LabelMap regions;  // 0 = background and outlines
  std::optional<Vec2> head_center;
  std::vector<AnnotatedRegion> region_list;
  std::vector<AnnotatedPair> pairs;
  std::optional<Strokes> strokes;        // strokes.json if present
  std::map<int, LabelMap> strand_masks;  // strands/S.png: 1 inside, 0 outside
};

// Reads one case folder; throws hair25d::Error naming the file, key and rule
// (a pair naming an unknown region, regions.png of another size than the image...).
AnnotatedCase read_annotated_case(const std::filesystem::path& folder,
                                  const ImageLimits& limits = {});

// The sub-folders of `root` that hold a layering.json, sorted by name.
std::vector<std::filesystem::path> find_annotated_cases(const std::filesystem::path& root);
// The name of the case in `folder` (its last path part; "cases/c1/" is "c1").
std::string annotated_case_name(const std::filesystem::path& folder);

// Writes a case folder (used by the synthetic generator).
void write_annotated_case(const std::filesystem::path& folder, const AnnotatedCase& c);

}  // namespace hair25d
