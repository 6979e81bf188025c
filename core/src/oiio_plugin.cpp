// libhair25d_core_oiio: OpenImageIO behind oiio_plugin.h, loaded by core's
// image I/O only when a file is not PNG.
#include "oiio_plugin.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace hair25d::oiio_plugin {
namespace {

namespace oiio = OIIO;

std::string one_line(std::string message, const char* fallback) {
  if (message.empty()) message = fallback;
  std::replace(message.begin(), message.end(), '\n', ' ');
  // libtiff reports every failing scanline: the first few say it all.
  if (message.size() > 300) message = message.substr(0, 297) + "...";
  return message;
}

// An uncompressed TIFF smaller than the pixels its header claims: refused
// before they are allocated (a 118-byte file claiming 4000 x 4000 x 60
// channels of 16 bits took 71 s and 3.9 GB to fail). Compressed data has no
// such bound.
bool too_small_for_its_pixels(const char* path, oiio::ImageInput& in, std::string* message) {
  const oiio::ImageSpec& spec = in.spec();
  if (std::string(in.format_name()) != "tiff" ||
      spec.get_string_attribute("compression", "none") != "none")
    return false;
  std::error_code ec;
  const std::uintmax_t file_bytes = std::filesystem::file_size(path, ec);
  const int bits =
      spec.get_int_attribute("oiio:BitsPerSample", static_cast<int>(spec.format.size() * 8));
  const std::uint64_t row_bits = std::uint64_t(spec.width) * spec.nchannels * bits;
  const std::uint64_t need = (row_bits + 7) / 8 * std::uint64_t(spec.height);
  if (ec || file_bytes >= need) return false;
  *message = "truncated: the header says " + std::to_string(spec.width) + "x" +
             std::to_string(spec.height) + ", " + std::to_string(spec.nchannels) +
             " channel(s) of " + std::to_string(bits) +
             " bits, uncompressed: " + std::to_string(need) + " bytes of pixels; the file has " +
             std::to_string(file_bytes);
  return true;
}

// The reader's own error, which must be fetched: OpenImageIO keeps it per
// reader and leaks it if nobody asks.
std::string reader_message(oiio::ImageInput& in) {
  std::string message = in.geterror();
  if (message.empty()) message = oiio::geterror();
  return one_line(message, "truncated or corrupt");
}

void read_impl(const char* path, const ReadRequest& request, ReadResult* result) {
  // Drawings store straight (unassociated) alpha; OpenImageIO would
  // premultiply on read unless told not to, which darkens soft edges.
  oiio::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = oiio::ImageInput::open(path, &config);
  if (!in) {
    result->status = Status::kCannotOpen;
    result->message = one_line(oiio::geterror(), "unknown format");
    return;
  }
  const oiio::ImageSpec& spec = in->spec();
  result->width = spec.width;
  result->height = spec.height;
  result->channels = spec.nchannels;
  result->alpha_channel = spec.alpha_channel;
  result->type = spec.format.c_str();
  const std::int64_t w = spec.width, h = spec.height;
  if (w <= 0 || h <= 0 || w > request.max_side || h > request.max_side ||
      w * h > request.max_pixels || spec.nchannels < 1) {
    // Refused before any pixel is decoded: a forged header cannot make us
    // allocate gigabytes.
    result->status = Status::kRefused;
    return;
  }
  if (spec.nchannels > kMaxChannels) {
    result->status = Status::kTooManyChannels;
    return;
  }
  if (too_small_for_its_pixels(path, *in, &result->message)) {
    result->status = Status::kCannotDecode;
    return;
  }
  const std::size_t pixels = static_cast<std::size_t>(w * h);
  bool ok = false;
  if (request.labels) {
    const auto base = static_cast<oiio::TypeDesc::BASETYPE>(spec.format.basetype);
    if ((base != oiio::TypeDesc::UINT8 && base != oiio::TypeDesc::UINT16) || spec.nchannels != 1) {
      result->status = Status::kBadType;
      return;
    }
    result->eight_bit = base == oiio::TypeDesc::UINT8;
    result->labels.resize(pixels);
    ok = in->read_image(0, 0, 0, 1, oiio::TypeDesc::UINT16, result->labels.data());
    // Files of fewer bits come scaled to the full range of their type (TIFF
    // 4-bit 1 -> 8-bit 17, 12-bit 1 -> 16-bit 16): give the stored labels
    // back, 1..7 bits as 8-bit values that core unscales from 16 bits.
    const int bits = spec.get_int_attribute("oiio:BitsPerSample", result->eight_bit ? 8 : 16);
    if (ok && result->eight_bit && bits >= 1 && bits < 8) {
      const int top = (1 << bits) - 1;
      for (std::uint16_t& v : result->labels)
        v = static_cast<std::uint16_t>((v / 257 * top + 127) / 255 * 257);
    } else if (ok && !result->eight_bit && bits > 8 && bits < 16) {
      const std::uint32_t top = (1u << bits) - 1;
      for (std::uint16_t& v : result->labels)
        v = static_cast<std::uint16_t>((v * top + 32767) / 65535);
    }
  } else {
    // Float keeps 16-bit and HDR data exact until core quantises once. At
    // most four channels are read: colour and alpha (alpha beyond the
    // fourth channel is read on its own into the fourth place).
    const int read = std::min(spec.nchannels, 4);
    const bool far_alpha = spec.alpha_channel >= read;
    result->channels = read;
    result->alpha_channel = far_alpha ? 3 : spec.alpha_channel;
    result->pixels.resize(pixels * read);
    ok = in->read_image(0, 0, 0, far_alpha ? 3 : read, oiio::TypeDesc::FLOAT, result->pixels.data(),
                        read * sizeof(float));
    if (ok && far_alpha)
      ok = in->read_image(0, 0, spec.alpha_channel, spec.alpha_channel + 1, oiio::TypeDesc::FLOAT,
                          result->pixels.data() + 3, read * sizeof(float));
  }
  // read_image's result is not enough: libjpeg only warns about a truncated
  // stream (the missing rows come back grey) and OpenImageIO still returns
  // true, with the warning left as the reader's error text.
  if (!ok || in->has_error()) {
    result->status = Status::kCannotDecode;
    result->message = reader_message(*in);
    return;
  }
  if (!in->close() || in->has_error()) {
    result->status = Status::kCannotDecode;
    result->message = reader_message(*in);
    return;
  }
  result->status = Status::kOk;
}

Status write_impl(const char* path, const WriteRequest& request, std::string* message) {
  const oiio::TypeDesc type = request.sixteen_bit ? oiio::TypeDesc::UINT16 : oiio::TypeDesc::UINT8;
  oiio::ImageSpec spec(request.width, request.height, request.channels, type);
  if (request.alpha_channel >= 0) {
    spec.alpha_channel = request.alpha_channel;
    spec.attribute("oiio:UnassociatedAlpha", 1);  // our pixels are straight alpha
  }
  auto out = oiio::ImageOutput::create(path);
  if (!out) {
    *message = one_line(oiio::geterror(), "unknown extension");
    return Status::kCannotCreate;
  }
  if (!out->open(path, spec) || !out->write_image(type, request.data) || !out->close()) {
    *message = one_line(out->geterror(), "write error");
    return Status::kCannotWrite;
  }
  return Status::kOk;
}

void read_entry(const char* path, const ReadRequest& request, ReadResult* result) {
  try {
    read_impl(path, request, result);
  } catch (const std::exception& e) {
    // Before a size is known the reader failed on the header: not an image
    // it can read (a GIF signature over garbage threw length_error).
    result->status = result->width > 0 ? Status::kCannotDecode : Status::kCannotOpen;
    result->message = one_line(e.what(), "error");
  }
}

Status write_entry(const char* path, const WriteRequest& request, std::string* message) {
  try {
    return write_impl(path, request, message);
  } catch (const std::exception& e) {
    *message = one_line(e.what(), "error");
    return Status::kCannotWrite;
  }
}

constexpr Api kApi{kAbiVersion, read_entry, write_entry};

}  // namespace
}  // namespace hair25d::oiio_plugin

extern "C" __attribute__((visibility("default"))) const hair25d::oiio_plugin::Api*
hair25d_core_oiio_api() {
  return &hair25d::oiio_plugin::kApi;
}
