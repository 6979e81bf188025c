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
// `stop`: a flood fill per piece, stopped as soon as the count is known to
// be too many, so a map of a million one-pixel regions costs one pass.
std::int64_t count_pieces(const LabelMap& labels, std::int64_t stop) {
  const int w = labels.width(), h = labels.height();
  const int* v = labels.data();
  std::vector<bool> seen(labels.size(), false);
  std::vector<std::int64_t> stack;
  std::int64_t count = 0;
  for (std::size_t start = 0; start < labels.size(); ++start) {
    if (v[start] == 0 || seen[start]) continue;
    if (++count >= stop) return count;
    const int l = v[start];
    seen[start] = true;
    stack.assign(1, static_cast<std::int64_t>(start));
    while (!stack.empty()) {
      const std::int64_t i = stack.back();
      stack.pop_back();
      const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
      const auto visit = [&](std::int64_t j) {
        if (v[j] == l && !seen[j]) {
          seen[j] = true;
          stack.push_back(j);
        }
      };
      if (x > 0) visit(i - 1);
      if (x + 1 < w) visit(i + 1);
      if (y > 0) visit(i - w);
      if (y + 1 < h) visit(i + w);
    }
  }
  return count;
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
