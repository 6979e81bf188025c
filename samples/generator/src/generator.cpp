#include "hair25d/generator/generator.h"

#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "ground_truth.h"
#include "hair25d/core/error.h"
#include "render.h"
#include "rng.h"
#include "scene.h"

namespace hair25d::generator {

namespace {

// Supersampling factor of the picture: 3×3 samples a pixel make 10 coverage
// levels, enough for smooth lines, and keep a 1024² case well under a second.
constexpr int kSupersample = 3;

template <class T>
bool fail(std::string* error, const char* option, T value, const char* rule) {
  if (error) {
    std::ostringstream out;
    out << "generator::Options::" << option << " = " << value << "; " << rule;
    *error = out.str();
  }
  return false;
}

void add_noise(cv::Mat& rgb, double sigma, bool grey, Rng& rng) {
  for (int y = 0; y < rgb.rows; ++y) {
    auto* row = rgb.ptr<cv::Vec3b>(y);
    for (int x = 0; x < rgb.cols; ++x) {
      const double shared = grey ? sigma * rng.normal() : 0.0;
      for (int c = 0; c < 3; ++c) {
        const double n = grey ? shared : sigma * rng.normal();
        row[x][c] = cv::saturate_cast<uchar>(std::lround(row[x][c] + n));
      }
    }
  }
}

cv::Mat jpeg_round_trip(const cv::Mat& rgb, int quality) {
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  std::vector<uchar> bytes;
  if (!cv::imencode(".jpg", bgr, bytes, {cv::IMWRITE_JPEG_QUALITY, quality})) {
    throw Error("generator: JPEG encoding failed at quality " + std::to_string(quality));
  }
  const cv::Mat decoded = cv::imdecode(bytes, cv::IMREAD_COLOR);
  if (decoded.empty()) throw Error("generator: JPEG decoding of the round trip failed");
  cv::Mat out;
  cv::cvtColor(decoded, out, cv::COLOR_BGR2RGB);
  return out;
}

Image to_image(const cv::Mat& rgb) {
  Image img(rgb.cols, rgb.rows);
  for (int y = 0; y < rgb.rows; ++y) {
    const auto* row = rgb.ptr<cv::Vec3b>(y);
    for (int x = 0; x < rgb.cols; ++x) img.at(x, y) = {row[x][0], row[x][1], row[x][2], 255};
  }
  return img;
}

}  // namespace

bool Options::is_valid(std::string* error) const {
  if (width < 64 || width > 8192) return fail(error, "width", width, "must be in [64, 8192]");
  if (height < 64 || height > 8192) return fail(error, "height", height, "must be in [64, 8192]");
  if (strand_count < 1 || strand_count > 400) {
    return fail(error, "strand_count", strand_count, "must be in [1, 400]");
  }
  if (!(line_width >= 1.0 && line_width <= 24.0)) {
    return fail(error, "line_width", line_width, "must be in [1, 24] pixels");
  }
  if (line_width * 40.0 > std::min(width, height)) {
    return fail(error, "line_width", line_width,
                "must be at most min(width, height) / 40 so strands are wider than their lines");
  }
  if (!(noise_sigma >= 0.0 && noise_sigma <= 100.0)) {
    return fail(error, "noise_sigma", noise_sigma, "must be in [0, 100]");
  }
  if (jpeg_quality < 0 || jpeg_quality > 100) {
    return fail(error, "jpeg_quality", jpeg_quality, "must be in [0, 100] (0 = no JPEG)");
  }
  const int s = static_cast<int>(shading);
  if (s < 0 || s > static_cast<int>(Shading::kScreentone)) {
    return fail(error, "shading", s, "must be one of flat, two-tone, gradient, screentone");
  }
  return true;
}

AnnotatedCase generate_case(const Options& options) {
  std::string why;
  if (!options.is_valid(&why)) throw Error(why);
  try {
    Rng rng(options.seed);
    const Scene scene = make_scene(options, rng);
    cv::Mat picture = render_picture(scene, kSupersample);
    Rng noise_rng = rng.fork();
    if (options.noise_sigma > 0.0) {
      add_noise(picture, options.noise_sigma, options.shading == Shading::kScreentone, noise_rng);
    }
    if (options.jpeg_quality > 0) picture = jpeg_round_trip(picture, options.jpeg_quality);
    const GroundTruth gt = make_ground_truth(scene, render_owner(scene));

    AnnotatedCase c;
    c.name = "seed" + std::to_string(options.seed);
    c.image = to_image(picture);
    c.regions = gt.regions;
    c.head_center = scene.head_center;
    c.region_list = gt.region_list;
    c.pairs = gt.pairs;
    c.strokes = gt.strokes;
    if (options.strand_masks) {
      for (const Shape& s : scene.shapes) {
        if (s.hair) c.strand_masks.emplace(s.strand, shape_mask(scene, s));
      }
    }
    return c;
  } catch (const cv::Exception& e) {
    throw Error(std::string("generator: OpenCV failed while drawing a case: ") + e.what());
  }
}

}  // namespace hair25d::generator
