// Image files through OpenImageIO: PNG, JPEG, TIFF, PSD (flattened composite),
// EXR, WebP; 8/16-bit and float; grey, RGB, RGBA — all read into one RGBA8 Image.
// Sizes are checked against limits before any pixel is decoded.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "hair25d/core/image.h"

namespace hair25d {

struct ImageLimits {
  int max_side = 16384;                   // pixels, either side
  std::int64_t max_pixels = 100'000'000;  // width × height

  // False, with a message naming the option, its value and the rule, if unusable.
  bool is_valid(std::string* error) const;
};

// Reads any supported file into RGBA8. Grey is replicated, missing alpha is
// opaque, 16-bit and float are scaled to 8 bits. Throws hair25d::Error naming the
// file for: missing file, not an image, truncated data, zero size, a size
// beyond `limits`.
Image load_image(const std::filesystem::path& path, const ImageLimits& limits = {});

// Reads channel 0 of a single-channel 8- or 16-bit image as integer labels
// (an annotation's regions.png, a segment label map).
LabelMap load_label_map(const std::filesystem::path& path, const ImageLimits& limits = {});

// Writes an 8-bit RGBA PNG (or any format OpenImageIO knows by the extension)
// atomically: a temporary name in the same folder, then a rename.
void save_image(const std::filesystem::path& path, const Image& image);

// Writes labels as a single-channel 16-bit PNG, atomically. Labels must be in
// [0, 65535].
void save_label_map(const std::filesystem::path& path, const LabelMap& labels);

// Writes a mask (non-zero = inside) as a single-channel 8-bit PNG of 0 and
// 255, atomically.
void save_mask(const std::filesystem::path& path, const LabelMap& mask);

}  // namespace hair25d
