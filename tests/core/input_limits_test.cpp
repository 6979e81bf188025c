// Bad input at every reader: forged sizes refused from the header, label maps
// of too many regions or pieces, 12-bit labels kept as stored, JSON nested or
// sized to crash or fill memory, stroke files too costly to paint. Each must
// throw hair25d::Error naming the file, the value and the rule.
#include <gtest/gtest.h>
#include <zlib.h>

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "common/temp_dir.h"
#include "hair25d/core/annotation.h"
#include "hair25d/core/atomic_file.h"
#include "hair25d/core/error.h"
#include "hair25d/core/image_io.h"
#include "hair25d/core/strokes.h"

namespace hair25d {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

std::string be32(std::uint32_t v) {
  return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
          static_cast<char>(v)};
}

std::string chunk(const std::string& type, const std::string& data) {
  const std::string body = type + data;
  const auto crc = static_cast<std::uint32_t>(
      crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size())));
  return be32(static_cast<std::uint32_t>(data.size())) + body + be32(crc);
}

std::string deflate(const std::string& raw) {
  uLongf size = compressBound(raw.size());
  std::string out(size, '\0');
  compress2(reinterpret_cast<Bytef*>(out.data()), &size, reinterpret_cast<const Bytef*>(raw.data()),
            raw.size(), 9);
  out.resize(size);
  return out;
}

// A PNG whose IHDR says w × h (colour type, bit depth) followed by `rows`
// (the filtered rows, deflated here) and any extra chunks before IDAT.
std::string png_bytes(std::uint32_t w, std::uint32_t h, int colour, int depth,
                      const std::string& rows, const std::string& extra = "") {
  std::string ihdr = be32(w) + be32(h);
  ihdr += {static_cast<char>(depth), static_cast<char>(colour), 0, 0, 0};
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + extra +
         chunk("IDAT", deflate(rows)) + chunk("IEND", "");
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

#define EXPECT_HAS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

TEST(InputLimits, PngHeaderBeyondTheLimitsNamesTheLimit) {
  TempDir dir;
  // 2^31-1 wide: libpng's own limit (10^6) used to answer in its words.
  write_bytes(dir / "wide.png", png_bytes(0x7fffffff, 1, 0, 8, std::string(2, '\0')));
  const std::string wide = error_of([&] { load_image(dir / "wide.png"); });
  EXPECT_HAS(wide, "wide.png");
  EXPECT_HAS(wide, "2147483647x1");
  EXPECT_HAS(wide, "16384 pixels a side");
  write_bytes(dir / "many.png", png_bytes(16384, 16384, 0, 8, std::string(2, '\0')));
  const std::string many = error_of([&] { load_label_map(dir / "many.png"); });
  EXPECT_HAS(many, "268435456 pixels");
  EXPECT_HAS(many, std::to_string(ImageLimits{}.max_pixels));
}

// A 70-byte file whose header claims 16000 x 3000 RGBA (within the limits)
// used to allocate 190 MB (780 MB for 16-bit) before libpng found the data
// missing; deflate's 1032:1 bound refuses it from the header and file size.
TEST(InputLimits, TinyPngClaimingManyPixelsIsRefusedBeforeDecoding) {
  TempDir dir;
  for (const int depth : {8, 16}) {
    write_bytes(dir / "claim.png", png_bytes(16000, 3000, 6, depth, std::string(16, '\0')));
    const std::string message = error_of([&] { load_image(dir / "claim.png"); });
    EXPECT_HAS(message, "claim.png: truncated");
    EXPECT_HAS(message, "16000x3000 RGBA");
    EXPECT_HAS(message, "1032:1");
  }
  // A real PNG as compressible as they come is read: 2000 x 1500 black
  // (every byte 0, filters included) deflates 1024:1 at zlib level 9.
  const std::uint32_t w = 2000, h = 1500;
  write_bytes(dir / "black.png", png_bytes(w, h, 0, 8, std::string((w + 1) * h, '\0')));
  ASSERT_LT(fs::file_size(dir / "black.png"), (w + 1) * h / 1000);
  const Image black = load_image(dir / "black.png");
  EXPECT_EQ(black.width(), 2000);
  EXPECT_EQ(black.at(1999, 1499), (Rgba{0, 0, 0, 255}));
}

// A little-endian TIFF: one IFD of (tag, type, count, value) SHORT/LONG entries.
std::string tiff_bytes(std::uint32_t w, std::uint32_t h, int samples, int bits) {
  auto le16 = [](unsigned v) { return std::string{char(v & 255), char(v >> 8)}; };
  auto le32 = [](std::uint32_t v) {
    return std::string{char(v & 255), char(v >> 8 & 255), char(v >> 16 & 255), char(v >> 24)};
  };
  const std::vector<std::pair<unsigned, std::uint32_t>> tags = {
      {256, w}, {257, h}, {258, std::uint32_t(bits)},    {259, 1},
      {262, 1}, {273, 8}, {277, std::uint32_t(samples)}, {278, h},
      {279, 4}};
  std::string ifd = le16(static_cast<unsigned>(tags.size()));
  for (const auto& [tag, value] : tags) ifd += le16(tag) + le16(4) + le32(1) + le32(value);
  ifd += le32(0);
  return std::string("II*\0", 4) + le32(12) + std::string(4, '\0') + ifd;
}

TEST(InputLimits, ForgedTiffHeadersAreRefusedNamingTheRule) {
  TempDir dir;
  write_bytes(dir / "huge.tif", tiff_bytes(100000, 100000, 1, 8));
  EXPECT_HAS(error_of([&] { load_image(dir / "huge.tif"); }), "16384 pixels a side");
  EXPECT_HAS(error_of([&] { load_label_map(dir / "huge.tif"); }), "huge.tif");
  // Uncompressed, 8000 x 7000 x 4 of 16 bits in a file of 130 bytes.
  write_bytes(dir / "short.tif", tiff_bytes(8000, 7000, 4, 16));
  const std::string small = error_of([&] { load_image(dir / "short.tif"); });
  EXPECT_HAS(small, "short.tif: cannot decode the pixels (truncated: the header says 8000x7000");
  EXPECT_HAS(small, "448000000 bytes of pixels");
  write_bytes(dir / "many.tif", tiff_bytes(3, 2, 1000, 8));
  const std::string many = error_of([&] { load_image(dir / "many.tif"); });
  EXPECT_HAS(many, "many.tif: 1000 channels; an image may have at most 64");
  write_bytes(dir / "gif.png", "GIF89a garbage, not an image");
  const std::string gif = error_of([&] { load_image(dir / "gif.png"); });
  EXPECT_HAS(gif, "gif.png: not a readable image");
}

// OpenImageIO reads a 12-bit TIFF as uint16 scaled to the full range (stored
// 1 comes back as 16): label maps must give the stored labels back.
TEST(InputLimits, TwelveBitTiffLabelsAreKeptAsStored) {
  TempDir dir;
  const int w = 64, h = 64;
  std::vector<std::uint16_t> full(w * h);
  for (int i = 0; i < w * h; ++i)  // labels 0..4095, given as their 16-bit images
    full[i] = static_cast<std::uint16_t>((i * 65535 + 2047) / 4095);
  const fs::path path = dir / "l12.tif";
  {
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(w, h, 1, OIIO::TypeDesc::UINT16);
    spec.attribute("oiio:BitsPerSample", 12);
    ASSERT_TRUE(out->open(path.string(), spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT16, full.data()));
    ASSERT_TRUE(out->close());
  }
  {
    auto in = OIIO::ImageInput::open(path.string());
    ASSERT_TRUE(in);
    ASSERT_EQ(in->spec().get_int_attribute("oiio:BitsPerSample"), 12);  // really 12 bits
  }
  const LabelMap labels = load_label_map(path);
  ASSERT_EQ(labels.width(), w);
  for (int i = 0; i < w * h; ++i) ASSERT_EQ(labels.data()[i], i) << i;
}

// Grey with a tRNS chunk decodes as grey + alpha: the message says so.
TEST(InputLimits, GreyPngWithTransparencyIsNamedInTheMessage) {
  TempDir dir;
  const std::string rows = std::string("\0\1\2\0\3", 5) + std::string("\0\0\1\1\2", 5);
  write_bytes(dir / "trns.png", png_bytes(4, 2, 0, 8, rows, chunk("tRNS", std::string(2, '\0'))));
  const std::string message = error_of([&] { load_label_map(dir / "trns.png"); });
  EXPECT_HAS(message, "trns.png");
  EXPECT_HAS(message, "grey with a tRNS transparency chunk");
  EXPECT_HAS(message, "2 channels, one of them alpha");
  EXPECT_HAS(message, "single-channel grey");
  write_bytes(dir / "grey.png", png_bytes(4, 2, 0, 8, rows));  // the same without tRNS
  EXPECT_EQ(load_label_map(dir / "grey.png").at(3, 0), 3);
  EXPECT_EQ(load_image(dir / "trns.png").at(2, 0).a, 0);  // as an image it is transparency
  EXPECT_EQ(load_image(dir / "trns.png").at(3, 0).a, 255);
}

LabelMap checkerboard(int w, int h) {
  LabelMap m(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) m.at(x, y) = 1 + (x + y) % 2;
  return m;
}

// A million one-pixel regions made eval-layering take 160 s and 3.6 GB.
TEST(InputLimits, LabelMapsOfTooManyRegionsOrPiecesAreRefused) {
  TempDir dir;
  LabelMap distinct(100, 41);
  for (int i = 0; i < 100 * 41; ++i) distinct.data()[i] = i < 4097 ? i + 1 : 0;
  save_label_map(dir / "regions.png", distinct);
  const std::string regions = error_of([&] { load_label_map(dir / "regions.png"); });
  EXPECT_HAS(regions, "regions.png: more than 4096 regions");
  EXPECT_HAS(regions, "at most 4096");
  distinct.data()[4096] = 0;  // 4096 regions are allowed
  save_label_map(dir / "regions.png", distinct);
  EXPECT_EQ(load_label_map(dir / "regions.png").labels().size(), 4096u);

  save_label_map(dir / "checker.png", checkerboard(200, 83));  // 16600 pieces of 2 labels
  const std::string pieces = error_of([&] { load_label_map(dir / "checker.png"); });
  EXPECT_HAS(pieces, "checker.png: more than 16384 separate pieces");
  EXPECT_EQ(load_label_map(dir / "checker.png", {.max_pieces = 20000}).labels().size(), 2u);
  save_label_map(dir / "ok.png", checkerboard(180, 91));  // 16380 pieces
  EXPECT_NO_THROW(load_label_map(dir / "ok.png"));

  EXPECT_HAS(error_of([&] { check_label_map(LabelMap(3, 2, -1), "map"); }),
             "map: label -1 at (0, 0)");
  ImageLimits bad;
  bad.max_regions = 0;
  EXPECT_HAS(error_of([&] { check_label_map(LabelMap(3, 2), "map", bad); }), "max_regions = 0");
}

// Annotated cases go through the same readers: a regions.png of scattered
// pixels and a forged strand mask are refused naming the file.
TEST(InputLimits, AnnotatedCaseReadersApplyTheLimits) {
  TempDir dir;
  AnnotatedCase c;
  c.image = Image(40, 30, {200, 200, 200, 255});
  c.regions = LabelMap(40, 30);
  c.regions.at(3, 3) = 1;
  c.regions.at(20, 20) = 2;
  c.region_list = {{1, 1, "a"}, {2, 2, "b"}};
  write_annotated_case(dir / "case", c);
  EXPECT_NO_THROW(read_annotated_case(dir / "case"));
  fs::create_directories(dir / "case" / "strands");
  write_bytes(dir / "case" / "strands" / "1.png", png_bytes(8000, 6000, 0, 8, std::string(9, 0)));
  const std::string mask = error_of([&] { read_annotated_case(dir / "case"); });
  EXPECT_HAS(mask, "1.png: truncated");
  fs::remove(dir / "case" / "strands" / "1.png");
  c.regions = checkerboard(40, 30);
  save_label_map(dir / "case" / "regions.png", c.regions);
  ImageLimits few;
  few.max_pieces = 100;
  EXPECT_HAS(error_of([&] { read_annotated_case(dir / "case", few); }), "separate pieces");
}

TEST(InputLimits, DeeplyNestedOrOverflowingJsonIsAnErrorNotACrash) {
  // 200000 '[' crashed the reader (stack overflow printing the value).
  const std::string deep = std::string(200000, '[') + std::string(200000, ']');
  const std::string message = error_of([&] {
    parse_strokes(R"({"format": "hair25d-strokes/1", "strokes": [{"label": 1, "width": )" + deep +
                      R"(, "points": [[1, 2]]}]})",
                  "deep.json");
  });
  EXPECT_HAS(message, "deep.json: arrays and objects nested more than 64");
  EXPECT_HAS(error_of([&] { parse_strokes(deep, "top.json"); }), "top.json: arrays");
  // A number beyond double was an "internal error" (out_of_range from the parser).
  const std::string huge = error_of([&] {
    parse_strokes(R"({"format": "hair25d-strokes/1", "strokes": [{"label": 1, "width": 1e999,
                      "points": [[1, 2]]}]})",
                  "e.json");
  });
  EXPECT_HAS(huge, "e.json: not valid JSON");
  EXPECT_HAS(huge, "1e999");
  // Brackets inside strings do not count as nesting.
  EXPECT_NO_THROW(parse_strokes(R"({"format": "hair25d-strokes/1", "strokes": [], "note": ")" +
                                    std::string(100, '[') + R"(\" ["})",
                                "s.json"));
}

TEST(InputLimits, TextFilesAreReadNoFurtherThanTheLimit) {
  TempDir dir;
  write_bytes(dir / "big.json", std::string(5000, ' '));
  EXPECT_EQ(read_text_file(dir / "big.json", 5000).size(), 5000u);
  EXPECT_HAS(error_of([&] { read_text_file(dir / "big.json", 4999); }),
             "big.json: 5000 bytes; a text file may hold at most 4999");
  // A device that never ends (a strokes file named /dev/zero read forever).
  if (fs::exists("/dev/zero")) {
    EXPECT_HAS(error_of([] { read_text_file("/dev/zero", 1 << 20); }),
               "/dev/zero: more than 1048576 bytes");
  }
}

TEST(InputLimits, StrokeFilesBeyondTheLimitsNameTheKey) {
  std::string labels = R"({"format": "hair25d-strokes/1", "strokes": [)";
  for (std::size_t i = 1; i <= kMaxStrokeLabels + 1; ++i) {
    labels += i > 1 ? R"(,{"label": )" : R"({"label": )";
    labels += std::to_string(i) + R"(, "width": 1, "points": [[0, 0]]})";
  }
  labels += "]}";
  const std::string many = error_of([&] { parse_strokes(labels, "l.json"); });
  EXPECT_HAS(many, "l.json: key 'strokes[4096].label'");
  EXPECT_HAS(many, "at most 4096 different labels");

  std::string points = R"({"format": "hair25d-strokes/1", "strokes": [{"label": 1, "width": 1,
      "points": [)";
  for (std::size_t i = 0; i <= kMaxStrokePoints; ++i) points += i > 0 ? ",[0,0]" : "[0,0]";
  points += "]}]}";
  EXPECT_HAS(error_of([&] { parse_strokes(points, "p.json"); }),
             "at most 1000000 points in all strokes together");
}

// 3000 points of a brush 10^6 wide over a 1-megapixel drawing took 52 s.
TEST(InputLimits, StrokesTooCostlyToPaintAreRefusedBeforePainting) {
  Strokes s;
  s.source = "wide.json";
  Stroke wide{1, 1e6, {}};
  for (int i = 0; i < 3000; ++i) wide.points.push_back({i % 900, (i * 7) % 1100});
  s.strokes.push_back(wide);
  const std::string message = error_of([&] { rasterize_strokes(s, 900, 1100); });
  EXPECT_HAS(message, "wide.json: painting the strokes would test");
  EXPECT_HAS(message, "at most 1e+09");
  // The same points with a 3-pixel brush paint at once.
  s.strokes[0].width = 3;
  EXPECT_EQ(rasterize_strokes(s, 900, 1100).at(0, 0), 1);
}

}  // namespace
}  // namespace hair25d
