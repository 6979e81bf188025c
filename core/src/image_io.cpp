#include "hair25d/core/image_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <system_error>

#include "hair25d/core/atomic_file.h"
#include "hair25d/core/error.h"
#include "oiio_loader.h"
#include "png_codec.h"

namespace hair25d {

namespace fs = std::filesystem;

bool ImageLimits::is_valid(std::string* error) const {
  if (max_side < 1) {
    if (error) *error = "ImageLimits::max_side = " + std::to_string(max_side) + "; must be >= 1";
    return false;
  }
  if (max_pixels < 1) {
    if (error)
      *error = "ImageLimits::max_pixels = " + std::to_string(max_pixels) + "; must be >= 1";
    return false;
  }
  if (max_regions < 1) {
    if (error)
      *error = "ImageLimits::max_regions = " + std::to_string(max_regions) + "; must be >= 1";
    return false;
  }
  if (max_pieces < 1) {
    if (error)
      *error = "ImageLimits::max_pieces = " + std::to_string(max_pieces) + "; must be >= 1";
    return false;
  }
  return true;
}

namespace {

// The checks every reader makes before decoding, so that a forged header
// cannot make us allocate gigabytes.
void check_file(const fs::path& path, const ImageLimits& limits) {
  std::string why;
  if (!limits.is_valid(&why)) throw Error(why);
  std::error_code ec;
  if (!fs::exists(path, ec)) throw Error(path.string() + ": no such file");
  if (fs::is_directory(path, ec)) throw Error(path.string() + ": is a folder, expected an image");
  if (fs::file_size(path, ec) == 0) throw Error(path.string() + ": the file is empty");
}

void check_header(const fs::path& path, std::int64_t w, std::int64_t h, int channels,
                  const ImageLimits& limits) {
  if (w <= 0 || h <= 0) {
    throw Error(path.string() + ": size " + std::to_string(w) + "x" + std::to_string(h) +
                "; an image must be at least 1x1");
  }
  if (w > limits.max_side || h > limits.max_side) {
    throw Error(path.string() + ": size " + std::to_string(w) + "x" + std::to_string(h) +
                " exceeds the limit of " + std::to_string(limits.max_side) + " pixels a side");
  }
  if (w * h > limits.max_pixels) {
    throw Error(path.string() + ": " + std::to_string(w * h) + " pixels exceed the limit of " +
                std::to_string(limits.max_pixels));
  }
  if (channels < 1) throw Error(path.string() + ": the image has no channels");
}

std::uint8_t quantise(float v) {
  if (!std::isfinite(v)) v = 0.0f;
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

// round(v * 255 / 65535) = round(v / 257), never a tie, in integers.
std::uint8_t sixteen_to_eight(std::uint16_t v) {
  return static_cast<std::uint8_t>((2 * static_cast<std::uint32_t>(v) + 257) / 514);
}

// Grey is replicated, missing alpha is opaque (channels 1..4 as decoded).
template <typename T, typename Convert>
Image to_rgba(const T* values, int w, int h, int channels, int alpha, Convert convert) {
  const bool grey = channels <= 2;
  Image image(w, h);
  Rgba* out = image.data();
  const std::size_t n = static_cast<std::size_t>(w) * h;
  for (std::size_t i = 0; i < n; ++i, values += channels) {
    Rgba& o = out[i];
    if (grey) {
      o.r = o.g = o.b = convert(values[0]);
    } else {
      o.r = convert(values[0]);
      o.g = convert(values[1]);
      o.b = convert(values[2]);
    }
    o.a = alpha >= 0 ? convert(values[alpha]) : 255;
  }
  return image;
}

int default_alpha(int channels) { return channels == 2 || channels >= 4 ? channels - 1 : -1; }

png::Pixels read_png(const fs::path& path, const ImageLimits& limits, png::Samples samples) {
  return png::read(path, samples, [&](const png::Header& h) {
    check_header(path, h.width, h.height, h.channels, limits);
  });
}

oiio_plugin::ReadResult read_other(const fs::path& path, const ImageLimits& limits, bool labels) {
  const oiio_plugin::Api& api = oiio_plugin::api_for(path);
  oiio_plugin::ReadRequest request;
  request.max_side = limits.max_side;
  request.max_pixels = limits.max_pixels;
  request.labels = labels;
  oiio_plugin::ReadResult r;
  api.read(path.c_str(), request, &r);
  using oiio_plugin::Status;
  switch (r.status) {
    case Status::kOk:
      break;
    case Status::kCannotOpen:
      throw Error(path.string() + ": not a readable image (" + r.message + ")");
    case Status::kRefused:
      check_header(path, r.width, r.height, r.channels, limits);
      throw Error(path.string() + ": refused by the size check");
    case Status::kBadType:
      if (r.channels != 1) {
        throw Error(path.string() + ": " + std::to_string(r.channels) + " channels" +
                    (r.alpha_channel >= 0 ? " (one of them alpha)" : "") +
                    "; a label map must be single-channel, without alpha");
      }
      throw Error(path.string() + ": pixel type " + r.type +
                  "; a label map must be 1- to 16-bit unsigned integers");
    case Status::kTooManyChannels:
      throw Error(path.string() + ": " + std::to_string(r.channels) +
                  " channels; an image may have at most " +
                  std::to_string(oiio_plugin::kMaxChannels));
    default:
      throw Error(path.string() + ": cannot decode the pixels (" + r.message + ")");
  }
  return r;
}

bool is_png_name(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".png";
}

// PNG through libpng; any other extension through the OpenImageIO module.
void write_pixels(const fs::path& target, int w, int h, int channels, bool sixteen_bit, bool alpha,
                  const void* data) {
  write_atomically(target, [&](const fs::path& tmp) {
    if (is_png_name(target)) {
      png::write(target, tmp, w, h, channels, sixteen_bit ? 16 : 8, data);
      return;
    }
    oiio_plugin::WriteRequest request;
    request.width = w;
    request.height = h;
    request.channels = channels;
    request.sixteen_bit = sixteen_bit;
    request.alpha_channel = alpha ? channels - 1 : -1;
    request.data = data;
    std::string message;
    const oiio_plugin::Status status =
        oiio_plugin::api_for(target).write(tmp.c_str(), request, &message);
    if (status == oiio_plugin::Status::kCannotCreate)
      throw Error(target.string() + ": cannot write this format (" + message + ")");
    if (status != oiio_plugin::Status::kOk)
      throw Error(target.string() + ": cannot write the image (" + message + ")");
  });
}

}  // namespace

Image load_image(const fs::path& path, const ImageLimits& limits) {
  check_file(path, limits);
  if (png::has_png_signature(path)) {
    const png::Pixels p = read_png(path, limits, png::Samples::kScaled);
    const png::Header& h = p.header;
    const int alpha = default_alpha(h.channels);
    if (h.bit_depth == 16)
      return to_rgba(p.words.data(), h.width, h.height, h.channels, alpha, sixteen_to_eight);
    return to_rgba(p.bytes.data(), h.width, h.height, h.channels, alpha,
                   [](std::uint8_t v) { return v; });
  }
  const oiio_plugin::ReadResult r = read_other(path, limits, false);
  const int alpha = r.alpha_channel >= 0 ? r.alpha_channel : default_alpha(r.channels);
  return to_rgba(r.pixels.data(), r.width, r.height, r.channels, alpha, quantise);
}

LabelMap load_label_map(const fs::path& path, const ImageLimits& limits) {
  check_file(path, limits);
  if (png::has_png_signature(path)) {
    const png::Pixels p = read_png(path, limits, png::Samples::kStored);
    const png::Header& h = p.header;
    if (h.channels != 1) {
      throw Error(path.string() + ": a " + h.stored + " PNG (read as " +
                  std::to_string(h.channels) + " channels" +
                  (h.channels == 2 || h.channels == 4 ? ", one of them alpha" : "") +
                  "); a label map must be single-channel grey, 1 to 16 bits, without alpha or "
                  "transparency");
    }
    LabelMap labels(h.width, h.height);
    int* out = labels.data();
    if (h.bit_depth == 16)
      std::copy(p.words.begin(), p.words.end(), out);
    else
      std::copy(p.bytes.begin(), p.bytes.end(), out);
    check_label_map(labels, path.string(), limits);
    return labels;
  }
  const oiio_plugin::ReadResult r = read_other(path, limits, true);
  // An 8-bit file read as UINT16 is rescaled by OpenImageIO (v * 257): undo it
  // so that labels keep their values.
  LabelMap labels(r.width, r.height);
  for (std::size_t i = 0; i < r.labels.size(); ++i)
    labels.data()[i] = r.eight_bit ? r.labels[i] / 257 : r.labels[i];
  check_label_map(labels, path.string(), limits);
  return labels;
}

void save_image(const fs::path& path, const Image& image) {
  if (image.empty()) throw Error(path.string() + ": refusing to save an empty image");
  write_pixels(path, image.width(), image.height(), 4, false, true, image.bytes());
}

void save_label_map(const fs::path& path, const LabelMap& labels) {
  if (labels.empty()) throw Error(path.string() + ": refusing to save an empty label map");
  std::vector<std::uint16_t> buffer(labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const int v = labels.data()[i];
    if (v < 0 || v > 65535) {
      throw Error(path.string() + ": label " + std::to_string(v) +
                  " cannot be stored; labels must be in [0, 65535]");
    }
    buffer[i] = static_cast<std::uint16_t>(v);
  }
  write_pixels(path, labels.width(), labels.height(), 1, true, false, buffer.data());
}

void save_mask(const fs::path& path, const LabelMap& mask) {
  if (mask.empty()) throw Error(path.string() + ": refusing to save an empty mask");
  std::vector<std::uint8_t> buffer(mask.size());
  for (std::size_t i = 0; i < mask.size(); ++i) buffer[i] = mask.data()[i] != 0 ? 255 : 0;
  write_pixels(path, mask.width(), mask.height(), 1, false, false, buffer.data());
}

}  // namespace hair25d
