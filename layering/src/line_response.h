// Is a boundary on a drawn line (paper §4.1)? The paper sums the Laplacian
// along it; we measure a dark bar directly — the line centre darker than both
// sides one line width away — which is robust to step edges between cel
// tones, where a Laplacian answers too.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <future>
#include <memory>
#include <vector>

#include "hair25d/core/geometry.h"
#include "hair25d/core/image.h"
#include "parallel.h"

namespace hair25d::layering::detail {

using Rgb3f = std::array<float, 3>;
struct LabelBox;  // raster_scan.h

// How far from a boundary point the line measurements look (pixels): for
// the line centre, for paper, and for paint on each side.
struct Reach {
  double half, paper, paint_near, paint_far;
};
inline Reach reach_of(double line_width) {
  return {0.5 * line_width + 1.0, 3.0 * line_width + 2.0, line_width + 2.0, 2.5 * line_width + 3.0};
}

// What is measured along one boundary.
struct BoundaryLine {
  double contrast = 0.0;      // median over samples of the line's contrast (grey levels)
  double contrast_low = 0.0;  // its lower quartile: low where a line fades out along the boundary
  // Median over samples of the colour distance (RGB, 0..255 per channel,
  // Euclidean / √3) between the two sides just beyond the line: two halves of
  // one strand share their paint, an occluder often does not.
  double colour_difference = 0.0;
  // colour_line only: median over samples of the brighter side's paper grey
  // level (0 without samples), what black ink could show there at most.
  double paper = 0.0;
};

// Grey levels of [x0, x0 + w) × [y0, y0 + h) of `image` into `out` (w × h,
// row-major): 0.299 r + 0.587 g + 0.114 b summed in double, as float;
// translucent pixels blended over white paper. What LineResponse measures on.
// With `widest` false, not sixteen pixels at a time even where the processor
// has AVX-512F (the same floats, for tests).
void grey_levels(const Image& image, int x0, int y0, int w, int h, float* out, bool widest = true);

// The 4-neighbour Laplacian at (x, y) of the w × h grey levels `grey` (rows
// `stride` floats apart), edges reflected (BORDER_REFLECT_101): the float
// cv::Laplacian (ksize 1) gives there. The noise estimate reads it at a
// sixteenth of the pixels instead of filtering them all.
float laplacian_at(const float* grey, int w, int h, std::ptrdiff_t stride, int x, int y);

class LineResponse {
 public:
  // Grey levels of `image` smoothed at a scale from the line width, kept for
  // the window [x0, x1) × [y0, y1) only (clipped to the image): the part that
  // holds the boundaries, with a margin. Samples outside it are clamped.
  // Colours are read from `image` when sampled: it must outlive this.
  LineResponse(const Image& image, double line_width, int x0, int y0, int x1, int y1);

  // The same in two steps: the constructor starts converting `image` to grey
  // levels on a second core (the caller meanwhile prepares the boundaries),
  // smooth() then smooths the window once the line width is known. Nothing
  // may be measured before smooth(). With `regions` (the map whose filled
  // boundaries will be measured; unchanged until prepare() or smooth()) only
  // the part of the image near its non-zero labels is converted at first;
  // the rest is converted when a window reaches it.
  // With `convert_later`, the conversion starts only at prepare() (near the
  // box it is given) or smooth(): then the second core is free for the
  // caller's other work until then.
  explicit LineResponse(const Image& image, const LabelMap* regions = nullptr,
                        bool convert_later = false);
  // With `noise_by_caller` the noise is not estimated on the second core
  // after the early blur: the caller calls estimate_noise() (e.g. as one
  // item of its parallel measurements), where the second core's thread, a
  // third one, would wait for a core until they end.
  void smooth(double line_width, int x0, int y0, int x1, int y1, bool noise_by_caller = false);
  // The noise estimate smooth() left to the caller (nothing otherwise);
  // measurements may run meanwhile on other threads.
  void estimate_noise();
  // Optional, between the two: starts blurring, on a second core, the box of
  // the non-zero labels of `filled` (the map whose boundaries will be
  // measured) grown by window_margin(line_width); smooth() with the same
  // line width then uses it if it holds smooth()'s window. `filled` must
  // stay unchanged until smooth(). With `box`, the box of `filled`'s
  // non-zero labels (label_box's answer; fill_outlines gives it), which is
  // then not looked for.
  void prepare(double line_width, const LabelMap& filled, const LabelBox* box = nullptr);

  LineResponse(const LineResponse&) = delete;
  LineResponse& operator=(const LineResponse&) = delete;
  ~LineResponse();

  // How far the window must reach beyond the boundaries measured for their
  // measurements to be those on the whole image: the farthest sample, its
  // pixel footprint and the smoothing kernels' radius.
  static int window_margin(double line_width);

  // Median over samples along `curve` (pixel corners) of
  // min(paper left, paper right) − darkest point of the line's cross-section,
  // ignoring `skip` pixels at each end. "Paper" on a side is the brightest
  // point within three line widths along the normal that still lies in that
  // side's region of `labels` (`left`/`right`): crowded lines beside the
  // boundary (hair tips) do not hide its own line.
  double boundary_contrast(const Polyline& curve, double skip, const LabelMap& labels, int left,
                           int right) const {
    return measure(curve, skip, labels, left, right).contrast;
  }
  // The same contrast with its lower quartile and the colour difference
  // across the boundary (sampled 1–2 line widths beyond its centre, in each
  // side's own region, on colours smoothed at half a line width).
  BoundaryLine measure(const Polyline& curve, double skip, const LabelMap& labels, int left,
                       int right) const;

  // With `on`, measure() checks the bounds of every sample, as it does near
  // the window's and the map's edges (for tests: the same values).
  void check_every_sample(bool on) { check_every_sample_ = on; }
  // With `on` (the default where the processor has AVX2), colours are
  // smoothed and grey levels sampled eight floats or four doubles at a
  // time; off, four floats or one double (for tests: the same values).
  void use_wide_vectors(bool on) {
    wide_vectors_ = on && wide_vectors_available();
    widest_vectors_ = on && widest_vectors_available();
  }
  static bool wide_vectors_available();
  // With `on` (the default where the processor has AVX-512F) and wide
  // vectors, colours are smoothed four pixels per register instead of two
  // (for tests: the same values).
  void use_widest_vectors(bool on) {
    widest_vectors_ = on && wide_vectors_ && widest_vectors_available();
  }
  static bool widest_vectors_available();

  // The image's colour at pixel (x, y) smoothed at half a line width (a
  // Gaussian, OpenCV's kernel, edges of the window repeated); pixels outside
  // the window are clamped to it. Translucent pixels are blended over white.
  Rgb3f smoothed_colour(int x, int y) const;

  // Estimated standard deviation of pixel noise (grey levels) from the
  // median absolute deviation of a Laplacian, for a floor of the threshold.
  // (After the early blur it is estimated on a second core while the
  // caller measures lines, and waited for here.)
  double noise_sigma() const { return noise_.valid() ? noise_.get() : noise_sigma_; }
  // The same noise after the blur at a quarter line width that the lines
  // are measured on: σ × Σ k_i² of the blur's 1-D kernel (the 2-D kernel's
  // weights are k_i k_j, so its gain on i.i.d. noise is (Σ k_i²)² in
  // variance), about σ / (2√π × the blur's σ).
  double smoothed_noise_sigma() const;

  // Line width estimated from the image alone: the most common width of dark
  // runs across rows and columns, for maps that carry no outlines.
  static double estimate_line_width(const Image& image);

 private:
  std::array<double, 3> sample_colour(double x, double y) const;
  int x0_ = 0, y0_ = 0, w_ = 0, h_ = 0;
  double line_width_ = 1.0;
  double noise_sigma_ = 0.0;
  bool check_every_sample_ = false;
  bool wide_vectors_ = false;
  bool widest_vectors_ = false;
  const Image* image_ = nullptr;  // colours are smoothed from it where sampled
  // Grey levels of the whole image, unsmoothed, and per image row whether it
  // holds a translucent pixel; made on a second core (converting_).
  std::unique_ptr<float[]> raw_;
  std::vector<std::uint8_t> image_translucent_;
  // The part of raw_ converted: [raw_x0_, raw_x1_) × [raw_y0_, raw_y1_).
  int raw_x0_ = 0, raw_y0_ = 0, raw_x1_ = 0, raw_y1_ = 0;
  // Converts the whole image unless raw_ holds [x0, x1) × [y0, y1) (clipped).
  void ensure_raw(int x0, int y0, int x1, int y1);
  // Starts the conversion on the second core (once): first the part near
  // `near` (a box of non-zero labels) where given, else near `regions_`'s.
  void start_converting(const LabelBox* near);
  const LabelMap* regions_ = nullptr;
  bool conversion_started_ = false;
  std::future<void> converting_;
  // The early blur (prepare): its window and line width, and its result.
  struct EarlyWindow {
    int x0 = 0, y0 = 0, w = 0, h = 0;
    double line_width = 0.0;
  };
  EarlyWindow early_;
  std::unique_ptr<float[]> early_grey_;
  // The early blur runs in bands of rows; the second core takes them one by
  // one, and smooth() takes those still left when it is called. early_ and
  // early_grey_ are set before early_ready_ (then bands may be taken).
  static constexpr int kEarlyBands = 4;
  std::atomic<int> next_early_band_{0};
  std::atomic<bool> early_ready_{false};
  void blur_early_bands();
  std::future<void> smoothing_;
  std::shared_future<double> noise_;  // noise_sigma() once the early blur was used
  // The window of raw_ whose noise estimate_noise() is to read (w 0: none).
  int noise_x0_ = 0, noise_y0_ = 0, noise_w_ = 0, noise_h_ = 0;
  // w_ × h_, row-major.
  std::unique_ptr<float[]> grey_;
  std::vector<float> colour_kernel_;
  // Each weight four times (a pixel's lanes), zero-padded to a multiple of 4 weights.
  std::vector<float> colour_weights_;
  // translucent_rows_[y]: how many of the window's rows above y hold a pixel
  // with alpha < 255.
  std::vector<int> translucent_rows_;
  // The second core's thread for the conversion, the early blur and the
  // noise, in that order. Last, so it ends (running what is queued) before
  // the buffers its jobs use go.
  Worker worker_;
};

}  // namespace hair25d::layering::detail
