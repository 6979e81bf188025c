#include "hair25d/core/image_io.h"

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <fstream>
#include <vector>

#include "common/temp_dir.h"
#include "hair25d/core/error.h"

namespace hair25d {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

// Writes raw pixels with OpenImageIO in any format and type the project reads.
template <typename T>
void write_raw(const fs::path& path, int w, int h, int channels, OIIO::TypeDesc type,
               const std::vector<T>& data) {
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out) << path;
  OIIO::ImageSpec spec(w, h, channels, type);
  ASSERT_TRUE(out->open(path.string(), spec)) << out->geterror();
  ASSERT_TRUE(out->write_image(type, data.data())) << out->geterror();
  ASSERT_TRUE(out->close());
}

Image gradient(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      img.at(x, y) = {static_cast<std::uint8_t>(x * 7), static_cast<std::uint8_t>(y * 5),
                      static_cast<std::uint8_t>((x + y) * 3), static_cast<std::uint8_t>(255 - x)};
    }
  }
  return img;
}

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(ImageIo, PngRgbaRoundTripIsExact) {
  TempDir dir;
  const Image img = gradient(13, 7);
  save_image(dir / "a.png", img);
  EXPECT_EQ(load_image(dir / "a.png"), img);
}

TEST(ImageIo, SixteenBitGreyIsReplicatedAndScaled) {
  TempDir dir;
  std::vector<std::uint16_t> px = {0, 65535, 32896, 257 * 10, 257 * 200, 65535};
  write_raw(dir / "g16.png", 3, 2, 1, OIIO::TypeDesc::UINT16, px);
  const Image img = load_image(dir / "g16.png");
  ASSERT_EQ(img.width(), 3);
  ASSERT_EQ(img.height(), 2);
  EXPECT_EQ(img.at(0, 0), (Rgba{0, 0, 0, 255}));
  EXPECT_EQ(img.at(1, 0), (Rgba{255, 255, 255, 255}));
  EXPECT_EQ(img.at(2, 0), (Rgba{128, 128, 128, 255}));
  EXPECT_EQ(img.at(0, 1), (Rgba{10, 10, 10, 255}));
}

TEST(ImageIo, GreyAlphaKeepsTransparency) {
  TempDir dir;
  std::vector<std::uint8_t> px = {100, 0, 200, 255};  // two pixels: grey, alpha
  write_raw(dir / "ga.png", 2, 1, 2, OIIO::TypeDesc::UINT8, px);
  const Image img = load_image(dir / "ga.png");
  EXPECT_EQ(img.at(0, 0).a, 0);
  EXPECT_EQ(img.at(1, 0), (Rgba{200, 200, 200, 255}));
}

TEST(ImageIo, FloatExrIsClampedTo8Bits) {
  TempDir dir;
  std::vector<float> px = {0.0f, 0.5f, 1.0f, 2.0f, -1.0f, 0.25f};  // two RGB pixels
  write_raw(dir / "f.exr", 2, 1, 3, OIIO::TypeDesc::FLOAT, px);
  const Image img = load_image(dir / "f.exr");
  EXPECT_EQ(img.at(0, 0), (Rgba{0, 128, 255, 255}));
  EXPECT_EQ(img.at(1, 0), (Rgba{255, 0, 64, 255}));
}

TEST(ImageIo, JpegTiffAndWebpAreRead) {
  TempDir dir;
  std::vector<std::uint8_t> rgb(20 * 9 * 3);
  for (std::size_t i = 0; i < rgb.size(); ++i)
    rgb[i] = static_cast<std::uint8_t>(i % 3 == 0 ? 200 : 40);
  for (const char* name : {"a.jpg", "a.tif", "a.webp"}) {
    write_raw(dir / name, 20, 9, 3, OIIO::TypeDesc::UINT8, rgb);
    const Image img = load_image(dir / name);
    ASSERT_EQ(img.width(), 20) << name;
    ASSERT_EQ(img.height(), 9) << name;
    // Lossy codecs move values a little; the colour must survive.
    EXPECT_NEAR(img.at(10, 4).r, 200, 12) << name;
    EXPECT_NEAR(img.at(10, 4).g, 40, 12) << name;
    EXPECT_EQ(img.at(10, 4).a, 255) << name;
  }
  std::vector<std::uint16_t> rgb16(5 * 4 * 3, 65535);
  write_raw(dir / "b16.tif", 5, 4, 3, OIIO::TypeDesc::UINT16, rgb16);
  EXPECT_EQ(load_image(dir / "b16.tif").at(4, 3), (Rgba{255, 255, 255, 255}));
}

// A minimal Photoshop file: header, empty sections, raw planar composite.
std::string tiny_psd(int w, int h, const std::vector<std::uint8_t>& planar_rgb) {
  std::string s = "8BPS";
  auto u16 = [&](int v) {
    s += static_cast<char>((v >> 8) & 255);
    s += static_cast<char>(v & 255);
  };
  auto u32 = [&](std::uint32_t v) {
    u16(static_cast<int>(v >> 16));
    u16(static_cast<int>(v & 0xffff));
  };
  u16(1);
  s.append(6, '\0');
  u16(3);  // channels
  u32(h);
  u32(w);
  u16(8);  // depth
  u16(3);  // RGB
  u32(0);  // colour mode data
  u32(0);  // image resources
  u32(0);  // layers and masks
  u16(0);  // raw image data
  s.append(planar_rgb.begin(), planar_rgb.end());
  return s;
}

TEST(ImageIo, PsdFlattenedCompositeIsRead) {
  TempDir dir;
  const int w = 3, h = 2;
  std::vector<std::uint8_t> planar;
  for (int c = 0; c < 3; ++c) {
    for (int i = 0; i < w * h; ++i) planar.push_back(static_cast<std::uint8_t>(c * 100 + i));
  }
  write_bytes(dir / "a.psd", tiny_psd(w, h, planar));
  const Image img = load_image(dir / "a.psd");
  ASSERT_EQ(img.width(), w);
  ASSERT_EQ(img.height(), h);
  EXPECT_EQ(img.at(2, 1), (Rgba{5, 105, 205, 255}));
}

TEST(ImageIo, MissingFileNamesThePath) {
  TempDir dir;
  try {
    load_image(dir / "nope.png");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("nope.png"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no such file"), std::string::npos) << e.what();
  }
}

TEST(ImageIo, NotAnImageEmptyAndFolderAreErrors) {
  TempDir dir;
  write_bytes(dir / "text.png", "this is not a picture at all");
  write_bytes(dir / "empty.png", "");
  fs::create_directory(dir / "folder.png");
  for (const char* name : {"text.png", "empty.png", "folder.png"}) {
    EXPECT_THROW(load_image(dir / name), Error) << name;
  }
}

TEST(ImageIo, TruncatedPngIsAnErrorNotACrash) {
  TempDir dir;
  save_image(dir / "full.png", gradient(64, 48));
  const std::string bytes = read_bytes(dir / "full.png");
  for (std::size_t cut : {std::size_t{40}, bytes.size() / 2, bytes.size() - 20}) {
    write_bytes(dir / "cut.png", bytes.substr(0, cut));
    EXPECT_THROW(load_image(dir / "cut.png"), Error) << "cut at " << cut;
  }
}

// libjpeg only warns about a truncated stream and fills the rest with grey;
// OpenImageIO then returns success with the warning as its error text.
TEST(ImageIo, TruncatedJpegIsRefusedWithOpenImageIosMessage) {
  TempDir dir;
  std::vector<std::uint8_t> rgb(96 * 70 * 3);
  for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<std::uint8_t>(i * 31 % 251);
  write_raw(dir / "full.jpg", 96, 70, 3, OIIO::TypeDesc::UINT8, rgb);
  EXPECT_EQ(load_image(dir / "full.jpg").width(), 96);  // the whole file loads
  const std::string bytes = read_bytes(dir / "full.jpg");
  ASSERT_GT(bytes.size(), 2000u);
  for (std::size_t cut : {bytes.size() / 3, bytes.size() / 2, bytes.size() - 10}) {
    write_bytes(dir / "cut.jpg", bytes.substr(0, cut));
    try {
      load_image(dir / "cut.jpg");
      ADD_FAILURE() << "a JPEG cut at " << cut << " of " << bytes.size() << " bytes was accepted";
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("cut.jpg"), std::string::npos) << message;
      EXPECT_NE(message.find("cannot decode"), std::string::npos) << message;
    }
  }
}

TEST(ImageIo, SizeLimitsAreCheckedBeforeDecoding) {
  TempDir dir;
  save_image(dir / "a.png", gradient(40, 30));
  ImageLimits small;
  small.max_side = 32;
  try {
    load_image(dir / "a.png", small);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("40x30"), std::string::npos) << e.what();
  }
  ImageLimits few;
  few.max_pixels = 1000;
  EXPECT_THROW(load_image(dir / "a.png", few), Error);
  ImageLimits bad;
  bad.max_side = 0;
  std::string why;
  EXPECT_FALSE(bad.is_valid(&why));
  EXPECT_NE(why.find("max_side = 0"), std::string::npos) << why;
  EXPECT_THROW(load_image(dir / "a.png", bad), Error);
}

TEST(ImageIo, ForgedHugeHeaderIsRefused) {
  TempDir dir;
  save_image(dir / "a.png", gradient(8, 8));
  std::string bytes = read_bytes(dir / "a.png");
  // IHDR width and height are the big-endian words at bytes 16 and 20.
  bytes[16] = 0;
  bytes[17] = 1;
  bytes[18] = static_cast<char>(0x86);
  bytes[19] = static_cast<char>(0xA0);
  bytes[20] = 0;
  bytes[21] = 1;
  bytes[22] = static_cast<char>(0x86);
  bytes[23] = static_cast<char>(0xA0);
  write_bytes(dir / "huge.png", bytes);
  EXPECT_THROW(load_image(dir / "huge.png"), Error);
}

TEST(ImageIo, LabelMapsKeepTheirValues) {
  TempDir dir;
  LabelMap labels(5, 3);
  labels.at(0, 0) = 1;
  labels.at(4, 2) = 65535;
  labels.at(2, 1) = 300;
  save_label_map(dir / "l.png", labels);
  EXPECT_EQ(load_label_map(dir / "l.png"), labels);
  EXPECT_EQ(load_label_map(dir / "l.png").labels(), (std::vector<int>{1, 300, 65535}));

  std::vector<std::uint8_t> eight = {0, 7, 255, 3, 3, 0};
  write_raw(dir / "l8.png", 3, 2, 1, OIIO::TypeDesc::UINT8, eight);
  const LabelMap l8 = load_label_map(dir / "l8.png");
  EXPECT_EQ(l8.at(1, 0), 7);
  EXPECT_EQ(l8.at(2, 0), 255);

  // A 4-bit TIFF (through OpenImageIO, which scales it to 8 bits): labels
  // 0..15 stored, given to OpenImageIO as their 8-bit images (v * 17).
  std::vector<std::uint8_t> four(16 * 3);
  for (std::size_t i = 0; i < four.size(); ++i) four[i] = static_cast<std::uint8_t>(i % 16 * 17);
  {
    auto out = OIIO::ImageOutput::create((dir / "l4.tif").string());
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(16, 3, 1, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:BitsPerSample", 4);
    ASSERT_TRUE(out->open((dir / "l4.tif").string(), spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, four.data()));
    ASSERT_TRUE(out->close());
  }
  const LabelMap l4 = load_label_map(dir / "l4.tif");
  ASSERT_EQ(l4.width(), 16);
  for (int x = 0; x < 16; ++x) ASSERT_EQ(l4.at(x, 2), x) << x;

  save_image(dir / "rgba.png", gradient(4, 4));
  EXPECT_THROW(load_label_map(dir / "rgba.png"), Error);
  LabelMap negative(2, 2, -1);
  EXPECT_THROW(save_label_map(dir / "neg.png", negative), Error);
  EXPECT_FALSE(fs::exists(dir / "neg.png"));
}

TEST(ImageIo, SavingIntoMissingFolderFailsCleanly) {
  TempDir dir;
  EXPECT_THROW(save_image(dir / "no" / "such" / "a.png", gradient(2, 2)), Error);
  EXPECT_THROW(save_image(dir / "a.png", Image()), Error);
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

}  // namespace
}  // namespace hair25d
