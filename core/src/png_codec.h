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
  // As decoded (palettes expanded, tRNS as alpha; 1/2/4-bit grey becomes 8,
  // see Samples); as stored in the header that read()'s check is given.
  int channels = 0;
  int bit_depth = 0;
  // As stored: "grey", "grey+alpha", "palette", "RGB" or "RGBA", with
  // " with a tRNS transparency chunk" when it has one; and its bits per sample.
  std::string stored;
  int stored_bit_depth = 0;
  // The pixel data's size before compression (rows of stored samples, each
  // with its filter byte, as if not interlaced).
  std::uint64_t inflated_bytes = 0;
};

// Deflate compresses at most 1032:1 (a length-258 match in two bits), so a
// file smaller than inflated_bytes / kMaxDeflateRatio cannot hold the pixels
// its header claims: read() refuses it before allocating them.
inline constexpr std::uint64_t kMaxDeflateRatio = 1032;

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
// beyond the limits, before anything is decoded), refuses a file too small
// for the pixels its header claims (kMaxDeflateRatio), then decodes. Throws
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
