#include "join_corridor.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace hair25d::completion::detail {
namespace {

// The largest box (pixels) a corridor is sought in; a join of larger
// pieces keeps the patch's test. The patches of large back pieces span the
// drawing (boxes up to 1 M px on the seed-7 1024² drawing of 40 strands,
// 20-30 ms each). Sampling such a box every s-th pixel is no cure: the
// grid skips thin walls (outlines, paper between strands), and at step 2-3
// dev two-tone 2093 joined a front strand to the body of back hair below
// it across the face (-6 right pairs, +2 wrong).
constexpr double kMaxCorridorBox = 2e5;

}  // namespace

bool corridor_under_occluders(const Context& ctx, const Edge& a, const Edge& b,
                              const Polyline& patch, const cv::Mat& face, bool ink, double width,
                              double reach) {
  if (patch.empty() || a.points.empty() || b.points.empty() || !(width > 0)) return false;
  double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18;
  for (const Polyline* line : {&patch, &a.points, &b.points})
    for (const Vec2& p : *line) {
      x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y());
      x1 = std::max(x1, p.x()), y1 = std::max(y1, p.y());
    }
  const int gx0 = std::max(0, static_cast<int>(std::floor(x0 - reach)));
  const int gy0 = std::max(0, static_cast<int>(std::floor(y0 - reach)));
  const int gx1 = std::min(ctx.labels.width() - 1, static_cast<int>(std::ceil(x1 + reach)));
  const int gy1 = std::min(ctx.labels.height() - 1, static_cast<int>(std::ceil(y1 + reach)));
  const int w = gx1 - gx0 + 1, h = gy1 - gy0 + 1;
  if (w <= 2 || h <= 2 || static_cast<double>(w) * h > kMaxCorridorBox) return false;
  // open: under an occluder or in a piece; piece: in a or b.
  cv::Mat open(h, w, CV_8U, cv::Scalar(0)), piece(h, w, CV_8U, cv::Scalar(0));
  AboveEither above(ctx, a.region, b.region);
  for (int y = 0; y < h; ++y) {
    std::uint8_t* o = open.ptr<std::uint8_t>(y);
    std::uint8_t* p = piece.ptr<std::uint8_t>(y);
    for (int x = 0; x < w; ++x) {
      const int gx = x + gx0, gy = y + gy0;
      const int l = ctx.labels.at(gx, gy);
      if (l == a.region || l == b.region) {
        o[x] = p[x] = 255;
      } else if (above.hides(l, gx, gy, face, ink)) {
        o[x] = 255;
      }
    }
  }
  // The box's border is no wall: a corridor may not leave the box, but the
  // distance to the nearest closed pixel counts only closed pixels.
  cv::Mat padded;
  cv::copyMakeBorder(open, padded, 1, 1, 1, 1, cv::BORDER_REPLICATE);
  cv::Mat dist;
  cv::distanceTransform(padded, dist, cv::DIST_L2, cv::DIST_MASK_3);
  dist = dist(cv::Rect(1, 1, w, h));
  const float radius = static_cast<float>(0.5 * width);
  cv::Mat centres = (dist >= radius) & ~piece;
  cv::Mat components;
  if (cv::connectedComponents(centres, components, 8, CV_32S) < 2) return false;
  // The components a corridor's centre line leaves a cut by: centres within
  // the corridor's half width (and a pixel) of the cut's points.
  cv::Mat near(h, w, CV_8U);
  auto touching = [&](const Edge& e) {
    std::vector<cv::Point> cut;
    for (const Vec2& pt : e.points)
      cut.emplace_back(static_cast<int>(std::lround(pt.x())) - gx0,
                       static_cast<int>(std::lround(pt.y())) - gy0);
    near.setTo(0);
    const int n = static_cast<int>(std::ceil(radius + 1.5));
    cv::polylines(near, cut, false, cv::Scalar(255), 2 * n + 1);
    const cv::Rect box = cv::boundingRect(cut) + cv::Size(2 * n + 1, 2 * n + 1) - cv::Point(n, n);
    const cv::Rect in = box & cv::Rect(0, 0, w, h);
    std::vector<int> ids;
    for (int y = in.y; y < in.y + in.height; ++y)
      for (int x = in.x; x < in.x + in.width; ++x) {
        const int id = components.at<int>(y, x);
        if (id == 0 || !near.at<std::uint8_t>(y, x)) continue;
        if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
      }
    return ids;
  };
  const std::vector<int> from = touching(a), to = touching(b);
  for (int id : from)
    if (std::find(to.begin(), to.end(), id) != to.end()) return true;
  return false;
}

}  // namespace hair25d::completion::detail
