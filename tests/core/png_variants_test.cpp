// PNG is read with libpng directly (core/src/png_codec.cpp) and everything
// else with OpenImageIO: every PNG layout must decode exactly as OpenImageIO
// decodes it, and the model-folder writes must round-trip.
#include <gtest/gtest.h>
#include <png.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <set>
#include <vector>

#include "common/temp_dir.h"
#include "hair25d/core/error.h"
#include "hair25d/core/image_io.h"

namespace hair25d {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

struct Layout {
  const char* name;
  int colour;  // PNG_COLOR_TYPE_*
  int depth;
  bool interlaced;
  bool trns;  // a tRNS chunk (palette alpha, or one transparent grey / RGB value)
};

// Writes a w × h PNG of the given layout with varied values, using libpng.
bool write_layout(const fs::path& path, const Layout& l, int w, int h) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) return false;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  const int channels = l.colour == PNG_COLOR_TYPE_GRAY         ? 1
                       : l.colour == PNG_COLOR_TYPE_GRAY_ALPHA ? 2
                       : l.colour == PNG_COLOR_TYPE_RGB        ? 3
                       : l.colour == PNG_COLOR_TYPE_RGB_ALPHA  ? 4
                                                               : 1;
  const int bytes_per_sample = l.depth == 16 ? 2 : 1;
  const int samples_per_byte = l.depth < 8 ? 8 / l.depth : 1;
  const std::size_t row_bytes =
      l.depth < 8 ? (static_cast<std::size_t>(w) + samples_per_byte - 1) / samples_per_byte
                  : static_cast<std::size_t>(w) * channels * bytes_per_sample;
  std::vector<png_byte> data(row_bytes * h, 0);
  for (int y = 0; y < h; ++y)
    for (std::size_t i = 0; i < row_bytes; ++i)
      data[y * row_bytes + i] = static_cast<png_byte>((i * 37 + y * 91 + (i * y) % 13) & 255);
  std::vector<png_bytep> rows(h);
  for (int y = 0; y < h; ++y) rows[y] = data.data() + y * row_bytes;
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
    return false;
  }
  png_init_io(png, f);
  png_set_IHDR(png, info, w, h, l.depth, l.colour,
               l.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  std::vector<png_color> palette(256);
  std::vector<png_byte> alpha(256);
  for (int i = 0; i < 256; ++i) {
    palette[i] = {static_cast<png_byte>(i), static_cast<png_byte>(255 - i),
                  static_cast<png_byte>(i * 7)};
    alpha[i] = static_cast<png_byte>(i * 3);
  }
  if (l.colour == PNG_COLOR_TYPE_PALETTE) {
    png_set_PLTE(png, info, palette.data(), 1 << l.depth);
    if (l.trns) png_set_tRNS(png, info, alpha.data(), 1 << l.depth, nullptr);
  } else if (l.trns) {
    png_color_16 key{};
    key.gray = 37 % (1 << std::min(l.depth, 15));
    key.red = 0, key.green = 37, key.blue = 74;  // pixel (0, 0) of the RGB pattern
    png_set_tRNS(png, info, nullptr, 0, &key);
  }
  png_write_info(png, info);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return std::fclose(f) == 0;
}

// OpenImageIO's reading, quantised as core did before PNG went to libpng.
Image oiio_reference(const fs::path& path) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path.string(), &config);
  if (!in) return {};
  const OIIO::ImageSpec spec = in->spec();
  const int w = spec.width, h = spec.height, nc = spec.nchannels;
  std::vector<float> buf(static_cast<std::size_t>(w) * h * nc);
  if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, buf.data())) return {};
  const int alpha =
      spec.alpha_channel >= 0 ? spec.alpha_channel : (nc == 2 || nc >= 4 ? nc - 1 : -1);
  auto q = [](float v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  Image out(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float* p = &buf[(static_cast<std::size_t>(y) * w + x) * nc];
      Rgba& o = out.at(x, y);
      if (nc <= 2) {
        o.r = o.g = o.b = q(p[0]);
      } else {
        o.r = q(p[0]), o.g = q(p[1]), o.b = q(p[2]);
      }
      o.a = alpha >= 0 ? q(p[alpha]) : 255;
    }
  return out;
}

TEST(PngVariants, EveryLayoutDecodesAsOpenImageIoDoes) {
  TempDir dir;
  const Layout layouts[] = {
      {"grey1", PNG_COLOR_TYPE_GRAY, 1, false, false},
      {"grey2", PNG_COLOR_TYPE_GRAY, 2, false, false},
      {"grey4_trns", PNG_COLOR_TYPE_GRAY, 4, false, true},
      {"grey8_trns", PNG_COLOR_TYPE_GRAY, 8, false, true},
      {"grey16_interlaced", PNG_COLOR_TYPE_GRAY, 16, true, false},
      {"grey_alpha16", PNG_COLOR_TYPE_GRAY_ALPHA, 16, false, false},
      {"rgb8_trns", PNG_COLOR_TYPE_RGB, 8, false, true},
      {"rgb16", PNG_COLOR_TYPE_RGB, 16, false, false},
      {"rgba8_interlaced", PNG_COLOR_TYPE_RGB_ALPHA, 8, true, false},
      {"rgba16", PNG_COLOR_TYPE_RGB_ALPHA, 16, false, false},
      {"palette2", PNG_COLOR_TYPE_PALETTE, 2, false, false},
      {"palette8", PNG_COLOR_TYPE_PALETTE, 8, false, false},
      {"palette8_trns_interlaced", PNG_COLOR_TYPE_PALETTE, 8, true, true},
  };
  for (const Layout& l : layouts) {
    const fs::path path = dir / (std::string(l.name) + ".png");
    ASSERT_TRUE(write_layout(path, l, 23, 11)) << l.name;
    const Image expected = oiio_reference(path);
    ASSERT_FALSE(expected.empty()) << l.name;
    const Image got = load_image(path);
    ASSERT_EQ(got.width(), 23) << l.name;
    ASSERT_EQ(got.height(), 11) << l.name;
    int differ = 0;
    for (int y = 0; y < 11; ++y)
      for (int x = 0; x < 23; ++x) differ += !(got.at(x, y) == expected.at(x, y));
    EXPECT_EQ(differ, 0) << l.name;
    // Not constant: the layout's values really vary (so equality means something).
    std::set<std::uint32_t> distinct;
    for (int i = 0; i < 23 * 11; ++i) {
      const Rgba p = got.data()[i];
      distinct.insert(p.r | p.g << 8 | p.b << 16 | static_cast<std::uint32_t>(p.a) << 24);
    }
    EXPECT_GE(distinct.size(), 2u) << l.name;
    if (l.trns) {
      bool some_transparent = false;
      for (int i = 0; i < 23 * 11; ++i) some_transparent |= got.data()[i].a < 255;
      EXPECT_TRUE(some_transparent) << l.name;
    }
  }
}

// Writes labels (each < 2^depth) as a 1/2/4-bit grey PNG, packed as PNG
// optimisers store maps of few labels.
bool write_packed_grey(const fs::path& path, const LabelMap& labels, int depth, bool interlaced) {
  const int w = labels.width(), h = labels.height();
  const int per_byte = 8 / depth;
  const std::size_t row_bytes = (static_cast<std::size_t>(w) + per_byte - 1) / per_byte;
  std::vector<png_byte> data(row_bytes * h, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int shift = 8 - depth * (x % per_byte + 1);  // first pixel in the high bits
      data[y * row_bytes + x / per_byte] |= static_cast<png_byte>(labels.at(x, y) << shift);
    }
  std::vector<png_bytep> rows(h);
  for (int y = 0; y < h; ++y) rows[y] = data.data() + y * row_bytes;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) return false;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
    return false;
  }
  png_init_io(png, f);
  png_set_IHDR(png, info, w, h, depth, PNG_COLOR_TYPE_GRAY,
               interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return std::fclose(f) == 0;
}

TEST(PngVariants, PackedGreyLabelMapsKeepTheStoredLabels) {
  TempDir dir;
  for (const int depth : {1, 2, 4}) {
    for (const bool interlaced : {false, true}) {
      const std::string name =
          "labels" + std::to_string(depth) + (interlaced ? "_interlaced" : "") + ".png";
      // 13 x 7 (not a multiple of the pixels per byte): every label 0..2^depth-1.
      LabelMap labels(13, 7);
      for (int y = 0; y < 7; ++y)
        for (int x = 0; x < 13; ++x) labels.at(x, y) = (x * 3 + y * 5) % (1 << depth);
      ASSERT_TRUE(write_packed_grey(dir / name, labels, depth, interlaced)) << name;
      // Scaling to 8 bits would give label 1 as 255, 85 or 17.
      EXPECT_EQ(load_label_map(dir / name), labels) << name;
      // As an image the same file is still scaled to the full range.
      const int top = (1 << depth) - 1;
      const Image img = load_image(dir / name);
      for (int y = 0; y < 7; ++y)
        for (int x = 0; x < 13; ++x)
          ASSERT_EQ(img.at(x, y).r, labels.at(x, y) * 255 / top) << name << " " << x << "," << y;
    }
  }
}

TEST(PngVariants, SixteenBitValuesRoundToTheNearestEightBitValue) {
  TempDir dir;
  // Every 16-bit value once: 256 × 256 grey.
  std::vector<std::uint16_t> all(65536);
  for (int v = 0; v < 65536; ++v) all[v] = static_cast<std::uint16_t>(v);
  LabelMap labels(256, 256);
  for (int i = 0; i < 65536; ++i) labels.data()[i] = all[i];
  save_label_map(dir / "all.png", labels);
  // 65535 one-pixel regions: beyond the pipeline's limits, allowed here.
  EXPECT_EQ(load_label_map(dir / "all.png", {.max_regions = 65535, .max_pieces = 65536}), labels);
  const Image img = load_image(dir / "all.png");
  for (int v = 0; v < 65536; ++v) {
    const auto want = static_cast<int>(std::lround(v * 255.0 / 65535.0));
    ASSERT_EQ(img.data()[v].r, want) << v;
  }
}

TEST(PngVariants, MasksAndOtherFormatsAreWritten) {
  TempDir dir;
  LabelMap mask(7, 4);
  mask.at(3, 2) = 5;
  mask.at(6, 0) = -2;
  save_mask(dir / "m.png", mask);
  const LabelMap back = load_label_map(dir / "m.png");
  EXPECT_EQ(back.at(3, 2), 255);
  EXPECT_EQ(back.at(6, 0), 255);
  EXPECT_EQ(back.at(0, 0), 0);
  // A TIFF goes through the OpenImageIO module, both ways.
  Image img(6, 5, Rgba{10, 20, 30, 200});
  img.at(5, 4) = {250, 1, 2, 3};
  save_image(dir / "a.tif", img);
  EXPECT_EQ(load_image(dir / "a.tif"), img);
  EXPECT_THROW(save_image(dir / "a.unknown_ext", img), Error);
  EXPECT_FALSE(fs::exists(dir / "a.unknown_ext"));
}

}  // namespace
}  // namespace hair25d
