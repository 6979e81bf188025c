#include "hair25d/core/image_io.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <system_error>

#include "hair25d/core/atomic_file.h"
#include "hair25d/core/error.h"

namespace hair25d {

namespace fs = std::filesystem;
namespace oiio = OIIO;

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
  return true;
}

namespace {

std::string oiio_message(const std::string& fallback) {
  std::string msg = oiio::geterror();
  if (msg.empty()) msg = fallback;
  // OpenImageIO messages may span lines; our errors are one line.
  std::replace(msg.begin(), msg.end(), '\n', ' ');
  return msg;
}

// The reader's own error, which must be fetched: OpenImageIO keeps it per
// reader and leaks it if nobody asks.
std::string reader_message(oiio::ImageInput& in) {
  std::string msg = in.geterror();
  if (msg.empty()) msg = oiio::geterror();
  if (msg.empty()) msg = "truncated or corrupt";
  std::replace(msg.begin(), msg.end(), '\n', ' ');
  return msg;
}

// Opens `path` and checks its declared size before any pixel is decoded, so a
// forged header cannot make us allocate gigabytes.
std::unique_ptr<oiio::ImageInput> open_checked(const fs::path& path, const ImageLimits& limits,
                                               oiio::ImageSpec* spec) {
  std::string why;
  if (!limits.is_valid(&why)) throw Error(why);
  std::error_code ec;
  if (!fs::exists(path, ec)) throw Error(path.string() + ": no such file");
  if (fs::is_directory(path, ec)) throw Error(path.string() + ": is a folder, expected an image");
  if (fs::file_size(path, ec) == 0) throw Error(path.string() + ": the file is empty");
  // Drawings store straight (unassociated) alpha; OpenImageIO would
  // premultiply on read unless told not to, which darkens soft edges.
  oiio::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = oiio::ImageInput::open(path.string(), &config);
  if (!in) {
    throw Error(path.string() + ": not a readable image (" + oiio_message("unknown format") + ")");
  }
  *spec = in->spec();
  const std::int64_t w = spec->width, h = spec->height;
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
  if (spec->nchannels < 1) throw Error(path.string() + ": the image has no channels");
  return in;
}

}  // namespace

Image load_image(const fs::path& path, const ImageLimits& limits) {
  oiio::ImageSpec spec;
  auto in = open_checked(path, limits, &spec);
  const int w = spec.width, h = spec.height, nc = spec.nchannels;
  // Float read keeps 16-bit and HDR data exact until we quantise once below.
  std::vector<float> buffer(static_cast<std::size_t>(w) * h * nc);
  if (!in->read_image(0, 0, 0, nc, oiio::TypeDesc::FLOAT, buffer.data())) {
    throw Error(path.string() + ": cannot decode the pixels (" + reader_message(*in) + ")");
  }
  in->close();
  const int alpha =
      spec.alpha_channel >= 0 ? spec.alpha_channel : (nc == 2 || nc >= 4 ? nc - 1 : -1);
  const bool grey = nc <= 2;
  auto q = [](float v) {
    if (!std::isfinite(v)) v = 0.0f;
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  Image image(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const float* p = &buffer[(static_cast<std::size_t>(y) * w + x) * nc];
      Rgba& out = image.at(x, y);
      if (grey) {
        out.r = out.g = out.b = q(p[0]);
      } else {
        out.r = q(p[0]);
        out.g = q(p[1]);
        out.b = q(p[2]);
      }
      out.a = alpha >= 0 ? q(p[alpha]) : 255;
    }
  }
  return image;
}

LabelMap load_label_map(const fs::path& path, const ImageLimits& limits) {
  oiio::ImageSpec spec;
  auto in = open_checked(path, limits, &spec);
  const oiio::TypeDesc::BASETYPE base = static_cast<oiio::TypeDesc::BASETYPE>(spec.format.basetype);
  if (base != oiio::TypeDesc::UINT8 && base != oiio::TypeDesc::UINT16) {
    throw Error(path.string() + ": pixel type " + std::string(spec.format.c_str()) +
                "; a label map must be 8- or 16-bit unsigned");
  }
  if (spec.nchannels != 1) {
    throw Error(path.string() + ": " + std::to_string(spec.nchannels) +
                " channels; a label map must have exactly one");
  }
  const int w = spec.width, h = spec.height;
  std::vector<std::uint16_t> buffer(static_cast<std::size_t>(w) * h);
  if (!in->read_image(0, 0, 0, 1, oiio::TypeDesc::UINT16, buffer.data())) {
    throw Error(path.string() + ": cannot decode the pixels (" + reader_message(*in) + ")");
  }
  in->close();
  // An 8-bit file read as UINT16 is rescaled by OpenImageIO (v * 257): undo it
  // so that labels keep their values.
  const bool eight = base == oiio::TypeDesc::UINT8;
  LabelMap labels(w, h);
  for (std::size_t i = 0; i < buffer.size(); ++i) {
    labels.data()[i] = eight ? buffer[i] / 257 : buffer[i];
  }
  return labels;
}

namespace {
void write_pixels(const fs::path& target, const fs::path& tmp, oiio::ImageSpec spec,
                  const void* data) {
  // zlib level 6 (libpng's default) spends most of a model write on
  // compression; level 1 writes several times faster for files ~20% larger.
  spec.attribute("png:compressionLevel", 1);
  auto out = oiio::ImageOutput::create(tmp.string());
  if (!out) {
    throw Error(target.string() + ": cannot write this format (" +
                oiio_message("unknown extension") + ")");
  }
  if (!out->open(tmp.string(), spec) || !out->write_image(spec.format, data) || !out->close()) {
    throw Error(target.string() + ": cannot write the image (" + out->geterror() + ")");
  }
}
}  // namespace

void save_image(const fs::path& path, const Image& image) {
  if (image.empty()) throw Error(path.string() + ": refusing to save an empty image");
  oiio::ImageSpec spec(image.width(), image.height(), 4, oiio::TypeDesc::UINT8);
  spec.alpha_channel = 3;
  spec.attribute("oiio:UnassociatedAlpha", 1);  // our pixels are straight alpha
  write_atomically(path,
                   [&](const fs::path& tmp) { write_pixels(path, tmp, spec, image.bytes()); });
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
  oiio::ImageSpec spec(labels.width(), labels.height(), 1, oiio::TypeDesc::UINT16);
  write_atomically(path,
                   [&](const fs::path& tmp) { write_pixels(path, tmp, spec, buffer.data()); });
}

void save_mask(const fs::path& path, const LabelMap& mask) {
  if (mask.empty()) throw Error(path.string() + ": refusing to save an empty mask");
  std::vector<std::uint8_t> buffer(mask.size());
  for (std::size_t i = 0; i < mask.size(); ++i) buffer[i] = mask.data()[i] != 0 ? 255 : 0;
  oiio::ImageSpec spec(mask.width(), mask.height(), 1, oiio::TypeDesc::UINT8);
  write_atomically(path,
                   [&](const fs::path& tmp) { write_pixels(path, tmp, spec, buffer.data()); });
}

}  // namespace hair25d
