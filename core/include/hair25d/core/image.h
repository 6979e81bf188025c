// Raster types shared by all stages: an RGBA8 image (transparent = background)
// and an integer label map (region ids, 0 = background). Row-major, origin at
// the top-left, x right, y down.
#pragma once

#include <cstdint>
#include <vector>

namespace hair25d {

struct Rgba {
  std::uint8_t r = 0, g = 0, b = 0, a = 0;
  friend bool operator==(const Rgba&, const Rgba&) = default;
};

// RGBA8 image, width × height pixels, 4 bytes a pixel.
class Image {
 public:
  Image() = default;
  Image(int width, int height, Rgba fill = {});

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return width_ == 0 || height_ == 0; }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }

  Rgba& at(int x, int y) { return pixels_[static_cast<std::size_t>(y) * width_ + x]; }
  const Rgba& at(int x, int y) const { return pixels_[static_cast<std::size_t>(y) * width_ + x]; }
  Rgba* data() { return pixels_.data(); }
  const Rgba* data() const { return pixels_.data(); }
  std::uint8_t* bytes() { return reinterpret_cast<std::uint8_t*>(pixels_.data()); }
  const std::uint8_t* bytes() const {
    return reinterpret_cast<const std::uint8_t*>(pixels_.data());
  }

  friend bool operator==(const Image&, const Image&) = default;

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<Rgba> pixels_;
};

// One integer per pixel: region or strand ids (0 = background / none).
class LabelMap {
 public:
  LabelMap() = default;
  LabelMap(int width, int height, int fill = 0);

  int width() const { return width_; }
  int height() const { return height_; }
  bool empty() const { return width_ == 0 || height_ == 0; }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }

  int& at(int x, int y) { return labels_[static_cast<std::size_t>(y) * width_ + x]; }
  int at(int x, int y) const { return labels_[static_cast<std::size_t>(y) * width_ + x]; }
  int* data() { return labels_.data(); }
  const int* data() const { return labels_.data(); }
  std::size_t size() const { return labels_.size(); }

  // The distinct non-zero labels, sorted.
  std::vector<int> labels() const;

  friend bool operator==(const LabelMap&, const LabelMap&) = default;

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<int> labels_;
};

}  // namespace hair25d
