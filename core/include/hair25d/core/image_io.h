// Image files through OpenImageIO: PNG, JPEG, TIFF, PSD (flattened composite),
// EXR, WebP; 8/16-bit and float; grey, RGB, RGBA — all read into one RGBA8 Image.
// Sizes are checked against limits before any pixel is decoded; label maps'
// region counts after.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "hair25d/core/image.h"

namespace hair25d {

// The limits keep every command within this project's reference machine
// (24 GB): hair25d model held ~235 bytes a pixel (0.98 GB for a 4.2-megapixel
// drawing), ~15 GB at max_pixels; a B4 page scanned at 600 dpi is 52
// megapixels (docs/formats.md, "Limits of every input").
struct ImageLimits {
  int max_side = 16384;                  // pixels, either side
  std::int64_t max_pixels = 64'000'000;  // width × height
  // Label maps: distinct non-zero labels, and 4-connected pieces of one label.
  // The paper's drawings have tens of regions; layering's cost grows with the
  // pieces' junctions (a million one-pixel regions: 160 s and 3.6 GB).
  int max_regions = 4096;
  std::int64_t max_pieces = 16384;

  // False, with a message naming the option, its value and the rule, if unusable.
  bool is_valid(std::string* error) const;
};

// Reads any supported file into RGBA8. Grey is replicated, missing alpha is
// opaque, 16-bit and float are scaled to 8 bits. Throws hair25d::Error naming the
// file for: missing file, not an image, truncated data, zero size, a size
// beyond `limits`.
Image load_image(const std::filesystem::path& path, const ImageLimits& limits = {});

// Reads a single-channel 1- to 16-bit image as integer labels, as stored
// (an annotation's regions.png, a segment label map), then check_label_map.
LabelMap load_label_map(const std::filesystem::path& path, const ImageLimits& limits = {});

// Throws hair25d::Error naming `source` when a region label map breaks a
// rule: a negative label, more than limits.max_regions distinct non-zero
// labels or more than limits.max_pieces pieces. Called where label maps enter
// the pipeline (read from a file, or made by segmentation), before layering.
void check_label_map(const LabelMap& labels, const std::string& source,
                     const ImageLimits& limits = {});

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
