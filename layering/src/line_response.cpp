#include "line_response.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <future>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "hair25d/core/error.h"
#include "line_samples.h"
#include "raster_scan.h"

namespace hair25d::layering::detail {
namespace {

// Transparent pixels read as white paper.
inline float grey_value(const Rgba& p) {
  const double a = p.a / 255.0;
  const double lum = 0.299 * p.r + 0.587 * p.g + 0.114 * p.b;
  return static_cast<float>(a * lum + (1.0 - a) * 255.0);
}

// Four floats (r, g, b, a) in one SSE register: the colour smoothing works
// on a pixel's three channels at once.
using Float4 = float __attribute__((vector_size(16)));
using Byte4 = std::uint8_t __attribute__((vector_size(4)));

inline Float4 opaque_value(const Rgba& p) {
  Byte4 b;
  std::memcpy(&b, &p, sizeof b);
  return __builtin_convertvector(b, Float4);
}

// Transparent pixels read as white paint, as in grey_value.
inline Float4 colour_value(const Rgba& p) {
  if (p.a == 255) return opaque_value(p);  // the common case, where the blend is exact
  const float a = p.a / 255.0f;
  return Float4{a * p.r + (1 - a) * 255.0f, a * p.g + (1 - a) * 255.0f, a * p.b + (1 - a) * 255.0f,
                0.0f};
}

// Fills `grey` (window-sized) in `r` from the window at (x0, y0) of `image`.
// Rows are made as if opaque (a = 1 leaves lum unchanged, exactly) and only
// redone pixel by pixel when some alpha is not 255.
// `translucent`, if given, gets a flag per row of `r`: does it hold a pixel
// with alpha below 255?
void grey_into(const Image& image, int x0, int y0, const cv::Rect& r, cv::Mat& grey,
               std::uint8_t* translucent = nullptr, bool wide = false, bool widest = false) {
  static_assert(sizeof(Rgba) == 4);
  for (int y = r.y; y < r.y + r.height; ++y) {
    float* row = grey.ptr<float>(y) + r.x;
    const Rgba* src = image.data() + static_cast<std::size_t>(y0 + y) * image.width() + x0 + r.x;
    unsigned alpha = 255;
    int x = 0;
#if defined(HAIR25D_LAYERING_AVX2)
    if (wide && widest) x = grey_row_avx512(src, r.width, row, &alpha);
    if (wide) x += grey_row_avx2(src + x, r.width - x, row + x, &alpha);
#else
    (void)wide, (void)widest;
#endif
#if defined(__SSE2__)
    // Four pixels at a time, two per double vector: the same products and
    // sums in the same order as below, so the same floats.
    const __m128i byte = _mm_set1_epi32(0xFF);
    const __m128d wr = _mm_set1_pd(0.299), wg = _mm_set1_pd(0.587), wb = _mm_set1_pd(0.114);
    __m128i alphas = _mm_set1_epi32(-1);
    auto lum = [&](__m128i r4, __m128i g4, __m128i b4) {
      return _mm_add_pd(
          _mm_add_pd(_mm_mul_pd(wr, _mm_cvtepi32_pd(r4)), _mm_mul_pd(wg, _mm_cvtepi32_pd(g4))),
          _mm_mul_pd(wb, _mm_cvtepi32_pd(b4)));
    };
    for (; x + 4 <= r.width; x += 4) {
      const __m128i px = _mm_loadu_si128(reinterpret_cast<const __m128i*>(src + x));
      const __m128i r4 = _mm_and_si128(px, byte);
      const __m128i g4 = _mm_and_si128(_mm_srli_epi32(px, 8), byte);
      const __m128i b4 = _mm_and_si128(_mm_srli_epi32(px, 16), byte);
      alphas = _mm_and_si128(alphas, px);
      const __m128d lo = lum(r4, g4, b4);
      const __m128d hi = lum(_mm_shuffle_epi32(r4, 0x0E), _mm_shuffle_epi32(g4, 0x0E),
                             _mm_shuffle_epi32(b4, 0x0E));
      _mm_storeu_ps(row + x, _mm_movelh_ps(_mm_cvtpd_ps(lo), _mm_cvtpd_ps(hi)));
    }
    alignas(16) std::uint32_t lanes[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(lanes), alphas);
    for (std::uint32_t v : lanes) alpha &= v >> 24;
#endif
    for (; x < r.width; ++x) {
      const Rgba p = src[x];
      row[x] = static_cast<float>(0.299 * p.r + 0.587 * p.g + 0.114 * p.b);
      alpha &= p.a;
    }
    if (translucent) translucent[y - r.y] = alpha != 255;
    if (alpha != 255)
      for (int i = 0; i < r.width; ++i)
        if (src[i].a != 255) row[i] = grey_value(src[i]);
  }
}

// Grey levels of the window [x0, x0 + w) × [y0, y0 + h) of `image`.
cv::Mat grey_of(const Image& image, int x0, int y0, int w, int h) {
  cv::Mat grey(h, w, CV_32F);
  grey_into(image, x0, y0, cv::Rect(0, 0, w, h), grey, nullptr,
            LineResponse::wide_vectors_available(), LineResponse::widest_vectors_available());
  return grey;
}

double median_of(std::vector<double>& v) {
  if (v.empty()) return 0.0;
  auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

double grey_sigma(double line_width) { return std::max(0.6, 0.25 * line_width); }
double colour_sigma(double line_width) { return std::max(1.0, 0.5 * line_width); }
// At least the radius of the kernel cv::GaussianBlur makes for a float image
// (size round(8σ + 1) | 1).
int kernel_radius(double sigma) { return static_cast<int>(std::ceil(4.0 * sigma)) + 1; }

// Noise: MAD of a 3x3 Laplacian on the raw grey window (its edges
// reflected, as if it were the whole image), over every fourth pixel of
// every fourth row, scaled for a Gaussian. Only those pixels' Laplacian is
// computed (laplacian_at: the values of cv::Laplacian over the window, a
// sixteenth of its work).
double noise_of(const cv::Mat& grey) {
  std::vector<double> mags;
  mags.reserve(static_cast<std::size_t>(grey.total()) / 16 + 1);
  for (int y = 0; y < grey.rows; y += 4)
    for (int x = 0; x < grey.cols; x += 4)
      mags.push_back(std::abs(laplacian_at(grey.ptr<float>(), grey.cols, grey.rows,
                                           static_cast<std::ptrdiff_t>(grey.step1()), x, y)));
  // A 4-neighbour Laplacian of i.i.d. noise has σ·√20.
  return median_of(mags) * 1.4826 / std::sqrt(20.0);
}

// Whether each row of `image` holds a pixel with alpha below 255.
// Whether each row of the image has a pixel that is not opaque. The rows
// y0 <= y < y1 between x0 and x1 have been read already (`known`, one per
// row, from grey_into): only the rest of them is scanned.
std::vector<std::uint8_t> translucent_rows_of(const Image& image, int x0 = 0, int y0 = 0,
                                              int x1 = 0, int y1 = 0,
                                              const std::uint8_t* known = nullptr) {
  std::vector<std::uint8_t> out(image.height(), 0);
  auto alpha_of = [](const Rgba* src, int n) {
    unsigned alpha = 255;
    int x = 0;
#if defined(__SSE2__)
    __m128i all = _mm_set1_epi32(-1);
    for (; x + 4 <= n; x += 4)
      all = _mm_and_si128(all, _mm_loadu_si128(reinterpret_cast<const __m128i*>(src + x)));
    alignas(16) std::uint32_t lanes[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(lanes), all);
    for (std::uint32_t v : lanes) alpha &= v >> 24;
#endif
    for (; x < n; ++x) alpha &= src[x].a;
    return alpha;
  };
  for (int y = 0; y < image.height(); ++y) {
    const Rgba* src = image.data() + static_cast<std::size_t>(y) * image.width();
    if (known != nullptr && y >= y0 && y < y1)
      out[y] = known[y - y0] || (alpha_of(src, x0) & alpha_of(src + x1, image.width() - x1)) != 255;
    else
      out[y] = alpha_of(src, image.width()) != 255;
  }
  return out;
}

}  // namespace

float laplacian_at(const float* grey, int w, int h, std::ptrdiff_t stride, int x, int y) {
  if (x > 0 && y > 0 && x + 1 < w && y + 1 < h) {  // inside: no edge to reflect
    const float* p = grey + y * stride + x;
    float s = 0.0f;
    s += p[-stride];
    s += p[-1];
    s += -4.0f * p[0];
    s += p[1];
    s += p[stride];
    return s;
  }
  auto reflect = [](int i, int n) {
    if (n == 1) return 0;
    if (i < 0) return -i;
    if (i >= n) return 2 * n - 2 - i;
    return i;
  };
  auto at = [&](int xx, int yy) { return grey[yy * stride + xx]; };
  const int xl = reflect(x - 1, w), xr = reflect(x + 1, w);
  const int yu = reflect(y - 1, h), yd = reflect(y + 1, h);
  // The kernel's non-zero taps in raster order added to 0 one after another,
  // as OpenCV's 2-D filter adds them; the products by 1 and −4 are exact, so
  // with or without fused multiply-adds the float is the same.
  float s = 0.0f;
  s += at(x, yu);
  s += at(xl, y);
  s += -4.0f * at(x, y);
  s += at(xr, y);
  s += at(x, yd);
  return s;
}

void grey_levels(const Image& image, int x0, int y0, int w, int h, float* out, bool widest) {
  cv::Mat grey(h, w, CV_32F, out);
  grey_into(image, x0, y0, cv::Rect(0, 0, w, h), grey, nullptr,
            LineResponse::wide_vectors_available(),
            widest && LineResponse::widest_vectors_available());
}

bool LineResponse::wide_vectors_available() {
#if defined(HAIR25D_LAYERING_AVX2)
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}

bool LineResponse::widest_vectors_available() {
#if defined(HAIR25D_LAYERING_AVX2)
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("avx512f");
#else
  return false;
#endif
}

int LineResponse::window_margin(double line_width) {
  const double lw = std::max(1.0, line_width);
  const Reach reach = reach_of(lw);
  // A sample reads pixels up to 2 beyond its point (bilinear footprint,
  // pixel centres), and a smoothed pixel reads the kernel's radius around it.
  const double grey = std::max(reach.half, reach.paper) + 2.0 + kernel_radius(grey_sigma(lw));
  const double colour = reach.paint_far + 2.0 + kernel_radius(colour_sigma(lw));
  return static_cast<int>(std::ceil(std::max(grey, colour)));
}

LineResponse::LineResponse(const Image& image, const LabelMap* regions, bool convert_later)
    : image_(&image), regions_(regions) {
  wide_vectors_ = wide_vectors_available();
  widest_vectors_ = widest_vectors_available();
  const int w = image.width(), h = image.height();
  raw_ = std::make_unique_for_overwrite<float[]>(static_cast<std::size_t>(w) * h);
  if (!convert_later) start_converting(nullptr);
}

void LineResponse::start_converting(const LabelBox* near) {
  if (conversion_started_) return;
  conversion_started_ = true;
  const int w = image_->width(), h = image_->height();
  // The grey levels need nothing but the image: a second core converts them
  // while the caller fills outlines and traces boundaries. It writes only
  // raw_, its box and image_translucent_, which nothing reads before
  // prepare()'s blur or smooth() waits.
  auto convert = [this, regions = regions_, known = near != nullptr,
                  given = near != nullptr ? *near : LabelBox{}, w, h, wide = wide_vectors_,
                  widest = widest_vectors_] {
    // Grey levels are needed in the window of the filled boundaries and a
    // kernel's reach around it: near the regions, within the outline fill's
    // reach and the window's margin at the line widths of most drawings
    // (wider lines, or no regions, convert the rest when a window needs it).
    // The rest converts to the same values when a window needs it.
    int x0 = 0, y0 = 0, x1 = w, y1 = h;
    int bx0 = given.x0, by0 = given.y0, bx1 = given.x1, by1 = given.y1;
    if (known ? given.any
              : regions && regions->width() == w && regions->height() == h &&
                    detail::label_box(*regions, &bx0, &by0, &bx1, &by1)) {
      constexpr int kNear = 56;  // outline fill 7 + margin 28 + kernel 6 at 4.6 px lines, and more
      x0 = std::clamp(bx0 - kNear, 0, w), y0 = std::clamp(by0 - kNear, 0, h);
      x1 = std::clamp(bx1 + 1 + kNear, x0, w), y1 = std::clamp(by1 + 1 + kNear, y0, h);
    }
    cv::Mat raw(h, w, CV_32F, raw_.get());
    // The conversion reads the box's pixels' alphas too: the rest of the
    // image is scanned for translucent pixels after it.
    std::vector<std::uint8_t> box_translucent(y1 - y0);
    grey_into(*image_, 0, 0, cv::Rect(x0, y0, x1 - x0, y1 - y0), raw, box_translucent.data(), wide,
              widest);
    image_translucent_ = translucent_rows_of(*image_, x0, y0, x1, y1, box_translucent.data());
    raw_x0_ = x0, raw_y0_ = y0, raw_x1_ = x1, raw_y1_ = y1;
  };
  converting_ = worker_.submit(convert);
}

void LineResponse::ensure_raw(int x0, int y0, int x1, int y1) {
  const Image& image = *image_;
  x0 = std::max(0, x0), y0 = std::max(0, y0);
  x1 = std::min(image.width(), x1), y1 = std::min(image.height(), y1);
  if (x0 >= raw_x0_ && y0 >= raw_y0_ && x1 <= raw_x1_ && y1 <= raw_y1_) return;
  cv::Mat raw(image.height(), image.width(), CV_32F, raw_.get());
  grey_into(image, 0, 0, cv::Rect(0, 0, image.width(), image.height()), raw, nullptr, wide_vectors_,
            widest_vectors_);
  raw_x0_ = 0, raw_y0_ = 0, raw_x1_ = image.width(), raw_y1_ = image.height();
}

LineResponse::LineResponse(const Image& image, double line_width, int x0, int y0, int x1, int y1)
    : LineResponse(image) {
  smooth(line_width, x0, y0, x1, y1);
}

LineResponse::~LineResponse() {
  // The conversion, the early blur and the noise read the image or this
  // object's buffers and write them: they must end before those go (also
  // when smooth() was never called). The early blur waits for the
  // conversion itself, so it is waited for first.
  if (noise_.valid()) noise_.wait();
  if (smoothing_.valid()) smoothing_.wait();
  if (converting_.valid()) converting_.wait();
}

void LineResponse::prepare(double line_width, const LabelMap& filled, const LabelBox* box) {
  if (smoothing_.valid() || filled.width() != image_->width() ||
      filled.height() != image_->height())
    return;
  // Every boundary smooth() will be given has a non-zero label on one side,
  // so it lies in the box of those labels' pixel corners; that box grown by
  // the margin holds smooth()'s window. Blurring it here, on a second core
  // while the caller traces the boundaries, gives the same values there: a
  // window's blur reads the pixels beyond it from the image.
  // No blur is under way (smoothing_ is not valid): a new one starts from
  // its first band.
  start_converting(box);
  next_early_band_ = 0;
  early_ready_ = false;
  auto blur = [this, lw = std::max(1.0, line_width), &filled, known = box != nullptr,
               given = box != nullptr ? *box : LabelBox{}] {
    if (converting_.valid()) converting_.get();  // (not after a first smooth())
    int bx0 = given.x0, by0 = given.y0, bx1 = given.x1, by1 = given.y1;
    if (known ? !given.any : !detail::label_box(filled, &bx0, &by0, &bx1, &by1)) return;
    const Image& image = *image_;
    const int margin = window_margin(lw);
    const int x0 = std::max(0, bx0 - margin), y0 = std::max(0, by0 - margin);
    const int x1 = std::min(image.width(), bx1 + 1 + margin);
    const int y1 = std::min(image.height(), by1 + 1 + margin);
    // The blur reads a kernel's radius beyond the box.
    const int kr = kernel_radius(grey_sigma(lw));
    ensure_raw(x0 - kr, y0 - kr, x1 + kr, y1 + kr);
    early_grey_ =
        std::make_unique_for_overwrite<float[]>(static_cast<std::size_t>(x1 - x0) * (y1 - y0));
    early_ = {x0, y0, x1 - x0, y1 - y0, lw};
    early_ready_.store(true, std::memory_order_release);
    blur_early_bands();
  };
  smoothing_ = worker_.submit(blur);
}

void LineResponse::blur_early_bands() {
  // A band's blur reads the rows around it from the image, as the blur of
  // the whole box does inside it: the values are those of one call.
  const Image& image = *image_;
  const cv::Mat raw(image.height(), image.width(), CV_32F, raw_.get());
  cv::Mat smooth(early_.h, early_.w, CV_32F, early_grey_.get());
  const double sigma = grey_sigma(early_.line_width);
  for (int b = next_early_band_++; b < kEarlyBands; b = next_early_band_++) {
    const int r0 = early_.h * b / kEarlyBands, r1 = early_.h * (b + 1) / kEarlyBands;
    if (r1 <= r0) continue;
    try {
      cv::Mat dst = smooth.rowRange(r0, r1);
      cv::GaussianBlur(raw(cv::Rect(early_.x0, early_.y0 + r0, early_.w, r1 - r0)), dst,
                       cv::Size(0, 0), sigma, sigma, cv::BORDER_REPLICATE);
    } catch (const cv::Exception& e) {
      throw Error(std::string("layering: OpenCV failed while smoothing grey levels: ") + e.what());
    }
  }
}

void LineResponse::smooth(double line_width, int x0, int y0, int x1, int y1, bool noise_by_caller) {
  // Blur the early bands still left here, then rethrow what the conversion
  // or the early blur threw.
  if (smoothing_.valid()) {
    if (early_ready_.load(std::memory_order_acquire)) blur_early_bands();
    smoothing_.get();
  }
  start_converting(nullptr);
  if (converting_.valid()) converting_.get();
  const Image& image = *image_;
  line_width_ = std::max(1.0, line_width);
  x0_ = std::clamp(x0, 0, std::max(0, image.width() - 1));
  y0_ = std::clamp(y0, 0, std::max(0, image.height() - 1));
  w_ = std::clamp(x1, x0_ + 1, image.width()) - x0_;
  h_ = std::clamp(y1, y0_ + 1, image.height()) - y0_;
  // The window's blur reads a kernel's radius beyond it.
  const int kr = kernel_radius(grey_sigma(line_width_));
  ensure_raw(x0_ - kr, y0_ - kr, x0_ + w_ + kr, y0_ + h_ + kr);
  // The noise is measured on this window; the smoothed grey levels may be
  // kept for the larger one blurred early, whose values here are the same.
  const cv::Rect window(x0_, y0_, w_, h_);
  const bool early = early_grey_ && early_.line_width == line_width_ && early_.x0 <= x0_ &&
                     early_.y0 <= y0_ && x0_ + w_ <= early_.x0 + early_.w &&
                     y0_ + h_ <= early_.y0 + early_.h;
  if (early) {
    x0_ = early_.x0, y0_ = early_.y0, w_ = early_.w, h_ = early_.h;
    grey_ = std::move(early_grey_);
  }
  const std::size_t n = static_cast<std::size_t>(w_) * h_;
  if (!early) grey_ = std::make_unique_for_overwrite<float[]>(n);
  translucent_rows_.assign(h_ + 1, 0);
  for (int y = 0; y < h_; ++y)
    translucent_rows_[y + 1] = translucent_rows_[y] + image_translucent_[y0_ + y];
  try {
    // Colours for the paint on each side are smoothed at half a line width
    // (screentone dots and JPEG blocks average to their tone) only where
    // they are sampled, two pixels per point measured: a few percent of the
    // window, where blurring all of it cost as much as the rest of the
    // layering. The kernel is OpenCV's, as cv::GaussianBlur would use it.
    const double cs = colour_sigma(line_width_);
    const int ksize = static_cast<int>(std::lround(cs * 4 * 2 + 1)) | 1;
    const cv::Mat k = cv::getGaussianKernel(ksize, cs, CV_32F);
    colour_kernel_.assign(k.ptr<float>(), k.ptr<float>() + ksize);
#if defined(__SSE2__)
    colour_weights_.assign((ksize + 3) / 4 * 16, 0.0f);
    for (int i = 0; i < 4 * ksize; ++i) colour_weights_[i] = colour_kernel_[i / 4];
#endif
    const cv::Mat raw(image.height(), image.width(), CV_32F, raw_.get());
    const cv::Mat grey = raw(cv::Rect(x0_, y0_, w_, h_));
    cv::Mat smooth(h_, w_, CV_32F, grey_.get());
    if (early) {
      // Only the threshold needs the noise, after every line is measured: a
      // second core estimates it meanwhile (the measurements leave the
      // grey levels unchanged), or the caller does.
      if (noise_by_caller) {
        noise_x0_ = window.x, noise_y0_ = window.y, noise_w_ = window.width,
        noise_h_ = window.height;
        return;
      }
      auto noise = [raw_window = raw(window)] {
        try {
          return noise_of(raw_window);
        } catch (const cv::Exception& e) {
          throw Error(std::string("layering: OpenCV failed while estimating noise: ") + e.what());
        }
      };
      noise_ = worker_.submit(noise).share();
      return;
    }
    // Smooth at about a quarter line width: tones (screentone dots, JPEG
    // ringing) average out while a line keeps most of its depth. The top
    // rows on a second core, the bottom ones here after the noise. A band
    // reads the rows around it from the image (a pixel beyond the window
    // differs from the replicated edge, but no sample reads that far:
    // window_margin), so the values are those of one call.
    const double sigma = grey_sigma(line_width_);
    const int split = h_ * 11 / 20;
    auto blur_rows = [&](int r0, int r1) {
      if (r1 <= r0) return;
      cv::Mat dst = smooth.rowRange(r0, r1);
      cv::GaussianBlur(grey.rowRange(r0, r1), dst, cv::Size(0, 0), sigma, sigma,
                       cv::BORDER_REPLICATE);
    };
    // Not worth a thread for small windows; where no thread can be made,
    // the band runs here at get().
    const auto policy =
        n > 20000 ? std::launch::async | std::launch::deferred : std::launch::deferred;
    auto top = std::async(policy, [&] { blur_rows(0, split); });
    noise_sigma_ = noise_of(grey);
    blur_rows(split, h_);
    top.get();
  } catch (const cv::Exception& e) {
    throw Error(std::string("layering: OpenCV failed while measuring lines: ") + e.what());
  }
}

double LineResponse::smoothed_noise_sigma() const {
  const double sigma = grey_sigma(line_width_);
  // The kernel cv::GaussianBlur makes for a float image at this σ.
  const int ksize = static_cast<int>(std::lround(sigma * 4 * 2 + 1)) | 1;
  const cv::Mat k = cv::getGaussianKernel(ksize, sigma, CV_64F);
  double gain = 0.0;
  for (int i = 0; i < ksize; ++i) gain += k.at<double>(i) * k.at<double>(i);
  return noise_sigma() * gain;
}

void LineResponse::estimate_noise() {
  if (noise_w_ == 0) return;
  const cv::Mat raw(image_->height(), image_->width(), CV_32F, raw_.get());
  try {
    noise_sigma_ = noise_of(raw(cv::Rect(noise_x0_, noise_y0_, noise_w_, noise_h_)));
  } catch (const cv::Exception& e) {
    throw Error(std::string("layering: OpenCV failed while estimating noise: ") + e.what());
  }
  noise_w_ = 0;
}

Rgb3f LineResponse::smoothed_colour(int x, int y) const {
  const int xi = std::clamp(x - x0_, 0, w_ - 1);
  const int yi = std::clamp(y - y0_, 0, h_ - 1);
  const int r = static_cast<int>(colour_kernel_.size()) / 2;
  const float* k = colour_kernel_.data();
  const int iw = image_->width();
  const Rgba* window = image_->data() + static_cast<std::size_t>(y0_) * iw + x0_;
#if defined(__SSE2__)
  // Columns first, four at a time (the kernel's width rounded up; the
  // weights past its end are 0), each pixel widened to four float lanes
  // (r, g, b, a). The kernel is symmetric: rows y − j and y + j are added as
  // integers (exact) before they are weighted. Only where the footprint lies
  // in the window and all its pixels are opaque.
  const int groups = (2 * r + 4) / 4;
  if (xi - r >= 0 && xi - r + 4 * groups <= w_ && yi - r >= 0 && yi + r < h_ &&
      translucent_rows_[yi + r + 1] == translucent_rows_[yi - r]) {
    const Rgba* centre = window + static_cast<std::size_t>(yi) * iw + xi - r;
#if defined(HAIR25D_LAYERING_AVX2)
    if (widest_vectors_)
      return colour_sum_avx512(centre, iw, r, groups, colour_kernel_.data(),
                               colour_weights_.data());
    if (wide_vectors_)
      return colour_sum_avx2(centre, iw, r, groups, colour_kernel_.data(), colour_weights_.data());
#endif
    const __m128i zero = _mm_setzero_si128();
    __m128 sum = _mm_setzero_ps();
    const float* wv = colour_weights_.data() + 4 * r;  // wv + 4j: weight j in four lanes
    auto widen = [&](__m128i half, __m128 w, bool high) {
      return _mm_mul_ps(w, _mm_cvtepi32_ps(high ? _mm_unpackhi_epi16(half, zero)
                                                : _mm_unpacklo_epi16(half, zero)));
    };
    for (int g = 0; g < groups; ++g) {
      // The centre row, then the pairs of rows j above and below it.
      const __m128i mid = _mm_loadu_si128(reinterpret_cast<const __m128i*>(centre + 4 * g));
      __m128i lo = _mm_unpacklo_epi8(mid, zero), hi = _mm_unpackhi_epi8(mid, zero);
      __m128 w = _mm_loadu_ps(wv);
      __m128 c0 = widen(lo, w, false), c1 = widen(lo, w, true);
      __m128 c2 = widen(hi, w, false), c3 = widen(hi, w, true);
      const Rgba* above = centre + 4 * g;
      const Rgba* below = centre + 4 * g;
      for (int j = 1; j <= r; ++j) {
        above -= iw;
        below += iw;
        const __m128i up = _mm_loadu_si128(reinterpret_cast<const __m128i*>(above));
        const __m128i down = _mm_loadu_si128(reinterpret_cast<const __m128i*>(below));
        lo = _mm_add_epi16(_mm_unpacklo_epi8(up, zero), _mm_unpacklo_epi8(down, zero));
        hi = _mm_add_epi16(_mm_unpackhi_epi8(up, zero), _mm_unpackhi_epi8(down, zero));
        w = _mm_loadu_ps(wv + 4 * j);
        c0 = _mm_add_ps(c0, widen(lo, w, false));
        c1 = _mm_add_ps(c1, widen(lo, w, true));
        c2 = _mm_add_ps(c2, widen(hi, w, false));
        c3 = _mm_add_ps(c3, widen(hi, w, true));
      }
      const float* wg = colour_weights_.data() + 16 * g;
      sum = _mm_add_ps(sum, _mm_mul_ps(_mm_loadu_ps(wg), c0));
      sum = _mm_add_ps(sum, _mm_mul_ps(_mm_loadu_ps(wg + 4), c1));
      sum = _mm_add_ps(sum, _mm_mul_ps(_mm_loadu_ps(wg + 8), c2));
      sum = _mm_add_ps(sum, _mm_mul_ps(_mm_loadu_ps(wg + 12), c3));
    }
    alignas(16) float out[4];
    _mm_store_ps(out, sum);
    return {out[0], out[1], out[2]};
  }
#endif
  // Near the window's edges (the edge pixel repeats, BORDER_REPLICATE, as a
  // blur of the whole window would) and around translucent pixels.
  Float4 sum = {0, 0, 0, 0};
  for (int j = -r; j <= r; ++j) {
    const Rgba* row = window + static_cast<std::size_t>(std::clamp(yi + j, 0, h_ - 1)) * iw;
    Float4 acc = {0, 0, 0, 0};
    for (int i = -r; i <= r; ++i)
      acc += k[i + r] * colour_value(row[std::clamp(xi + i, 0, w_ - 1)]);
    sum += k[j + r] * acc;
  }
  return {sum[0], sum[1], sum[2]};
}

std::array<double, 3> LineResponse::sample_colour(double x, double y) const {
  // Nearest pixel: colours are smoothed.
  const Rgb3f c = smoothed_colour(floor_int(x), floor_int(y));
  return {c[0], c[1], c[2]};
}

BoundaryLine LineResponse::measure(const Polyline& curve, double skip, const LabelMap& labels,
                                   int left, int right) const {
  BoundaryLine out;
  if (curve.size() < 2) return out;
  const Polyline pts = resample_polyline(curve, 1.0);
  const int n = static_cast<int>(pts.size());
  const double total = polyline_length(curve);
  // Near short boundaries keep at least the middle third.
  skip = std::min(skip, total / 3.0);
  const Reach r = reach_of(line_width_);  // smooth_tiles() must cover it
  const double half = r.half;             // search for the line centre
  const double reach = r.paper;           // search for paper
  const int span = std::max(2, static_cast<int>(std::lround(line_width_)));
  const GreyView grey{grey_.get(), w_,      h_, static_cast<double>(x0_), static_cast<double>(y0_),
                      w_ - 1.0,    h_ - 1.0};
  const LabelView label{labels.data(), labels.width(), labels.height()};
  std::vector<double> values, colours;
  values.reserve(n);
  // Paint is sampled past the line, its anti-aliased rim and the colour
  // smoothing (the boundary may sit half a pixel off the line's centre), and
  // before the next line of a thin strand.
  const double paint_near = r.paint_near;
  const double paint_far = r.paint_far;
  const double farthest = std::max({half, reach, paint_far}) + 1.0;
  // The steps of the centre and paper searches below, made as they make
  // them, for the wide-vector paths: padded to eight (AVX-512) by repeating
  // the last; AVX2 reads them up to the next multiple of four.
  std::vector<double> centre_steps;
  for (double s = -half; s <= half + 1e-9; s += 0.5) centre_steps.push_back(s);
  const int centre_count = static_cast<int>(centre_steps.size());
  while (centre_steps.size() % 8 != 0) centre_steps.push_back(centre_steps.back());
  const int centre_count4 = (centre_count + 3) / 4 * 4;
  int paper_steps = 0;
  for (double s = 1.0; s <= reach; s += 1.0) ++paper_steps;
  double along = 0.0;
  // Every other point is plenty for a median, except on short boundaries.
  const int stride = n > 40 ? 2 : 1;
  for (int i = 0; i < n; ++i) {
    if (i > 0) along += (pts[i] - pts[i - 1]).norm();
    if (i % stride != 0 || along < skip || along > total - skip) continue;
    const Vec2 t = pts[std::min(n - 1, i + span)] - pts[std::max(0, i - span)];
    if (t.squaredNorm() == 0.0) continue;
    // On the screen the left of travel t is (t.y, −t.x).
    const Vec2 to_left = Vec2(t.y(), -t.x()).normalized();
    const double px = pts[i].x(), py = pts[i].y(), nx = to_left.x(), ny = to_left.y();
    // Every sample below lies within `farthest` of the point along the
    // normal; where that segment is well inside the window and the map (almost
    // always) the bounds need no checks, and coordinates are >= 0, so
    // truncation is the floor: the same values, fewer instructions.
    const bool inside = !check_every_sample_ && grey.holds(px, py, farthest * nx, farthest * ny) &&
                        label.holds(px, py, farthest * nx, farthest * ny);
    auto point = [&](auto fast) {
      auto sample = [&](double x, double y) {
        if constexpr (decltype(fast)::value)
          return grey.sample_inside(x, y);
        else
          return grey.sample(x, y);
      };
      auto label_at = [&](double x, double y) {
        if constexpr (decltype(fast)::value)
          return label.at_inside(x, y);
        else
          return label.at(x, y);
      };
      double centre = 1e9;
      double paper_left = -1.0, paper_right = -1.0;
#if defined(HAIR25D_LAYERING_AVX2)
      if (decltype(fast)::value && wide_vectors_ && centre_count > 0) {
        const PointSamples got =
            widest_vectors_ ? point_samples_avx512(grey, label, px, py, nx, ny, centre_steps.data(),
                                                   static_cast<int>(centre_steps.size()),
                                                   paper_steps, left, right)
                            : point_samples_avx2(grey, label, px, py, nx, ny, centre_steps.data(),
                                                 centre_count4, paper_steps, left, right);
        centre = got.centre, paper_left = got.paper_left, paper_right = got.paper_right;
      } else
#endif
      {
        for (double s = -half; s <= half + 1e-9; s += 0.5)
          centre = std::min(centre, sample(px + s * nx, py + s * ny));
        for (double s = 1.0; s <= reach; s += 1.0) {
          const double lx = px + s * nx, ly = py + s * ny;
          const double rx = px - s * nx, ry = py - s * ny;
          if (label_at(lx, ly) == left) paper_left = std::max(paper_left, sample(lx, ly));
          if (label_at(rx, ry) == right) paper_right = std::max(paper_right, sample(rx, ry));
        }
      }
      if (paper_left < 0 || paper_right < 0) return;
      values.push_back(std::min(paper_left, paper_right) - centre);
      std::array<double, 3> paint_left{}, paint_right{};
      bool found_left = false, found_right = false;
      for (double s = paint_near; s <= paint_far + 1e-9 && !(found_left && found_right); s += 1.0) {
        const double lx = px + s * nx, ly = py + s * ny;
        const double rx = px - s * nx, ry = py - s * ny;
        if (!found_left && label_at(lx, ly) == left) {
          paint_left = sample_colour(lx, ly);
          found_left = true;
        }
        if (!found_right && label_at(rx, ry) == right) {
          paint_right = sample_colour(rx, ry);
          found_right = true;
        }
      }
      if (found_left && found_right) {
        double d2 = 0.0;
        for (int c = 0; c < 3; ++c)
          d2 += (paint_left[c] - paint_right[c]) * (paint_left[c] - paint_right[c]);
        colours.push_back(std::sqrt(d2 / 3.0));
      }
    };
    if (inside)
      point(std::true_type{});
    else
      point(std::false_type{});
  }
  if (!values.empty()) {
    std::vector<double> low = values;
    auto q = low.begin() + static_cast<std::ptrdiff_t>(low.size() / 4);
    std::nth_element(low.begin(), q, low.end());
    out.contrast_low = *q;
  }
  out.contrast = median_of(values);
  out.colour_difference = median_of(colours);
  return out;
}

double LineResponse::estimate_line_width(const Image& image) {
  // Dark runs: pixels well below the local paper level. Widths of runs along
  // rows and columns; the mode of the short ones is the typical line width.
  const cv::Mat grey = grey_of(image, 0, 0, image.width(), image.height());
  cv::Mat bright;
  cv::dilate(grey, bright, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(15, 15)));
  std::vector<int> histogram(32, 0);
  auto scan = [&](bool rows) {
    const int outer = rows ? grey.rows : grey.cols;
    const int inner = rows ? grey.cols : grey.rows;
    for (int o = 0; o < outer; o += 2) {
      int run = 0;
      for (int i = 0; i < inner; ++i) {
        const int y = rows ? o : i, x = rows ? i : o;
        const bool dark = grey.at<float>(y, x) < 0.5f * bright.at<float>(y, x);
        if (dark) {
          ++run;
        } else {
          if (run > 0 && run < static_cast<int>(histogram.size())) ++histogram[run];
          run = 0;
        }
      }
    }
  };
  scan(true);
  scan(false);
  const auto best = std::max_element(histogram.begin() + 1, histogram.end());
  if (*best == 0) return 2.0;
  // Runs cross lines at all angles, so the mode slightly overestimates.
  return static_cast<double>(best - histogram.begin());
}

}  // namespace hair25d::layering::detail
