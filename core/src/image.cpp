#include "hair25d/core/image.h"

#include <algorithm>
#include <cstdint>

#include "hair25d/core/error.h"

namespace hair25d {

namespace {
void check_size(int width, int height, const char* what) {
  if (width < 0 || height < 0) {
    throw Error(std::string(what) + " size " + std::to_string(width) + "x" +
                std::to_string(height) + " is negative; sizes must be >= 0");
  }
}
}  // namespace

Image::Image(int width, int height, Rgba fill) : width_(width), height_(height) {
  check_size(width, height, "Image");
  pixels_.assign(static_cast<std::size_t>(width) * height, fill);
}

LabelMap::LabelMap(int width, int height, int fill) : width_(width), height_(height) {
  check_size(width, height, "LabelMap");
  labels_.assign(static_cast<std::size_t>(width) * height, fill);
}

std::vector<int> LabelMap::labels() const {
  // Labels 1..65535 (every map read from a PNG) are marked in a table; the
  // others, if any, sorted: negatives before the table's, larger ones after.
  constexpr int kTable = 65536;
  std::vector<std::uint8_t> seen;
  std::vector<int> other;
  int last = 0;  // runs of one label are marked once
  for (int v : labels_) {
    if (v == 0 || v == last) continue;
    last = v;
    if (v > 0 && v < kTable) {
      if (seen.empty()) seen.assign(kTable, 0);
      seen[v] = 1;
    } else {
      other.push_back(v);
    }
  }
  std::sort(other.begin(), other.end());
  other.erase(std::unique(other.begin(), other.end()), other.end());
  std::vector<int> out;
  auto large = std::lower_bound(other.begin(), other.end(), kTable);
  out.insert(out.end(), other.begin(), large);
  if (!seen.empty())
    for (int v = 1; v < kTable; ++v)
      if (seen[v]) out.push_back(v);
  out.insert(out.end(), large, other.end());
  return out;
}

}  // namespace hair25d
