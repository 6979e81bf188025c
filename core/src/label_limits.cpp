#include <cstdint>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "hair25d/core/error.h"
#include "hair25d/core/image_io.h"

namespace hair25d {

namespace {

std::string at_pixel(const LabelMap& labels, std::size_t i) {
  const auto w = static_cast<std::size_t>(labels.width());
  std::string out = "(";  // appended, not "(" + ...: GCC 12 warns falsely (-Wrestrict)
  out += std::to_string(i % w) + ", " + std::to_string(i / w) + ")";
  return out;
}

// Distinct non-zero labels, counting no further than `stop`.
std::int64_t count_regions(const LabelMap& labels, std::int64_t stop) {
  std::vector<std::uint8_t> small(65536, 0);  // the labels a 16-bit file can hold
  std::unordered_set<int> large;
  std::int64_t count = 0;
  const int* v = labels.data();
  for (std::size_t i = 0; i < labels.size() && count < stop; ++i) {
    const int l = v[i];
    if (l == 0) continue;
    const bool fresh = l < 65536 ? !std::exchange(small[l], 1) : large.insert(l).second;
    count += fresh ? 1 : 0;
  }
  return count;
}

// 4-connected pieces of equal non-zero labels, counting no further than
// `stop`: the rows' runs of one label, joined (union-find) to the runs of the
// same label they touch in the row above; a piece is a run less the joins.
// One pass over the pixels, and as many runs as pixels at worst.
std::int64_t count_pieces(const LabelMap& labels, std::int64_t stop) {
  const int w = labels.width(), h = labels.height();
  const int* v = labels.data();
  struct Run {
    int x0, x1;  // [x0, x1)
    int label;
  };
  std::vector<Run> above, row;
  std::vector<std::int64_t> parent;
  std::vector<std::int64_t> above_id, row_id;
  const auto find = [&](std::int64_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  std::int64_t count = 0;
  for (int y = 0; y < h; ++y) {
    const int* r = v + static_cast<std::size_t>(y) * w;
    row.clear();
    row_id.clear();
    for (int x = 0; x < w;) {
      const int l = r[x];
      int e = x + 1;
      while (e < w && r[e] == l) ++e;
      if (l != 0) {
        row.push_back({x, e, l});
        row_id.push_back(static_cast<std::int64_t>(parent.size()));
        parent.push_back(static_cast<std::int64_t>(parent.size()));
        ++count;
      }
      x = e;
    }
    // Runs of both rows are sorted by x: walk them together.
    std::size_t j = 0;
    for (std::size_t i = 0; i < row.size(); ++i) {
      while (j < above.size() && above[j].x1 <= row[i].x0) ++j;
      for (std::size_t k = j; k < above.size() && above[k].x0 < row[i].x1; ++k) {
        if (above[k].label != row[i].label) continue;
        const std::int64_t a = find(above_id[k]), b = find(row_id[i]);
        if (a != b) parent[a] = b, --count;
      }
    }
    std::swap(above, row);
    std::swap(above_id, row_id);
  }
  return std::min(count, stop);
}

}  // namespace

void check_label_map(const LabelMap& labels, const std::string& source, const ImageLimits& limits) {
  std::string why;
  if (!limits.is_valid(&why)) throw Error(why);
  const int* v = labels.data();
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (v[i] < 0) {
      throw Error(source + ": label " + std::to_string(v[i]) + " at " + at_pixel(labels, i) +
                  "; region labels must be >= 0 (0 = not a hair region)");
    }
  }
  const std::int64_t regions = count_regions(labels, limits.max_regions + std::int64_t{1});
  if (regions > limits.max_regions) {
    throw Error(source + ": more than " + std::to_string(limits.max_regions) +
                " regions (distinct non-zero labels); at most " +
                std::to_string(limits.max_regions) +
                " are allowed (a drawing's hair has tens of regions)");
  }
  const std::int64_t pieces = count_pieces(labels, limits.max_pieces + 1);
  if (pieces > limits.max_pieces) {
    throw Error(source + ": more than " + std::to_string(limits.max_pieces) +
                " separate pieces of regions (4-connected areas of one label); at most " +
                std::to_string(limits.max_pieces) +
                " are allowed (a map of scattered pixels would make layering take hours)");
  }
}

}  // namespace hair25d
