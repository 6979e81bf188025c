#include "hair25d/core/image.h"

#include <algorithm>

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
  std::vector<int> out;
  for (int v : labels_) {
    if (v != 0) out.push_back(v);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace hair25d
