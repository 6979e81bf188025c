// PNG through libpng, without OpenImageIO: the drawings, label maps and every
// image of a model folder are PNG, and linking OpenImageIO (with the ~260
// libraries it pulls in) costs ~0.5 s at every program start.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace hair25d::png {

// True if the file starts with the PNG signature.
bool has_png_signature(const std::filesystem::path& path);

struct Header {
  int width = 0;
  int height = 0;
  int channels = 0;   // as decoded: palettes expanded, tRNS as alpha
  int bit_depth = 0;  // 8 or 16 as decoded (1/2/4-bit grey becomes 8, see Samples)
};

// How 1/2/4-bit grey is widened to 8 bits: kScaled to the full range, as
// for images (4-bit 15 -> 255); kStored keeps the stored values, as label
// maps need (4-bit 1 stays 1).
enum class Samples { kScaled, kStored };

// Pixels as decoded, row-major, `channels` interleaved; 16-bit in host order.
struct Pixels {
  Header header;
  std::vector<std::uint8_t> bytes;   // bit_depth 8
  std::vector<std::uint16_t> words;  // bit_depth 16
};

// Reads the header, calls check(header) (which throws to refuse, e.g. a size
// beyond the limits, before anything is decoded), then decodes. Throws
// hair25d::Error naming the file when it is not a readable PNG.
template <typename Check>
Pixels read(const std::filesystem::path& path, Samples samples, Check check);

// The non-template core of read(): check is called through a pointer.
Pixels read_checked(const std::filesystem::path& path, Samples samples,
                    void (*check)(const Header&, const void* context), const void* context);

template <typename Check>
Pixels read(const std::filesystem::path& path, Samples samples, Check check) {
  return read_checked(
      path, samples, [](const Header& h, const void* c) { (*static_cast<const Check*>(c))(h); },
      &check);
}

// Writes `data` (row-major, channels 1-4 interleaved, 8 or 16 bits in host
// order) to `file` (the temporary of an atomic write); messages name `target`.
// Fast rather than small: zlib level 1, no row filters.
void write(const std::filesystem::path& target, const std::filesystem::path& file, int width,
           int height, int channels, int bit_depth, const void* data);

}  // namespace hair25d::png
