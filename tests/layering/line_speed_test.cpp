// The fast paths of the line response (layering/src/line_response.h, paper
// §4.1) against straightforward reference computations: the colours smoothed
// only where they are sampled against cv::GaussianBlur over the whole window
// (what the layering did before), on non-square images with noise, translucent
// pixels and windows cut by the image's edges, for line widths 1–21; and
// the outline fill grown in bands of rows on several cores against one
// growth over the whole map; the region ids of a map against LabelMap::labels;
// grey levels converted four pixels at a time against the formula, and
// converted only near the regions against the whole image; the AVX2 and
// AVX-512 paths against the SSE2 and scalar ones. (parallel_for, the pool
// and the worker: parallel_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <random>
#include <thread>
#include <tuple>
#include <vector>

#include "boundary_box.h"
#include "boundary_trace.h"
#include "hair25d/layering/boundary_graph.h"
#include "line_response.h"
#include "line_samples.h"
#include "outline_fill.h"
#include "parallel.h"
#include "raster_scan.h"

namespace hair25d::layering {
namespace {

using detail::LineResponse;

// A drawing-like image: flat cels, dark strokes, noise, and (optionally) a
// band of translucent pixels.
Image test_image(int w, int h, unsigned seed, bool translucent) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> noise(-12, 12);
  Image image(w, h, Rgba{240, 235, 225, 255});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      Rgba& p = image.at(x, y);
      const bool cel = (x / 23 + y / 17) % 3 == 0;
      const bool stroke = (x + 2 * y) % 41 < 3 || (3 * x - y + 1000) % 57 < 2;
      const int base_r = stroke ? 30 : cel ? 180 : 235;
      const int base_g = stroke ? 25 : cel ? 110 : 230;
      const int base_b = stroke ? 35 : cel ? 60 : 220;
      p.r = static_cast<std::uint8_t>(std::clamp(base_r + noise(rng), 0, 255));
      p.g = static_cast<std::uint8_t>(std::clamp(base_g + noise(rng), 0, 255));
      p.b = static_cast<std::uint8_t>(std::clamp(base_b + noise(rng), 0, 255));
      if (translucent && y % 7 == 3 && x % 3 != 0) p.a = static_cast<std::uint8_t>((x * 13) % 256);
    }
  return image;
}

// The window [x0, x1) × [y0, y1) of `image` as RGB floats, blended over white
// as the layering reads it, blurred the way the layering did before it
// sampled colours sparsely.
cv::Mat reference_blur(const Image& image, int x0, int y0, int x1, int y1, double sigma) {
  cv::Mat rgb(y1 - y0, x1 - x0, CV_32FC3);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const Rgba& p = image.at(x, y);
      const float a = p.a / 255.0f;
      rgb.at<cv::Vec3f>(y - y0, x - x0) =
          p.a == 255 ? cv::Vec3f(p.r, p.g, p.b)
                     : cv::Vec3f(a * p.r + (1 - a) * 255.0f, a * p.g + (1 - a) * 255.0f,
                                 a * p.b + (1 - a) * 255.0f);
    }
  cv::Mat out;
  cv::GaussianBlur(rgb, out, cv::Size(0, 0), sigma, sigma, cv::BORDER_REPLICATE);
  return out;
}

// Every pixel of the window (and a ring outside it, which clamps to it).
double max_colour_error(const Image& image, double line_width, int x0, int y0, int x1, int y1) {
  const LineResponse lines(image, line_width, x0, y0, x1, y1);
  // The sigma LineResponse documents: half a line width, at least 1.
  const cv::Mat ref = reference_blur(image, x0, y0, x1, y1, std::max(1.0, 0.5 * line_width));
  double worst = 0.0;
  for (int y = y0 - 3; y < y1 + 3; ++y)
    for (int x = x0 - 3; x < x1 + 3; ++x) {
      const cv::Vec3f& want =
          ref.at<cv::Vec3f>(std::clamp(y, y0, y1 - 1) - y0, std::clamp(x, x0, x1 - 1) - x0);
      const auto got = lines.smoothed_colour(x, y);
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(got[c]) - want[c]));
    }
  return worst;
}

// Float sums in another order: within a thousandth of a grey level (values
// are 0..255). A wrong kernel, a wrong tap or a lost channel is off by
// grey levels.
constexpr double kTolerance = 1e-3;

TEST(LineSpeed, SparseColourSmoothingEqualsGaussianBlurOfTheWholeImage) {
  const Image image = test_image(157, 93, 1, false);
  for (const double lw : {1.0, 2.0, 3.3, 4.6, 7.0, 12.0, 21.0})
    EXPECT_LT(max_colour_error(image, lw, 0, 0, image.width(), image.height()), kTolerance)
        << "line width " << lw;
}

TEST(LineSpeed, SparseColourSmoothingInAWindowRepeatsTheWindowsEdges) {
  const Image image = test_image(211, 140, 2, false);
  for (const double lw : {1.5, 4.6, 9.0})
    EXPECT_LT(max_colour_error(image, lw, 37, 21, 170, 101), kTolerance) << "line width " << lw;
}

TEST(LineSpeed, SparseColourSmoothingBlendsTranslucentPixelsOverWhite) {
  const Image image = test_image(120, 175, 3, true);
  for (const double lw : {1.0, 4.6, 13.0}) {
    EXPECT_LT(max_colour_error(image, lw, 0, 0, image.width(), image.height()), kTolerance)
        << "line width " << lw;
    EXPECT_LT(max_colour_error(image, lw, 11, 30, 97, 160), kTolerance) << "line width " << lw;
  }
}

TEST(LineSpeed, SparseColourSmoothingOnImagesSmallerThanTheKernel) {
  for (const auto& [w, h] :
       {std::pair{1, 1}, std::pair{3, 2}, std::pair{9, 30}, std::pair{25, 4}}) {
    const Image image = test_image(w, h, 4, true);
    for (const double lw : {1.0, 6.0, 21.0})
      EXPECT_LT(max_colour_error(image, lw, 0, 0, w, h), kTolerance)
          << w << "x" << h << ", line width " << lw;
  }
}

// Blurring early (prepare: the box of the labels, on a second core) and
// blurring smooth()'s window measure alike, to the bit; so does a prepare()
// whose line width smooth() does not use.
TEST(LineSpeed, EarlyBlurMeasuresLikeTheWindowBlur) {
  const Image image = test_image(331, 247, 5, true);
  LabelMap labels(image.width(), image.height(), 0);
  for (int y = 20; y < 230; ++y)
    for (int x = 15 + y / 9; x < 300; ++x) labels.at(x, y) = 1 + (x / 41 + y / 37) % 4;
  const BoundaryGraph graph = build_boundary_graph(labels);
  for (const double lw : {1.0, 3.0, 4.6, 8.0}) {
    const int m = LineResponse::window_margin(lw);
    const auto [x0, y0, x1, y1] = test::inner_boundary_box(graph, image.width(), image.height());
    const LineResponse plain(image, lw, x0 - m, y0 - m, x1 + m, y1 + m);
    LineResponse early(image);
    early.prepare(lw, labels);
    early.smooth(lw, x0 - m, y0 - m, x1 + m, y1 + m);
    LineResponse other(image);
    other.prepare(lw + 1.0, labels);
    other.smooth(lw, x0 - m, y0 - m, x1 + m, y1 + m);
    EXPECT_EQ(plain.noise_sigma(), early.noise_sigma());
    EXPECT_EQ(plain.noise_sigma(), other.noise_sigma());
    int compared = 0;
    for (const Boundary& b : graph.boundaries) {
      if (b.left == kOutsideLabel || b.right == kOutsideLabel) continue;
      const auto want = plain.measure(b.points, 1.5 * lw, labels, b.left, b.right);
      for (const LineResponse* got : {&early, &other}) {
        const auto m2 = got->measure(b.points, 1.5 * lw, labels, b.left, b.right);
        EXPECT_EQ(want.contrast, m2.contrast) << "line width " << lw;
        EXPECT_EQ(want.contrast_low, m2.contrast_low) << "line width " << lw;
        EXPECT_EQ(want.colour_difference, m2.colour_difference) << "line width " << lw;
      }
      compared += want.contrast != 0.0;
    }
    EXPECT_GT(compared, 10) << "line width " << lw;
  }
}

// The noise left to the caller (smooth(…, true), then estimate_noise(), as
// the layering does beside its measurements) is the one the second core
// estimates, and the one a window blurred without prepare() gives; the
// measurements meanwhile are the same.
TEST(LineSpeed, NoiseEstimatedByTheCallerEqualsTheSecondCores) {
  const Image image = test_image(283, 219, 12, true);
  LabelMap labels(image.width(), image.height(), 0);
  for (int y = 14; y < 205; ++y)
    for (int x = 10 + y / 7; x < 270; ++x) labels.at(x, y) = 1 + (x / 29 + y / 43) % 5;
  const BoundaryGraph graph = build_boundary_graph(labels);
  for (const double lw : {1.0, 2.5, 4.6, 9.0}) {
    const int m = LineResponse::window_margin(lw);
    const auto [x0, y0, x1, y1] = test::inner_boundary_box(graph, image.width(), image.height());
    const LineResponse plain(image, lw, x0 - m, y0 - m, x1 + m, y1 + m);
    LineResponse worker(image, &labels), caller(image, &labels);
    worker.prepare(lw, labels);
    worker.smooth(lw, x0 - m, y0 - m, x1 + m, y1 + m);
    caller.prepare(lw, labels);
    caller.smooth(lw, x0 - m, y0 - m, x1 + m, y1 + m, true);
    for (const Boundary& b : graph.boundaries) {
      if (b.left == kOutsideLabel || b.right == kOutsideLabel) continue;
      EXPECT_EQ(worker.measure(b.points, 1.5 * lw, labels, b.left, b.right).contrast,
                caller.measure(b.points, 1.5 * lw, labels, b.left, b.right).contrast);
    }
    caller.estimate_noise();
    EXPECT_GT(worker.noise_sigma(), 0.0) << "line width " << lw;
    EXPECT_EQ(caller.noise_sigma(), worker.noise_sigma()) << "line width " << lw;
    EXPECT_EQ(caller.noise_sigma(), plain.noise_sigma()) << "line width " << lw;
    caller.estimate_noise();  // once is enough: nothing left
    EXPECT_EQ(caller.noise_sigma(), worker.noise_sigma()) << "line width " << lw;
  }
}

// The grey conversion started late (convert_later: at prepare(), near the
// box it is given, which may be wider than the labels', or at smooth()
// without prepare()) measures like the one started at construction.
TEST(LineSpeed, ConversionStartedLateMeasuresLikeAtConstruction) {
  const Image image = test_image(301, 263, 14, true);
  LabelMap labels(image.width(), image.height(), 0);
  for (int y = 70; y < 240; ++y)
    for (int x = 90 + y / 8; x < 230; ++x) labels.at(x, y) = 1 + (x / 31 + y / 27) % 4;
  const BoundaryGraph graph = build_boundary_graph(labels);
  int x0, y0, x1, y1;
  ASSERT_TRUE(detail::label_box(labels, &x0, &y0, &x1, &y1));
  for (const double lw : {1.0, 3.0, 4.6}) {
    const int m = LineResponse::window_margin(lw);
    const auto [wx0, wy0, wx1, wy1] =
        test::inner_boundary_box(graph, image.width(), image.height());
    LineResponse first(image, &labels);
    first.prepare(lw, labels);
    first.smooth(lw, wx0 - m, wy0 - m, wx1 + m, wy1 + m);
    LineResponse at_prepare(image, &labels, true);
    const detail::LabelBox wider{true, std::max(0, x0 - 5), y0, x1, std::min(262, y1 + 9)};
    at_prepare.prepare(lw, labels, &wider);
    at_prepare.smooth(lw, wx0 - m, wy0 - m, wx1 + m, wy1 + m);
    LineResponse at_smooth(image, &labels, true);
    at_smooth.smooth(lw, wx0 - m, wy0 - m, wx1 + m, wy1 + m);
    EXPECT_EQ(first.noise_sigma(), at_prepare.noise_sigma()) << "line width " << lw;
    EXPECT_EQ(first.noise_sigma(), at_smooth.noise_sigma()) << "line width " << lw;
    int compared = 0;
    for (const Boundary& b : graph.boundaries) {
      if (b.left == kOutsideLabel || b.right == kOutsideLabel) continue;
      const auto want = first.measure(b.points, 1.5 * lw, labels, b.left, b.right);
      for (const LineResponse* got : {&at_prepare, &at_smooth}) {
        const auto m2 = got->measure(b.points, 1.5 * lw, labels, b.left, b.right);
        EXPECT_EQ(want.contrast, m2.contrast) << "line width " << lw;
        EXPECT_EQ(want.colour_difference, m2.colour_difference) << "line width " << lw;
      }
      compared += want.contrast != 0.0;
    }
    EXPECT_GT(compared, 5) << "line width " << lw;
  }
}

// A second prepare() and smooth() on one LineResponse blur again (every
// band) and measure like the first.
TEST(LineSpeed, PreparedTwiceMeasuresLikeOnce) {
  const Image image = test_image(260, 301, 10, false);
  LabelMap labels(image.width(), image.height(), 0);
  for (int y = 30; y < 280; ++y)
    for (int x = 20 + y / 11; x < 240; ++x) labels.at(x, y) = 1 + (x / 33 + y / 41) % 3;
  const BoundaryGraph graph = build_boundary_graph(labels);
  const auto [x0, y0, x1, y1] = test::inner_boundary_box(graph, image.width(), image.height());
  const double lw = 3.0;
  const int m = LineResponse::window_margin(lw);
  const LineResponse plain(image, lw, x0 - m, y0 - m, x1 + m, y1 + m);
  LineResponse twice(image, &labels);
  for (int round = 0; round < 2; ++round) {
    twice.prepare(round == 0 ? lw + 2 : lw, labels);
    twice.smooth(lw, x0 - m, y0 - m, x1 + m, y1 + m);
  }
  int compared = 0;
  for (const Boundary& b : graph.boundaries) {
    if (b.left == kOutsideLabel || b.right == kOutsideLabel) continue;
    const auto want = plain.measure(b.points, 1.5 * lw, labels, b.left, b.right);
    const auto got = twice.measure(b.points, 1.5 * lw, labels, b.left, b.right);
    EXPECT_EQ(want.contrast, got.contrast);
    EXPECT_EQ(want.colour_difference, got.colour_difference);
    compared += want.contrast != 0.0;
  }
  EXPECT_GT(compared, 5);
}

// Measures every boundary between two regions with both responses, expects
// the same numbers to the bit, and returns how many measured a line (and,
// with `paint`, a paint step too).
int same_measurements(const LineResponse& want_from, const LineResponse& got_from,
                      const BoundaryGraph& graph, const LabelMap& labels, double lw, bool paint) {
  int compared = 0;
  for (const Boundary& b : graph.boundaries) {
    if (b.left == kOutsideLabel || b.right == kOutsideLabel) continue;
    const auto want = want_from.measure(b.points, 1.5 * lw, labels, b.left, b.right);
    const auto got = got_from.measure(b.points, 1.5 * lw, labels, b.left, b.right);
    EXPECT_EQ(want.contrast, got.contrast) << "line width " << lw;
    EXPECT_EQ(want.contrast_low, got.contrast_low) << "line width " << lw;
    EXPECT_EQ(want.colour_difference, got.colour_difference) << "line width " << lw;
    compared += want.contrast != 0.0 && (!paint || want.colour_difference != 0.0);
  }
  return compared;
}
// Points whose samples all lie well inside the window and the map are
// measured without bounds checks: the same values as checking every sample,
// on boundaries inside, along and across the window's and the image's edges.
TEST(LineSpeed, UncheckedSamplesMeasureLikeCheckedOnes) {
  const Image image = test_image(297, 211, 8, true);
  LabelMap labels(image.width(), image.height(), 0);
  for (int y = 0; y < 211; ++y)
    for (int x = y / 7; x < 297; ++x) labels.at(x, y) = 1 + (x / 37 + y / 29) % 5;
  const BoundaryGraph graph = build_boundary_graph(labels);
  for (const double lw : {1.0, 4.6, 9.0}) {
    LineResponse fast(image, lw, 20, 10, 260, 190);
    LineResponse checked(image, lw, 20, 10, 260, 190);
    checked.check_every_sample(true);
    EXPECT_GT(same_measurements(checked, fast, graph, labels, lw, false), 10)
        << "line width " << lw;
  }
}

// The AVX2 paths (eight floats or four doubles at a time) and the AVX-512
// colour sums (sixteen floats) against the SSE2 and scalar ones, to the
// bit: every pixel's smoothed colour (windows cut by the image's edges,
// translucent rows, kernels of 9 to 53 taps), and every measurement along
// the boundaries of a map.
TEST(LineSpeed, WideVectorsSmoothColoursLikeNarrowOnes) {
  if (!LineResponse::wide_vectors_available()) GTEST_SKIP() << "no AVX2 on this processor";
  for (const bool translucent : {false, true}) {
    const Image image = test_image(151, 97, 12, translucent);
    // Kernels of 3, 4, 6, 9 and 14 groups of four columns (every remainder
    // of four).
    for (const double lw : {1.0, 3.0, 4.6, 8.0, 13.0}) {
      LineResponse wide(image, lw, 9, 5, 140, 93);
      wide.use_widest_vectors(false);
      LineResponse narrow(image, lw, 9, 5, 140, 93);
      narrow.use_wide_vectors(false);
      LineResponse widest(image, lw, 9, 5, 140, 93);  // four pixels a register, with AVX-512
      int differ = 0, differ_widest = 0;
      for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
          differ += wide.smoothed_colour(x, y) != narrow.smoothed_colour(x, y);
          differ_widest += widest.smoothed_colour(x, y) != narrow.smoothed_colour(x, y);
        }
      EXPECT_EQ(differ, 0) << "line width " << lw << (translucent ? ", translucent" : "");
      EXPECT_EQ(differ_widest, 0) << "line width " << lw << (translucent ? ", translucent" : "");
    }
  }
}

#if defined(HAIR25D_LAYERING_AVX2)
// The point samples eight at a time (AVX-512) against four at a time (AVX2),
// point by point: random points and normals well inside a random grey window
// and label map, centre searches of 1 to 12 steps, paper searches of 1 to 20.
TEST(LineSpeed, WidestPointSamplesEqualWideOnes) {
  if (!LineResponse::widest_vectors_available()) GTEST_SKIP() << "no AVX-512F on this processor";
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int w = 173, h = 131;
  std::vector<float> grey(static_cast<std::size_t>(w) * h);
  for (float& g : grey) g = static_cast<float>(255.0 * unit(rng));
  LabelMap labels(w + 40, h + 40, 0);
  for (int y = 0; y < labels.height(); ++y)
    for (int x = 0; x < labels.width(); ++x) labels.at(x, y) = static_cast<int>(rng() % 3);
  const detail::GreyView view{grey.data(), w, h, 20.0, 20.0, w - 1.0, h - 1.0};
  const detail::LabelView lv{labels.data(), labels.width(), labels.height()};
  int compared = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int steps = 1 + static_cast<int>(rng() % 12), paper = 1 + static_cast<int>(rng() % 20);
    std::vector<double> offsets;
    for (int k = 0; k < steps; ++k) offsets.push_back(-0.5 * (steps / 2) + 0.5 * k);
    while (offsets.size() % 8 != 0) offsets.push_back(offsets.back());
    const double angle = 6.283185307179586 * unit(rng);
    const double nx = std::cos(angle), ny = std::sin(angle);
    // The farthest sample stays a pixel inside the window (20 + 1 .. 20 + w - 2).
    const double reach = std::max(paper, steps) + 1.0;
    const double px = 20.0 + reach + 1.0 + (w - 2 * reach - 3.0) * unit(rng);
    const double py = 20.0 + reach + 1.0 + (h - 2 * reach - 3.0) * unit(rng);
    const int left = static_cast<int>(rng() % 3), right = static_cast<int>(rng() % 3);
    const int count = static_cast<int>(offsets.size());
    const detail::PointSamples a = detail::point_samples_avx2(
        view, lv, px, py, nx, ny, offsets.data(), count, paper, left, right);
    const detail::PointSamples b = detail::point_samples_avx512(
        view, lv, px, py, nx, ny, offsets.data(), count, paper, left, right);
    ASSERT_EQ(a.centre, b.centre) << "trial " << trial;
    ASSERT_EQ(a.paper_left, b.paper_left) << "trial " << trial;
    ASSERT_EQ(a.paper_right, b.paper_right) << "trial " << trial;
    compared += a.paper_left >= 0 && a.paper_right >= 0;
  }
  EXPECT_GT(compared, 1000);
}
#endif

TEST(LineSpeed, WideVectorsMeasureLikeNarrowOnes) {
  if (!LineResponse::wide_vectors_available()) GTEST_SKIP() << "no AVX2 on this processor";
  const Image image = test_image(313, 229, 13, true);
  LabelMap labels(image.width(), image.height(), 0);
  for (int y = 0; y < 229; ++y)
    for (int x = y / 5; x < 313; ++x) labels.at(x, y) = 1 + (x / 31 + y / 23 + x * y / 900) % 6;
  const BoundaryGraph graph = build_boundary_graph(labels);
  for (const double lw : {1.0, 2.5, 4.6, 9.0}) {
    LineResponse widest(image, lw, 15, 10, 290, 215);  // AVX-512 where there is one
    LineResponse wide(image, lw, 15, 10, 290, 215);
    wide.use_widest_vectors(false);
    LineResponse narrow(image, lw, 15, 10, 290, 215);
    narrow.use_wide_vectors(false);
    EXPECT_GT(same_measurements(narrow, wide, graph, labels, lw, true), 10) << "line width " << lw;
    EXPECT_GT(same_measurements(narrow, widest, graph, labels, lw, true), 10)
        << "line width " << lw;
  }
}

// The comparison itself must be able to fail: a colour smoothed at another
// scale is far from the reference.
TEST(LineSpeed, TheReferenceTellsAnotherSmoothingApart) {
  const Image image = test_image(157, 93, 1, false);
  const LineResponse lines(image, 4.6, 0, 0, image.width(), image.height());
  const cv::Mat other = reference_blur(image, 0, 0, image.width(), image.height(), 1.0);
  double worst = 0.0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      worst = std::max(
          worst, std::abs(double(lines.smoothed_colour(x, y)[0]) - other.at<cv::Vec3f>(y, x)[0]));
  EXPECT_GT(worst, 1.0);
}

// A drawing-like label map: strands as discs and thick strokes painted one
// over another, each with a label-0 outline `line` pixels wide (lines of
// even width split into ties), on a background of label 0.
LabelMap strand_map(int w, int h, unsigned seed, int line) {
  std::mt19937 rng(seed);
  LabelMap m(w, h, 0);
  const int strands = 4 + static_cast<int>(rng() % 12);
  for (int s = 0; s < strands; ++s) {
    const double cx = rng() % w, cy = rng() % h;
    const double dx = (static_cast<int>(rng() % 200) - 100) / 100.0;
    const double dy = (static_cast<int>(rng() % 200) - 100) / 100.0;
    const double length = 5 + rng() % std::max(6, w / 2);
    const double radius = 3 + rng() % std::max(4, h / 6);
    const int label = 1 + static_cast<int>(rng() % 9);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        // Distance to the segment from (cx, cy) along (dx, dy).
        const double len2 = dx * dx + dy * dy;
        const double t =
            len2 > 0 ? std::clamp(((x - cx) * dx + (y - cy) * dy) / len2, 0.0, length) : 0.0;
        const double d = std::hypot(x - cx - t * dx, y - cy - t * dy);
        if (d < radius)
          m.at(x, y) = label;
        else if (d < radius + line)
          m.at(x, y) = 0;
      }
  }
  return m;
}

void expect_same_fill(const LabelMap& m, const OutlineFillOptions& options, int bands,
                      const std::string& what) {
  const OutlineFill one = detail::fill_outlines_in_bands(m, options, 1, 1);
  const OutlineFill split = detail::fill_outlines_in_bands(m, options, bands, 1);
  EXPECT_EQ(split.line_width, one.line_width) << what;
  EXPECT_EQ(split.radius, one.radius) << what;
  ASSERT_EQ(split.labels.width(), one.labels.width());
  int differ = 0;
  for (int y = 0; y < m.height(); ++y)
    for (int x = 0; x < m.width(); ++x) differ += split.labels.at(x, y) != one.labels.at(x, y);
  EXPECT_EQ(differ, 0) << what;
}

// Two fills of one map agree: line width, radius, labels and filled box.
void expect_equal_fills(const OutlineFill& a, const detail::LabelBox& a_box, const OutlineFill& b,
                        const detail::LabelBox& b_box, const std::string& where) {
  EXPECT_EQ(a.line_width, b.line_width) << where;
  EXPECT_EQ(a.radius, b.radius) << where;
  EXPECT_TRUE(a.labels == b.labels) << where;
  EXPECT_EQ(a_box.any, b_box.any) << where;
  EXPECT_EQ(a_box.x0, b_box.x0) << where;
  EXPECT_EQ(a_box.y0, b_box.y0) << where;
  EXPECT_EQ(a_box.x1, b_box.x1) << where;
  EXPECT_EQ(a_box.y1, b_box.y1) << where;
}

// Hand-built: lines of odd and even width (ties in the middle), across and
// along the bands' edges, between regions and against the background.
TEST(FillBands, HandBuiltLinesFillAsOneGrowth) {
  LabelMap m(37, 61, 0);
  for (int y = 0; y < 61; ++y)
    for (int x = 0; x < 37; ++x) {
      if (y >= 3 && y < 20 && x >= 2 && x < 34) m.at(x, y) = x < 17 ? 1 : (x >= 19 ? 2 : 0);
      if (y >= 22 && y < 58 && x >= 4) m.at(x, y) = y < 39 ? 3 : (y >= 42 ? 4 : 0);
      if (y >= 22 && y < 58 && (x + y) % 13 < 2) m.at(x, y) = 0;  // diagonal lines
    }
  const OutlineFill one = detail::fill_outlines_in_bands(m, {}, 1, 1);
  // The two-pixel line between 1 and 2 is split between them; the
  // three-pixel one between 3 and 4 too, its middle row to one of them.
  EXPECT_EQ(one.labels.at(17, 10), 1);
  EXPECT_EQ(one.labels.at(18, 10), 2);
  EXPECT_EQ(one.labels.at(20, 39), 3);
  EXPECT_EQ(one.labels.at(20, 41), 4);
  for (int bands : {2, 3, 5, 8, 61})
    for (double reach : {0.0, 1.0, 2.5, 7.0, 12.0})
      expect_same_fill(m, {.max_distance = reach}, bands,
                       std::to_string(bands) + " bands, reach " + std::to_string(reach));
}

// Generated drawing-like maps (non-square, outlines 1–5 px) and noise (ties
// everywhere), split into bands of a few rows up to one band per row.
TEST(FillBands, GeneratedMapsFillAsOneGrowth) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 24; ++trial) {
    const int w = 30 + static_cast<int>(rng() % 150), h = 20 + static_cast<int>(rng() % 110);
    LabelMap m = strand_map(w, h, 100 + trial, 1 + trial % 5);
    if (trial % 6 == 5) {
      const int kinds[] = {0, 0, 0, 1, 2, 7};
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) m.at(x, y) = kinds[rng() % 6];
    }
    const double reach = trial % 3 == 0 ? 0.0 : 0.5 + (rng() % 90) / 10.0;
    const int bands = 2 + static_cast<int>(rng() % 9);
    expect_same_fill(m, {.max_distance = reach}, bands,
                     "trial " + std::to_string(trial) + ", " + std::to_string(bands) + " bands");
  }
}

// Rows prepared sixteen pixels at a time (AVX2) or thirty-two (AVX-512) fill
// like rows prepared one pixel at a time: maps narrower and wider than a
// block, lines of 1–5 px.
TEST(FillBands, WideRowsFillLikeNarrowOnes) {
  std::mt19937 rng(17);
  for (int trial = 0; trial < 12; ++trial) {
    const int w = 5 + static_cast<int>(rng() % 200), h = 4 + static_cast<int>(rng() % 90);
    const LabelMap m = strand_map(w, h, 500 + trial, 1 + trial % 5);
    for (const int bands : {1, 3}) {
      const OutlineFill widest = detail::fill_outlines_in_bands(m, {}, bands, 1, true);
      const OutlineFill wide =
          detail::fill_outlines_in_bands(m, {}, bands, 1, true, nullptr, nullptr, false);
      const OutlineFill narrow = detail::fill_outlines_in_bands(m, {}, bands, 1, false);
      EXPECT_EQ(wide.line_width, narrow.line_width) << "trial " << trial;
      EXPECT_TRUE(wide.labels == narrow.labels) << "trial " << trial;
      EXPECT_EQ(widest.line_width, narrow.line_width) << "trial " << trial;
      EXPECT_TRUE(widest.labels == narrow.labels) << "trial " << trial;
    }
  }
}

// The growth with `wide` compares a pixel's eight neighbours at once and
// relaxes only those improved: the same distances, owners and ties as one
// compare after another, at reaches where corners stop before edges (limit
// − 7 < d ≤ limit − 5), on strand maps and on noise (many ties), in bands.
TEST(FillBands, NeighboursComparedAtOnceGrowLikeOneByOne) {
  std::mt19937 rng(29);
  for (int trial = 0; trial < 30; ++trial) {
    const int w = 3 + static_cast<int>(rng() % 160), h = 3 + static_cast<int>(rng() % 100);
    LabelMap m = strand_map(w, h, 900 + trial, 1 + trial % 5);
    if (trial % 5 == 4) {
      const int kinds[] = {0, 0, 0, 0, 1, 2, 3};
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) m.at(x, y) = kinds[rng() % 7];
    }
    const double reach = trial % 4 == 0 ? 0.0 : 0.2 * static_cast<double>(1 + rng() % 40);
    for (const int bands : {1, 4}) {
      detail::LabelBox wide_box, narrow_box;
      const OutlineFill wide = detail::fill_outlines_in_bands(m, {.max_distance = reach}, bands, 1,
                                                              true, nullptr, &wide_box);
      const OutlineFill narrow = detail::fill_outlines_in_bands(m, {.max_distance = reach}, bands,
                                                                1, false, nullptr, &narrow_box);
      const std::string where = "trial " + std::to_string(trial) + ", reach " +
                                std::to_string(reach) + ", " + std::to_string(bands) + " bands";
      expect_equal_fills(wide, wide_box, narrow, narrow_box, where);
    }
  }
}

// With AVX-512 the growth relaxes a bucket's fronts by masked stores and
// compressed pushes, and the pass after it finds the pixels reached by a
// scan of the rows: the same labels, line width, radius and box as the
// growth one neighbour at a time with its list of pixels reached. Maps of
// widths about the scan's 32-pixel blocks, thin lines (one-pixel crossings
// decide the width), wide ones, noise (ties, buckets regrown many times)
// and reaches where corners stop before edges, in bands.
TEST(FillBands, MaskedRelaxationAndRowScanFillLikeOneByOne) {
  std::mt19937 rng(31);
  for (int trial = 0; trial < 36; ++trial) {
    const int w = trial < 8 ? 30 + trial : 3 + static_cast<int>(rng() % 220);
    const int h = 3 + static_cast<int>(rng() % 120);
    LabelMap m = strand_map(w, h, 1300 + trial, 1 + trial % 6);
    if (trial % 6 == 5) {
      const int kinds[] = {0, 0, 0, 0, 0, 1, 2, 3, 4};
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) m.at(x, y) = kinds[rng() % 9];
    }
    const double reach = trial % 4 == 0 ? 0.0 : 0.2 * static_cast<double>(1 + rng() % 45);
    for (const int bands : {1, 3}) {
      detail::LabelBox widest_box, narrow_box;
      const OutlineFill widest = detail::fill_outlines_in_bands(
          m, {.max_distance = reach}, bands, 1, true, nullptr, &widest_box, true);
      const OutlineFill narrow = detail::fill_outlines_in_bands(
          m, {.max_distance = reach}, bands, 1, false, nullptr, &narrow_box, false);
      const std::string where = "trial " + std::to_string(trial) + ", reach " +
                                std::to_string(reach) + ", " + std::to_string(bands) + " bands";
      expect_equal_fills(widest, widest_box, narrow, narrow_box, where);
    }
  }
}

// The ids the fill reads while it copies the map (its label box's rows, in
// two parts) are the map's distinct non-zero labels, and the line width and
// box it gives before writing the pixels are those of its result: strand
// maps with labels up to the map's edges and below 0, one label, none.
TEST(FillBands, IdsAndEarlyBoxAreTheFilledMapsOwn) {
  std::mt19937 rng(37);
  for (int trial = 0; trial < 24; ++trial) {
    const int w = 4 + static_cast<int>(rng() % 190), h = 3 + static_cast<int>(rng() % 130);
    LabelMap m = strand_map(w, h, 1700 + trial, 1 + trial % 5);
    if (trial % 6 == 1)
      for (int y = 0; y < h; ++y) m.at(w - 1, y) = y % 3 == 0 ? -1 : 40 + y % 2;
    if (trial % 6 == 2)
      for (int x = 0; x < w; ++x) m.at(x, 0) = m.at(x, h - 1) = 1000 + x % 7;
    if (trial % 6 == 3) m = LabelMap(w, h, 0);
    if (trial % 6 == 4) {
      m = LabelMap(w, h, 0);
      m.at(static_cast<int>(rng() % w), static_cast<int>(rng() % h)) = 5;
    }
    const double reach = trial % 3 == 0 ? 0.0 : 0.5 + (rng() % 90) / 10.0;
    for (const int bands : {1, 4}) {
      std::vector<int> ids = {-7};
      detail::LabelBox box, early;
      double early_width = -1;
      int calls = 0;
      const OutlineFill f =
          detail::fill_outlines_in_bands(m, {.max_distance = reach}, bands, 1, true, nullptr, &box,
                                         true, &ids, [&](double width, const detail::LabelBox& b) {
                                           early_width = width, early = b;
                                           ++calls;
                                         });
      const std::string where = "trial " + std::to_string(trial) + ", " + std::to_string(bands);
      EXPECT_EQ(ids, m.labels()) << where;
      if (!box.any) {
        EXPECT_EQ(calls, 0) << where;
        continue;
      }
      ASSERT_EQ(calls, 1) << where;
      EXPECT_EQ(early_width, f.line_width) << where;
      EXPECT_TRUE(early.any) << where;
      EXPECT_EQ(early.x0, box.x0) << where;
      EXPECT_EQ(early.y0, box.y0) << where;
      EXPECT_EQ(early.x1, box.x1) << where;
      EXPECT_EQ(early.y1, box.y1) << where;
      int x0, y0, x1, y1;
      ASSERT_TRUE(detail::label_box(f.labels, &x0, &y0, &x1, &y1)) << where;
      EXPECT_EQ(early.x0, x0) << where;
      EXPECT_EQ(early.y0, y0) << where;
      EXPECT_EQ(early.x1, x1) << where;
      EXPECT_EQ(early.y1, y1) << where;
    }
  }
}

// The box the fill gives is label_box's answer on the filled map (which the
// early blur would otherwise look for): generated maps, lines beyond the
// regions' box, and maps with no regions.
TEST(FillBands, FilledBoxIsTheLabelBoxOfTheFilledMap) {
  std::mt19937 rng(23);
  for (int trial = 0; trial < 16; ++trial) {
    const int w = 20 + static_cast<int>(rng() % 160), h = 15 + static_cast<int>(rng() % 120);
    LabelMap m = strand_map(w, h, 700 + trial, 1 + trial % 5);
    if (trial % 4 == 3) m = LabelMap(w, h, 0);
    const double reach = trial % 3 == 0 ? 0.0 : 0.5 + (rng() % 90) / 10.0;
    detail::LabelBox box;
    box.any = trial % 4 != 3;  // the fill must say "none" itself
    const OutlineFill f = detail::fill_outlines_in_bands(m, {.max_distance = reach}, 1 + trial % 4,
                                                         1, true, nullptr, &box);
    int x0 = -7, y0 = -7, x1 = -7, y1 = -7;
    const bool any = detail::label_box(f.labels, &x0, &y0, &x1, &y1);
    ASSERT_EQ(box.any, any) << "trial " << trial;
    if (!any) continue;
    EXPECT_EQ(box.x0, x0) << "trial " << trial;
    EXPECT_EQ(box.y0, y0) << "trial " << trial;
    EXPECT_EQ(box.x1, x1) << "trial " << trial;
    EXPECT_EQ(box.y1, y1) << "trial " << trial;
  }
  // Background pixels given to the regions grow the box beyond the regions'.
  LabelMap m(12, 9, 0);
  for (int y = 2; y < 7; ++y)
    for (int x = 3; x < 6; ++x) m.at(x, y) = 4;
  for (int y = 2; y < 7; ++y) m.at(7, y) = 5;
  detail::LabelBox box;
  const OutlineFill f = detail::fill_outlines_in_bands(m, {}, 1, 1, true, nullptr, &box);
  ASSERT_EQ(f.labels.at(6, 4), 4);
  EXPECT_TRUE(box.any);
  EXPECT_LT(box.x0, 3);  // region 4 starts at x = 3
  EXPECT_GT(box.y1, 6);  // and ends at y = 6
  int x0, y0, x1, y1;
  ASSERT_TRUE(detail::label_box(f.labels, &x0, &y0, &x1, &y1));
  EXPECT_EQ(box.x0, x0);
  EXPECT_EQ(box.x1, x1);
  EXPECT_EQ(box.y0, y0);
  EXPECT_EQ(box.y1, y1);
}

// label_box sixteen labels a compare (AVX-512F where the processor has it)
// gives the plain scan's box: maps of every width up to 70 with a few labels
// anywhere (at the rows' ends, in the last block of sixteen), and none.
TEST(LabelBox, WidestScanEqualsThePlainScan) {
  std::mt19937 rng(31);
  for (int trial = 0; trial < 400; ++trial) {
    const int w = 1 + trial % 70, h = 1 + static_cast<int>(rng() % 12);
    LabelMap m(w, h, 0);
    const int count = static_cast<int>(rng() % 4);
    for (int k = 0; k < count; ++k)
      m.at(static_cast<int>(rng() % w), static_cast<int>(rng() % h)) =
          1 + static_cast<int>(rng() % 9);
    if (trial % 5 == 1) m.at(w - 1, static_cast<int>(rng() % h)) = 3;
    if (trial % 5 == 2) m.at(0, static_cast<int>(rng() % h)) = 3;
    int a[4] = {-7, -7, -7, -7}, b[4] = {-7, -7, -7, -7};
    const bool any_plain = detail::label_box(m, &a[0], &a[1], &a[2], &a[3], false);
    const bool any_widest = detail::label_box(m, &b[0], &b[1], &b[2], &b[3], true);
    ASSERT_EQ(any_plain, any_widest) << "trial " << trial;
    if (!any_plain) continue;
    for (int k = 0; k < 4; ++k) EXPECT_EQ(a[k], b[k]) << "trial " << trial << " k " << k;
  }
  // A generated drawing-like map.
  const LabelMap m = strand_map(640, 480, 9, 4);
  int a[4], b[4];
  ASSERT_TRUE(detail::label_box(m, &a[0], &a[1], &a[2], &a[3], false));
  ASSERT_TRUE(detail::label_box(m, &b[0], &b[1], &b[2], &b[3], true));
  for (int k = 0; k < 4; ++k) EXPECT_EQ(a[k], b[k]) << "k " << k;
}

// The public fill splits large maps; it equals one growth there too (a
// 640 x 480 drawing-like map, the bands of fill_outlines).
TEST(FillBands, PublicFillOnALargeMapEqualsOneGrowth) {
  const LabelMap m = strand_map(640, 480, 7, 4);
  const OutlineFill one = detail::fill_outlines_in_bands(m, {}, 1, 1);
  const OutlineFill pub = fill_outlines(m);
  EXPECT_GT(one.line_width, 0.0);
  EXPECT_EQ(pub.line_width, one.line_width);
  EXPECT_EQ(pub.radius, one.radius);
  EXPECT_TRUE(pub.labels == one.labels);
}

// The trace with its corners scanned eight at a time (AVX2), and the scan
// for closed loops skipped when every crack edge between rows was walked,
// gives the graph of the plain scans: strand maps, islands (closed loops
// with no junction, nested), noise with outside-like labels, maps narrower
// than a block; sixteen corners at a time (AVX-512) in every other trial.
TEST(TraceRows, WideRowsTraceLikeNarrowOnes) {
  std::mt19937 rng(23);
  int loops = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const int w = 1 + static_cast<int>(rng() % 150), h = 1 + static_cast<int>(rng() % 90);
    LabelMap m = strand_map(w, h, 700 + trial, 1 + trial % 4);
    if (trial % 3 == 1)  // islands: rectangles inside rectangles
      for (int k = 0; k < 4; ++k) {
        const int x0 = static_cast<int>(rng() % w), y0 = static_cast<int>(rng() % h);
        const int x1 = std::min(w, x0 + 2 + static_cast<int>(rng() % 30));
        const int y1 = std::min(h, y0 + 2 + static_cast<int>(rng() % 20));
        for (int y = y0; y < y1; ++y)
          for (int x = x0; x < x1; ++x) m.at(x, y) = 20 + k;
      }
    if (trial % 3 == 2)
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          if (rng() % 4 == 0) m.at(x, y) = std::array{0, 1, 2, -1}[rng() % 4];
    const BoundaryGraph wide = detail::build_boundary_graph(m, true, trial % 2 == 0);
    const BoundaryGraph narrow = detail::build_boundary_graph(m, false);
    ASSERT_EQ(wide.junctions.size(), narrow.junctions.size()) << "trial " << trial;
    for (std::size_t j = 0; j < wide.junctions.size(); ++j) {
      EXPECT_EQ(wide.junctions[j].position, narrow.junctions[j].position);
      EXPECT_EQ(wide.junctions[j].boundaries, narrow.junctions[j].boundaries);
    }
    ASSERT_EQ(wide.boundaries.size(), narrow.boundaries.size()) << "trial " << trial;
    int closed = 0;
    for (std::size_t i = 0; i < wide.boundaries.size(); ++i) {
      const Boundary& a = wide.boundaries[i];
      const Boundary& b = narrow.boundaries[i];
      EXPECT_EQ(a.left, b.left);
      EXPECT_EQ(a.right, b.right);
      EXPECT_EQ(a.start, b.start);
      EXPECT_EQ(a.end, b.end);
      EXPECT_TRUE(a.points == b.points) << "trial " << trial << ", boundary " << i;
      closed += a.closed();
    }
    loops += closed;
  }
  EXPECT_GT(loops, 3);  // the closed-loop scan had work to do
}

// The layering gives the trace the outline fill's box of the non-zero
// labels: the rows are scanned only across it, to the same graph as the
// whole rows give (strand maps with islands set in a larger map of zeros at
// random places, touching its sides or not; the tight box and a looser one;
// eight and sixteen corners at a time).
TEST(TraceRows, RowsScannedAcrossTheBoxTraceLikeWholeRows) {
  std::mt19937 rng(31);
  for (int trial = 0; trial < 24; ++trial) {
    const int iw = 1 + static_cast<int>(rng() % 120), ih = 1 + static_cast<int>(rng() % 80);
    const LabelMap inner = strand_map(iw, ih, 900 + trial, 1 + trial % 4);
    const int left = trial % 4 == 0 ? 0 : static_cast<int>(rng() % 40);
    const int top = trial % 5 == 0 ? 0 : static_cast<int>(rng() % 30);
    const int w = left + iw + (trial % 3 == 0 ? 0 : static_cast<int>(rng() % 50));
    const int h = top + ih + (trial % 4 == 1 ? 0 : static_cast<int>(rng() % 30));
    LabelMap m(w, h, 0);
    for (int y = 0; y < ih; ++y)
      for (int x = 0; x < iw; ++x) m.at(left + x, top + y) = inner.at(x, y);
    // Labels that change along the box's sides: junctions on its edges.
    if (trial % 3 != 2) {
      for (int y = 0; y < ih; ++y) {
        m.at(left, top + y) = 40 + (y / 3) % 2;
        m.at(left + iw - 1, top + y) = 42 + (y / 2) % 2;
      }
      for (int x = 0; x < iw; ++x) {
        m.at(left + x, top) = 44 + (x / 4) % 2;
        m.at(left + x, top + ih - 1) = 46 + (x / 3) % 2;
      }
    }
    if (trial % 2 == 1)  // an island: a rectangle inside a rectangle
      for (int y = top + ih / 4; y < top + ih / 2; ++y)
        for (int x = left + iw / 4; x < left + iw / 2; ++x) m.at(x, y) = 30;
    detail::LabelBox tight;
    tight.any = detail::label_box(m, &tight.x0, &tight.y0, &tight.x1, &tight.y1);
    detail::LabelBox loose = tight;
    loose.x0 = std::max(0, loose.x0 - 3), loose.y0 = std::max(0, loose.y0 - 2);
    loose.x1 = std::min(w - 1, loose.x1 + 5), loose.y1 = std::min(h - 1, loose.y1 + 1);
    const BoundaryGraph want = detail::build_boundary_graph(m, false);
    for (const detail::LabelBox* box : {&tight, &loose})
      for (const bool widest : {false, true}) {
        const BoundaryGraph got = detail::build_boundary_graph(m, true, widest, box);
        ASSERT_EQ(got.junctions.size(), want.junctions.size()) << "trial " << trial;
        for (std::size_t j = 0; j < got.junctions.size(); ++j) {
          EXPECT_EQ(got.junctions[j].position, want.junctions[j].position) << "trial " << trial;
          EXPECT_EQ(got.junctions[j].boundaries, want.junctions[j].boundaries);
        }
        ASSERT_EQ(got.boundaries.size(), want.boundaries.size()) << "trial " << trial;
        for (std::size_t i = 0; i < got.boundaries.size(); ++i) {
          EXPECT_EQ(got.boundaries[i].left, want.boundaries[i].left);
          EXPECT_EQ(got.boundaries[i].right, want.boundaries[i].right);
          EXPECT_TRUE(got.boundaries[i].points == want.boundaries[i].points)
              << "trial " << trial << ", boundary " << i;
        }
      }
  }
}

// The region ids the layering reads off the input map (skipping runs of one
// label, a cache of labels met before) are LabelMap::labels: on strand maps,
// noise, negative and large labels, more labels than the cache has slots,
// maps narrower than a block, and a map large enough to be read in halves;
// blocks compared sixteen labels at a time (AVX-512) and four (SSE2).
TEST(DistinctLabels, EqualLabelMapLabels) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 30; ++trial) {
    const int w = 1 + static_cast<int>(rng() % 90), h = 1 + static_cast<int>(rng() % 70);
    LabelMap m = strand_map(w, h, 300 + trial, 1 + trial % 4);
    if (trial % 3 == 1)
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          if (rng() % 5 == 0) m.at(x, y) = static_cast<int>(rng() % 300) - 100;
    if (trial % 3 == 2) m.at(w - 1, h - 1) = 1 << 30;
    EXPECT_EQ(detail::distinct_labels(m), m.labels()) << "trial " << trial;
    EXPECT_EQ(detail::distinct_labels(m, nullptr, false), m.labels()) << "trial " << trial;
  }
  LabelMap aliased(40, 3, 0);  // 5, 69, 133 share a cache slot
  for (int x = 0; x < 40; ++x) aliased.at(x, x % 3) = std::array{5, 69, 133, 0}[x % 4];
  EXPECT_EQ(detail::distinct_labels(aliased), (std::vector<int>{5, 69, 133}));
  EXPECT_TRUE(detail::distinct_labels(LabelMap(17, 5, 0)).empty());
  // Large maps are read in two halves: labels only in one half, and a run
  // across the split.
  LabelMap large = strand_map(700, 451, 9, 3);
  large.at(3, 5) = 1000;
  large.at(699, 450) = -7;
  for (int x = 0; x < 700; ++x) large.at(x, 225) = 55;
  EXPECT_EQ(detail::distinct_labels(large), large.labels());
  EXPECT_EQ(detail::distinct_labels(large, nullptr, false), large.labels());
  // Started on a pool and read later (as the layering does, filling
  // outlines meanwhile), the halves on its helper or on the caller.
  for (const int helpers : {0, 1}) {
    detail::Pool pool(helpers);
    detail::DistinctLabels scan(large, &pool);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    EXPECT_EQ(scan.get(), large.labels()) << helpers << " helpers";
    detail::DistinctLabels at_once(large, &pool, false);
    EXPECT_EQ(at_once.get(), large.labels()) << helpers << " helpers";
  }
}

// The labels that change, found sixteen at a time (AVX-512: a block against
// the block a pixel to its left) over parts of rows, as the fill reads its
// label box, are those of the plain pass and of a set of every label:
// ranges from 0 to 70 labels starting anywhere, runs, noise with negative
// labels and labels sharing a cache slot, a label first met at a block's
// last lane.
TEST(DistinctLabels, ChangesFoundSixteenAtOnceEqualThePlainPass) {
  std::mt19937 rng(41);
  std::vector<int> data(4000);
  for (int trial = 0; trial < 400; ++trial) {
    const int kind = trial % 4;
    for (std::size_t i = 0; i < data.size(); ++i) {
      if (kind == 0) data[i] = static_cast<int>(rng() % 7);
      if (kind == 1) data[i] = i % 23 < 11 ? 64 * static_cast<int>(rng() % 4) + 5 : 0;
      if (kind == 2) data[i] = static_cast<int>(rng() % 300) - 100;
      if (kind == 3)
        data[i] = rng() % 40 == 0 ? static_cast<int>(rng() % 9) : (i > 0 ? data[i - 1] : 0);
    }
    const std::size_t from = rng() % 3000, to = from + rng() % 71;
    data[from + 16 < to ? from + 16 : from] = 1 << 30;
    std::set<int> widest, plain, every;
    detail::distinct_labels_into(data.data(), from, to, widest, true);
    detail::distinct_labels_into(data.data(), from, to, plain, false);
    for (std::size_t i = from; i < to; ++i)
      if (data[i] != 0) every.insert(data[i]);
    EXPECT_EQ(widest, every) << "trial " << trial;
    EXPECT_EQ(plain, every) << "trial " << trial;
  }
}

// Sixteen, eight or four pixels at a time (AVX-512, AVX2, SSE2)
// against the formula pixel by pixel, to the bit: odd widths (the tails),
// windows, translucent rows.
TEST(GreyLevels, EqualTheFormula) {
  for (const auto& [w, h, translucent] :
       {std::tuple{157, 93, false}, std::tuple{3, 5, true}, std::tuple{120, 75, true}}) {
    Image image = test_image(w, h, 9, translucent);
    std::mt19937 rng(w);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        Rgba& p = image.at(x, y);
        p.r = static_cast<std::uint8_t>(rng()), p.g = static_cast<std::uint8_t>(rng());
        p.b = static_cast<std::uint8_t>(rng());
      }
    for (const auto& [x0, y0, ww, hh] :
         {std::array{0, 0, w, h}, std::array{1, 2, w - 1, h - 2}, std::array{w / 3, h / 2, 2, 1}}) {
      if (ww <= 0 || hh <= 0) continue;
      for (const bool widest : {true, false}) {
        std::vector<float> got(static_cast<std::size_t>(ww) * hh);
        detail::grey_levels(image, x0, y0, ww, hh, got.data(), widest);
        int differ = 0;
        for (int y = 0; y < hh; ++y)
          for (int x = 0; x < ww; ++x) {
            const Rgba& p = image.at(x0 + x, y0 + y);
            const double a = p.a / 255.0, lum = 0.299 * p.r + 0.587 * p.g + 0.114 * p.b;
            const float want = static_cast<float>(p.a == 255 ? lum : a * lum + (1.0 - a) * 255.0);
            differ += got[static_cast<std::size_t>(y) * ww + x] != want;
          }
        EXPECT_EQ(differ, 0) << w << "x" << h << " window at " << x0 << "," << y0
                             << (widest ? ", AVX-512 where there is one" : "");
      }
    }
  }
}

// The Laplacian the noise estimate reads at a sixteenth of the pixels is
// cv::Laplacian's (ksize 1, edges reflected) to the bit: every pixel of
// random grey levels, windows of a larger image (row stride), one-pixel-wide
// and tiny images.
TEST(GreyLevels, SparseLaplacianEqualsOpenCVs) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<float> grey(0.0f, 255.0f);
  for (const auto& [w, h] : {std::pair{97, 61}, std::pair{1, 1}, std::pair{1, 9}, std::pair{7, 1},
                             std::pair{2, 3}, std::pair{160, 33}}) {
    cv::Mat image(h + 6, w + 10, CV_32F);
    for (int y = 0; y < image.rows; ++y)
      for (int x = 0; x < image.cols; ++x) image.at<float>(y, x) = grey(rng);
    const cv::Mat window = image(cv::Rect(4, 3, w, h));
    cv::Mat want;
    cv::Laplacian(window, want, CV_32F, 1, 1.0, 0.0, cv::BORDER_DEFAULT | cv::BORDER_ISOLATED);
    int differ = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        differ += detail::laplacian_at(window.ptr<float>(), w, h,
                                       static_cast<std::ptrdiff_t>(window.step1()), x,
                                       y) != want.at<float>(y, x);
    EXPECT_EQ(differ, 0) << w << "x" << h;
  }
}

// Converting grey levels only near the regions (and the rest when a window
// reaches it: wide lines, a window far from them) measures to the bit like
// converting the whole image, with and without the early blur.
TEST(GreyLevels, ConvertedNearTheRegionsMeasureLikeTheWholeImage) {
  const Image image = test_image(420, 333, 6, true);
  LabelMap labels(image.width(), image.height(), 0);
  for (int y = 120; y < 210; ++y)
    for (int x = 150 + y / 9; x < 260; ++x) labels.at(x, y) = 1 + (x / 31 + y / 27) % 4;
  const BoundaryGraph graph = build_boundary_graph(labels);
  const auto [bx0, by0, bx1, by1] = test::inner_boundary_box(graph, image.width(), image.height());
  for (const double lw : {2.0, 4.6, 15.0}) {
    const int m = LineResponse::window_margin(lw);
    for (const int far : {0, 1}) {
      // far: a window reaching the image's corner, beyond what was converted.
      const int x0 = far ? 0 : bx0 - m, y0 = far ? 0 : by0 - m;
      LineResponse whole(image);
      whole.prepare(lw, labels);
      whole.smooth(lw, x0, y0, bx1 + m, by1 + m);
      LineResponse near(image, &labels);
      near.prepare(lw, labels);
      near.smooth(lw, x0, y0, bx1 + m, by1 + m);
      LineResponse plain(image, &labels);
      plain.smooth(lw, x0, y0, bx1 + m, by1 + m);
      EXPECT_EQ(whole.noise_sigma(), near.noise_sigma());
      EXPECT_EQ(whole.noise_sigma(), plain.noise_sigma());
      int compared = 0;
      for (const Boundary& b : graph.boundaries) {
        if (b.left == kOutsideLabel || b.right == kOutsideLabel) continue;
        const auto want = whole.measure(b.points, 1.5 * lw, labels, b.left, b.right);
        for (const LineResponse* got : {&near, &plain}) {
          const auto m2 = got->measure(b.points, 1.5 * lw, labels, b.left, b.right);
          EXPECT_EQ(want.contrast, m2.contrast) << "line width " << lw << ", far " << far;
          EXPECT_EQ(want.contrast_low, m2.contrast_low) << "line width " << lw;
          EXPECT_EQ(want.colour_difference, m2.colour_difference) << "line width " << lw;
        }
        compared += want.contrast != 0.0;
      }
      EXPECT_GT(compared, 5) << "line width " << lw;
    }
  }
}

// Which rows hold translucent pixels is read beside the grey levels in the
// box converted near the regions, and from the image elsewhere: a row whose
// only translucent pixels lie left or right of that box, or a row above it,
// is still smoothed as translucent (as when the whole image is converted).
TEST(GreyLevels, TranslucentPixelsBesideTheConvertedBoxCount) {
  Image image = test_image(420, 333, 6, false);
  LabelMap labels(image.width(), image.height(), 0);
  for (int y = 120; y < 210; ++y)
    for (int x = 150 + y / 9; x < 260; ++x) labels.at(x, y) = 1 + (x / 31 + y / 27) % 4;
  // Left and right of the box (56 px about the regions) in rows through it,
  // and in rows above it.
  for (int y = 125; y < 200; y += 5) {
    image.at(20 + y % 11, y).a = 90;
    image.at(400 - y % 7, y + 2).a = 0;
  }
  for (int y = 20; y < 40; y += 3) image.at(60 + y, y).a = 140;
  const double lw = 3.0;
  LineResponse whole(image);
  whole.smooth(lw, 0, 0, image.width(), image.height());
  LineResponse near(image, &labels);
  near.smooth(lw, 0, 0, image.width(), image.height());
  int differ = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      differ += whole.smoothed_colour(x, y) != near.smoothed_colour(x, y);
  EXPECT_EQ(differ, 0);
}

}  // namespace
}  // namespace hair25d::layering
