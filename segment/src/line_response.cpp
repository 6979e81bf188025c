#include "line_response.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace hair25d::segment::detail {

cv::Mat grey_image(const Image& image) {
  cv::Mat grey(image.height(), image.width(), CV_32F);
  for (int y = 0; y < image.height(); ++y) {
    float* row = grey.ptr<float>(y);
    for (int x = 0; x < image.width(); ++x) {
      const Rgba& p = image.at(x, y);
      const float a = p.a / 255.0f;
      // Ink darkens every channel; a dark hair colour keeps one bright (a
      // black line on dark blue (39, 49, 143): 27 levels of luminance apart,
      // 113 in the brightest channel). Half luminance, half brightest
      // channel: black lines on dark colours stand out, and a saturated
      // coloured line on white paper still does.
      const float lum = 0.299f * p.r + 0.587f * p.g + 0.114f * p.b;
      const float ink = 0.5f * lum + 0.5f * std::max({p.r, p.g, p.b});
      row[x] = a * ink + (1.0f - a) * 255.0f;
    }
  }
  return grey;
}

void remove_dots(cv::Mat& grey, const cv::Mat& closed, int max_size, float contrast) {
  if (max_size <= 0 || grey.rows < 3 || grey.cols < 3) return;
  // Dark specks are pixels clearly darker than the light pixels around them
  // (closing minus image) that form small isolated blobs; lines are long runs.
  cv::Mat dark = (closed - grey) > contrast;
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(dark, labels, stats, centroids, 4, CV_32S);
  std::vector<char> speck(n, 0);
  for (int i = 1; i < n; ++i) {
    const int w = stats.at<int>(i, cv::CC_STAT_WIDTH), h = stats.at<int>(i, cv::CC_STAT_HEIGHT);
    speck[i] = w <= max_size && h <= max_size;
  }
  for (int y = 0; y < grey.rows; ++y) {
    const int* lab = labels.ptr<int>(y);
    float* g = grey.ptr<float>(y);
    const float* c = closed.ptr<float>(y);
    for (int x = 0; x < grey.cols; ++x)
      if (lab[x] > 0 && speck[lab[x]]) g[x] = c[x];
  }
}

namespace {

// Bilinear read of the whole image's row y (m holds its rows from `top` on, at
// least those the read touches; `rows` is the whole image's height).
float bilinear(const cv::Mat& m, int top, int rows, float x, float y) {
  x = std::clamp(x, 0.0f, static_cast<float>(m.cols - 1));
  y = std::clamp(y, 0.0f, static_cast<float>(rows - 1));
  const int x0 = std::min(static_cast<int>(x), m.cols - 2 < 0 ? 0 : m.cols - 2);
  const int y0 = std::min(static_cast<int>(y), rows - 2 < 0 ? 0 : rows - 2);
  const int x1 = std::min(x0 + 1, m.cols - 1);
  const int y1 = std::min(y0 + 1, rows - 1);
  const float fx = x - x0, fy = y - y0;
  const float a = m.at<float>(y0 - top, x0), b = m.at<float>(y0 - top, x1);
  const float c = m.at<float>(y1 - top, x0), d = m.at<float>(y1 - top, x1);
  return (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy;
}

// Rows per band of the line field: each band is blurred and differentiated on
// its own (with a margin), small enough to stay in cache, and bands are shared
// by the cores.
constexpr int kBandRows = 64;

}  // namespace

LineField compute_line_field(const cv::Mat& grey, const std::vector<double>& scales,
                             float low_threshold, float blob_weight) {
  const int w = grey.cols, h = grey.rows;
  LineField f;
  f.response = cv::Mat::zeros(h, w, CV_32F);
  f.nx = cv::Mat::zeros(h, w, CV_32F);
  f.ny = cv::Mat::zeros(h, w, CV_32F);
  f.offset = cv::Mat::zeros(h, w, CV_32F);
  f.sigma = cv::Mat::zeros(h, w, CV_32F);
  const cv::Mat k_d2 = (cv::Mat_<float>(1, 3) << 1.0f, -2.0f, 1.0f);
  const cv::Mat k_d1 = (cv::Mat_<float>(1, 3) << -0.5f, 0.0f, 0.5f);
  const cv::Mat k_id = (cv::Mat_<float>(1, 1) << 1.0f);
  // The gate reads the blurred image up to max(1.5, 2 sigma) px across, one
  // more for the bilinear read; the derivatives one row either side.
  double smax = 0.0;
  for (double s : scales) smax = std::max(smax, s);
  const int margin = static_cast<int>(std::ceil(std::max(1.5, 2.0 * smax))) + 2;
  // One band for an image a pixel or a few wide: OpenCV blurs a one-column
  // submatrix unlike the same column of a whole image (seen; not looked into).
  const int bands = w < 4 ? 1 : (h + kBandRows - 1) / kBandRows;
  // Each band is the whole image's computation restricted to its rows: the
  // filters of a band's rows read the rows round them (OpenCV reads past a
  // submatrix's edge inside its parent and replicates only at the image's
  // border), so every value is the same as filtering the whole image at once.
  cv::parallel_for_(cv::Range(0, bands), [&](const cv::Range& range) {
    for (int band = range.start; band < range.end; ++band) {
      const int y0 = band * kBandRows, y1 = bands == 1 ? h : std::min(h, y0 + kBandRows);
      const int top = std::max(0, y0 - margin), bottom = std::min(h, y1 + margin);
      const int n = y1 - y0;
      cv::Mat scale_index(n, w, CV_8U, cv::Scalar(255));
      cv::Mat dn(n, w, CV_32F, cv::Scalar(0));  // directional first derivative along n
      cv::Mat l1(n, w, CV_32F, cv::Scalar(0));  // eigenvalue across the line
      cv::Mat b, ixx, iyy, ixy, ix, iy;
      for (std::size_t s = 0; s < scales.size(); ++s) {
        const double sigma = scales[s];
        cv::GaussianBlur(grey.rowRange(top, bottom), b, cv::Size(0, 0), sigma, sigma,
                         cv::BORDER_REPLICATE);
        const cv::Mat mine = b.rowRange(y0 - top, y1 - top);
        cv::sepFilter2D(mine, ixx, CV_32F, k_d2, k_id, cv::Point(-1, -1), 0, cv::BORDER_REPLICATE);
        cv::sepFilter2D(mine, iyy, CV_32F, k_id, k_d2, cv::Point(-1, -1), 0, cv::BORDER_REPLICATE);
        cv::sepFilter2D(mine, ixy, CV_32F, k_d1, k_d1, cv::Point(-1, -1), 0, cv::BORDER_REPLICATE);
        cv::sepFilter2D(mine, ix, CV_32F, k_d1, k_id, cv::Point(-1, -1), 0, cv::BORDER_REPLICATE);
        cv::sepFilter2D(mine, iy, CV_32F, k_id, k_d1, cv::Point(-1, -1), 0, cv::BORDER_REPLICATE);
        const float s2 = static_cast<float>(sigma * sigma);
        for (int y = y0; y < y1; ++y) {
          const int i = y - y0;
          const float* pxx = ixx.ptr<float>(i);
          const float* pyy = iyy.ptr<float>(i);
          const float* pxy = ixy.ptr<float>(i);
          const float* px = ix.ptr<float>(i);
          const float* py = iy.ptr<float>(i);
          const float* pb = b.ptr<float>(y - top);
          float* resp = f.response.ptr<float>(y);
          for (int x = 0; x < w; ++x) {
            const float a = pxx[x], c = pyy[x], bxy = pxy[x];
            const float half = 0.5f * (a - c);
            const float root = std::sqrt(half * half + bxy * bxy);
            const float lambda = 0.5f * (a + c) + root;   // largest: across a dark valley
            const float lambda2 = 0.5f * (a + c) - root;  // along the line: ~0 on a line
            // A dark dot (screentone) curves the same way in every direction: the
            // second eigenvalue takes it out; on a line it is near zero.
            float r = s2 * (lambda - blob_weight * std::max(lambda2, 0.0f));
            if (r <= resp[x]) continue;
            // Eigenvector of the largest eigenvalue.
            float ex, ey;
            if (half >= 0.0f) {
              ex = half + root;
              ey = bxy;
            } else {
              ex = bxy;
              ey = root - half;
            }
            const float len = std::sqrt(ex * ex + ey * ey);
            if (len < 1e-12f) {
              ex = 1.0f;
              ey = 0.0f;
            } else {
              ex /= len;
              ey /= len;
            }
            if (r > low_threshold) {
              // A dark line is darker than both of its sides; the second
              // derivative alone also answers beside a step between two flat
              // tones. Each scale is gated on its own: beside light paper a
              // coarse scale blurs the paper into the centre of a line that
              // borders a dark fill (the outline of dark hair), a finer one
              // still sees the line darker than the fill.
              const float d = std::max(1.5f, 2.0f * static_cast<float>(sigma));
              const float side = std::min(bilinear(b, top, h, x + d * ex, y + d * ey),
                                          bilinear(b, top, h, x - d * ex, y - d * ey));
              const float depth = side - pb[x];
              // Gate, not cap: the second derivative keeps its single peak at
              // the line centre (a cap by the flat depth would make plateaus).
              r *= std::clamp(depth / (0.5f * r), 0.0f, 1.0f);
              if (r <= resp[x]) continue;
            }
            resp[x] = r;
            f.nx.at<float>(y, x) = ex;
            f.ny.at<float>(y, x) = ey;
            dn.at<float>(i, x) = ex * px[x] + ey * py[x];
            l1.at<float>(i, x) = lambda;
            scale_index.at<std::uint8_t>(i, x) = static_cast<std::uint8_t>(s);
          }
        }
      }
      // Sub-pixel centre and scale where a line may run.
      for (int y = y0; y < y1; ++y) {
        const int i = y - y0;
        const float* resp = f.response.ptr<float>(y);
        for (int x = 0; x < w; ++x) {
          if (resp[x] <= low_threshold) continue;
          const int s = scale_index.at<std::uint8_t>(i, x);
          const float lambda = l1.at<float>(i, x);
          float t = lambda > 1e-6f ? -dn.at<float>(i, x) / lambda : 0.0f;
          f.offset.at<float>(y, x) = std::clamp(t, -0.5f, 0.5f);
          f.sigma.at<float>(y, x) = static_cast<float>(scales[s]);
        }
      }
    }
  });
  return f;
}

cv::Mat suppress_non_maxima(const LineField& field, float low_threshold) {
  const int w = field.response.cols, h = field.response.rows;
  cv::Mat out = cv::Mat::zeros(h, w, CV_8U);
  constexpr float kSin22 = 0.38268343f;
  // Each row of `out`, and then of `thin`, is written from the rows round it
  // only: the rows are shared by the cores.
  cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      const float* resp = field.response.ptr<float>(y);
      for (int x = 0; x < w; ++x) {
        const float r = resp[x];
        if (r <= low_threshold) continue;
        const float ex = field.nx.at<float>(y, x), ey = field.ny.at<float>(y, x);
        int dx = ex > kSin22 ? 1 : (ex < -kSin22 ? -1 : 0);
        int dy = ey > kSin22 ? 1 : (ey < -kSin22 ? -1 : 0);
        // One orientation for ±n, so that the tie rule below picks the same
        // side for both pixels of a two-pixel plateau.
        if (dx < 0 || (dx == 0 && dy < 0)) dx = -dx, dy = -dy;
        // Look as far across as the scale blurs: a line between a dark and a
        // light fill has a second, weaker top a pixel or two off its centre.
        const int reach =
            std::max(1, static_cast<int>(std::lround(0.8 * field.sigma.at<float>(y, x))));
        bool keep = true;
        for (int k = 1; k <= reach && keep; ++k) {
          const int xa = x + k * dx, ya = y + k * dy, xb = x - k * dx, yb = y - k * dy;
          const float ra =
              (xa >= 0 && ya >= 0 && xa < w && ya < h) ? field.response.at<float>(ya, xa) : 0.0f;
          const float rb =
              (xb >= 0 && yb >= 0 && xb < w && yb < h) ? field.response.at<float>(yb, xb) : 0.0f;
          // Ties go to one side only, so a flat top of two equal pixels keeps one.
          keep = r >= ra && r > rb;
        }
        if (keep) out.at<std::uint8_t>(y, x) = 1;
      }
    }
  });
  // Two tops side by side whose normals were rounded to different
  // directions both survive the test above: keep the stronger one.
  cv::Mat thin = out.clone();
  cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      for (int x = 0; x < w; ++x) {
        if (!out.at<std::uint8_t>(y, x)) continue;
        const float r = field.response.at<float>(y, x);
        const float ex = field.nx.at<float>(y, x), ey = field.ny.at<float>(y, x);
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int qx = x + dx, qy = y + dy;
            if ((dx == 0 && dy == 0) || qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
            if (!out.at<std::uint8_t>(qy, qx)) continue;
            const float across = std::abs(dx * ex + dy * ey) / std::sqrt(float(dx * dx + dy * dy));
            const float rq = field.response.at<float>(qy, qx);
            if (across > 0.85f && (rq > r || (rq == r && qy * w + qx < y * w + x)))
              thin.at<std::uint8_t>(y, x) = 0;
          }
        }
      }
    }
  });
  return thin;
}

}  // namespace hair25d::segment::detail
