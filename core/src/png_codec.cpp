#include "png_codec.h"

#include <png.h>

#include <bit>
#include <cstdio>
#include <memory>
#include <system_error>

#include "hair25d/core/error.h"

namespace hair25d::png {

namespace fs = std::filesystem;

namespace {

// libpng reports errors by longjmp. The functions that call setjmp below hold
// no object with a destructor, so the jump never skips one; the message is
// kept in a string owned by the caller.
void on_error(png_structp png, png_const_charp message) {
  if (auto* out = static_cast<std::string*>(png_get_error_ptr(png))) *out = message;
  png_longjmp(png, 1);
}
void on_warning(png_structp, png_const_charp) {}

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

struct ReadStructs {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~ReadStructs() { png_destroy_read_struct(&png, info ? &info : nullptr, nullptr); }
};

struct WriteStructs {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~WriteStructs() { png_destroy_write_struct(&png, info ? &info : nullptr); }
};

const char* colour_name(int colour) {
  switch (colour) {
    case PNG_COLOR_TYPE_GRAY:
      return "grey";
    case PNG_COLOR_TYPE_GRAY_ALPHA:
      return "grey+alpha";
    case PNG_COLOR_TYPE_PALETTE:
      return "palette";
    case PNG_COLOR_TYPE_RGB:
      return "RGB";
    case PNG_COLOR_TYPE_RGB_ALPHA:
      return "RGBA";
    default:
      return "unknown colour type";
  }
}

// Reads the chunks up to the pixels: the header as stored, nothing
// allocated for rows yet (png_read_update_info allocates a row buffer, 2 GB
// for a forged width of 2^31-1, so the caller's check comes before it).
bool read_info(png_structp png, png_infop info, std::FILE* file, Header* header) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  // libpng's own width/height limit (10^6) would refuse a forged header in its
  // words; the caller's check names our limits instead.
  png_set_user_limits(png, PNG_UINT_31_MAX, PNG_UINT_31_MAX);
  png_read_info(png, info);
  const int colour = png_get_color_type(png, info);
  header->width = static_cast<int>(png_get_image_width(png, info));
  header->height = static_cast<int>(png_get_image_height(png, info));
  header->channels = png_get_channels(png, info);  // as stored until start_decoding
  header->bit_depth = png_get_bit_depth(png, info);
  header->stored_bit_depth = header->bit_depth;
  header->stored = colour_name(colour);
  if (png_get_valid(png, info, PNG_INFO_tRNS)) header->stored += " with a tRNS transparency chunk";
  header->inflated_bytes = static_cast<std::uint64_t>(png_get_image_height(png, info)) *
                           (1 + static_cast<std::uint64_t>(png_get_rowbytes(png, info)));
  return true;
}

// Sets up the same expansions OpenImageIO applies (palette to RGB, 1/2/4-bit
// grey to 8 bits, tRNS to alpha); no gamma conversion: values stay as stored.
// Label maps unpack 1/2/4-bit grey to one byte per pixel without scaling:
// PNG optimisers store maps of <= 15 labels as 4-bit grey, and scaling would
// turn label 1 into 17.
bool start_decoding(png_structp png, png_infop info, Samples samples, Header* header) {
  if (setjmp(png_jmpbuf(png))) return false;
  const int colour = png_get_color_type(png, info);
  const int depth = png_get_bit_depth(png, info);
  if (colour == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (colour == PNG_COLOR_TYPE_GRAY && depth < 8) {
    if (samples == Samples::kStored)
      png_set_packing(png);
    else
      png_set_expand_gray_1_2_4_to_8(png);
  }
  if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
  if (depth == 16 && std::endian::native == std::endian::little) png_set_swap(png);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  header->channels = png_get_channels(png, info);
  header->bit_depth = png_get_bit_depth(png, info);
  return true;
}

bool read_rows(png_structp png, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows);
  png_read_end(png, nullptr);
  return true;
}

bool write_rows(png_structp png, png_infop info, std::FILE* file, int width, int height, int colour,
                int depth, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), depth,
               colour, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // zlib level 1 without row filters: on the model folder's images (flat
  // cel colours, mostly transparent textures) ~4x faster than libpng's
  // default (level 6, every filter tried per row) and no larger; on
  // soft-shaded drawings ~12 % larger (docs/completion.md, whole model).
  png_set_compression_level(png, 1);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_write_info(png, info);
  if (depth == 16 && std::endian::native == std::endian::little) png_set_swap(png);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  return true;
}

std::string or_default(const std::string& message, const char* fallback) {
  return message.empty() ? fallback : message;
}

}  // namespace

bool has_png_signature(const fs::path& path) {
  const File file(std::fopen(path.c_str(), "rb"));
  if (!file) return false;
  png_byte signature[8] = {};
  return std::fread(signature, 1, 8, file.get()) == 8 && png_sig_cmp(signature, 0, 8) == 0;
}

Pixels read_checked(const fs::path& path, Samples samples,
                    void (*check)(const Header&, const void*), const void* context) {
  const File file(std::fopen(path.c_str(), "rb"));
  if (!file) throw Error(path.string() + ": cannot open the file");
  std::string message;
  ReadStructs s;
  s.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &message, on_error, on_warning);
  if (s.png != nullptr) s.info = png_create_info_struct(s.png);
  if (s.png == nullptr || s.info == nullptr) throw Error(path.string() + ": out of memory");
  Pixels out;
  if (!read_info(s.png, s.info, file.get(), &out.header)) {
    throw Error(path.string() + ": not a readable image (" + or_default(message, "bad PNG") + ")");
  }
  const Header& h = out.header;
  check(h, context);
  std::error_code ec;
  const std::uintmax_t file_bytes = fs::file_size(path, ec);
  if (!ec && file_bytes < h.inflated_bytes / kMaxDeflateRatio) {
    throw Error(path.string() + ": truncated: the header says " + std::to_string(h.width) + "x" +
                std::to_string(h.height) + " " + h.stored + " pixels (" +
                std::to_string(h.inflated_bytes) + " bytes uncompressed), which need at least " +
                std::to_string(h.inflated_bytes / kMaxDeflateRatio) +
                " bytes of PNG data (deflate compresses at most 1032:1); the file has " +
                std::to_string(file_bytes));
  }
  if (!start_decoding(s.png, s.info, samples, &out.header)) {
    throw Error(path.string() + ": not a readable image (" + or_default(message, "bad PNG") + ")");
  }
  const std::size_t row_values = static_cast<std::size_t>(h.width) * h.channels;
  std::vector<png_bytep> rows(static_cast<std::size_t>(h.height));
  if (h.bit_depth == 16) {
    out.words.resize(row_values * h.height);
    for (int y = 0; y < h.height; ++y)
      rows[y] = reinterpret_cast<png_bytep>(out.words.data() + row_values * y);
  } else {
    out.bytes.resize(row_values * h.height);
    for (int y = 0; y < h.height; ++y) rows[y] = out.bytes.data() + row_values * y;
  }
  if (!read_rows(s.png, rows.data())) {
    throw Error(path.string() + ": cannot decode the pixels, the file is truncated or corrupt (" +
                or_default(message, "libpng gave no reason") + ")");
  }
  return out;
}

void write(const fs::path& target, const fs::path& file_path, int width, int height, int channels,
           int bit_depth, const void* data) {
  static constexpr int kColour[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA,
                                    PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB_ALPHA};
  if (channels < 1 || channels > 4 || (bit_depth != 8 && bit_depth != 16))
    throw Error(target.string() + ": cannot write " + std::to_string(channels) + " channels of " +
                std::to_string(bit_depth) + " bits as PNG");
  File file(std::fopen(file_path.c_str(), "wb"));
  if (!file) throw Error(target.string() + ": cannot write the image (cannot create the file)");
  std::string message;
  WriteStructs s;
  s.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &message, on_error, on_warning);
  if (s.png != nullptr) s.info = png_create_info_struct(s.png);
  if (s.png == nullptr || s.info == nullptr) throw Error(target.string() + ": out of memory");
  const std::size_t row_bytes = static_cast<std::size_t>(width) * channels * (bit_depth / 8);
  std::vector<png_bytep> rows(static_cast<std::size_t>(height));
  auto* bytes = static_cast<png_bytep>(const_cast<void*>(data));  // libpng does not write to rows
  for (int y = 0; y < height; ++y) rows[y] = bytes + row_bytes * y;
  const bool ok = write_rows(s.png, s.info, file.get(), width, height, kColour[channels - 1],
                             bit_depth, rows.data());
  std::FILE* raw = file.release();
  const bool flushed = std::ferror(raw) == 0;
  const bool closed = std::fclose(raw) == 0;
  if (!ok || !flushed || !closed) {
    throw Error(target.string() + ": cannot write the image (" +
                or_default(message, "write error") + ")");
  }
}

}  // namespace hair25d::png
