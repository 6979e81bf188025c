// The interface between core's image I/O and libhair25d_core_oiio, a module
// loaded on first use for formats other than PNG (JPEG, TIFF, PSD, EXR, WebP):
// OpenImageIO pulls in ~260 libraries whose loading costs ~0.5 s at every
// program start, which PNG-only runs (all of a model folder) no longer pay.
// Only standard types cross the boundary; the module throws nothing.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace hair25d::oiio_plugin {

inline constexpr int kAbiVersion = 2;
// Images with more channels are refused (a drawing has at most four; EXR
// and PSD may carry a few more, of which the first four and alpha are read).
inline constexpr int kMaxChannels = 64;
inline constexpr const char* kEntryPoint = "hair25d_core_oiio_api";
inline constexpr const char* kFileName = "libhair25d_core_oiio.so";

enum class Status {
  kOk,
  kCannotOpen,
  kRefused,
  kCannotDecode,
  kBadType,
  kTooManyChannels,
  kCannotCreate,
  kCannotWrite
};

struct ReadRequest {
  int max_side = 0;
  std::int64_t max_pixels = 0;
  bool labels = false;  // one 8/16-bit channel as UINT16 (else all channels as FLOAT)
};

struct ReadResult {
  Status status = Status::kOk;
  std::string message;  // the library's own words, one line
  int width = 0, height = 0, channels = 0;
  int alpha_channel = -1;
  bool eight_bit = false;  // the file stores 8-bit values (labels only)
  std::string type;        // the stored pixel type ("uint8", "float", ...)
  std::vector<float> pixels;
  std::vector<std::uint16_t> labels;
};

struct WriteRequest {
  int width = 0, height = 0, channels = 0;
  bool sixteen_bit = false;
  int alpha_channel = -1;  // straight alpha
  const void* data = nullptr;
};

struct Api {
  int abi_version = kAbiVersion;
  void (*read)(const char* path, const ReadRequest& request, ReadResult* result) = nullptr;
  Status (*write)(const char* path, const WriteRequest& request, std::string* message) = nullptr;
};

}  // namespace hair25d::oiio_plugin

extern "C" const hair25d::oiio_plugin::Api* hair25d_core_oiio_api();
