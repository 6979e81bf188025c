#include "join_curves.h"

#include <algorithm>
#include <cmath>

#include "hair25d/completion/bezier.h"
#include "raster.h"

namespace hair25d::completion::detail {
namespace {

// The run's points, contour indices begin..end (unwrapped).
Polyline run_points(const std::vector<cv::Point>& contour, int begin, int end) {
  Polyline out;
  const int n = static_cast<int>(contour.size());
  for (int i = begin; i <= end; ++i) out.push_back(centre(contour[wrap(i, n)]));
  return out;
}

}  // namespace

bool outline_tangent(const std::vector<cv::Point>& contour, int end, int step, int arm,
                     const std::vector<char>& usable, Vec2* direction) {
  const int n = static_cast<int>(contour.size());
  if (n < 8) return false;
  // Visible outline beside the end, up to arm + skip px (never round the
  // whole contour).
  int free = 0;
  const int most = std::min(arm + 3, n / 2);
  while (free < most && (usable.empty() || usable[wrap(end + step * (free + 1), n)] != 0)) ++free;
  const int skip = std::min(3, free / 3);
  if (free - skip < 3) return false;
  Polyline piece;
  for (int k = skip; k <= free; ++k) piece.push_back(centre(contour[wrap(end + step * k, n)]));
  *direction = principal_axis(
      piece, centre(contour[wrap(end, n)]) - centre(contour[wrap(end + step * free, n)]));
  return true;
}

Polyline bezier_band(const Polyline& run_a, const Vec2& tangent_pa, const Vec2& tangent_qa,
                     const Polyline& run_b, const Vec2& tangent_pb, const Vec2& tangent_qb) {
  const Vec2 pa = run_a.front(), qa = run_a.back(), pb = run_b.front(), qb = run_b.back();
  const CubicBezier first = join_bezier(pa, tangent_pa, qb, -tangent_qb);
  const CubicBezier second = join_bezier(pb, tangent_pb, qa, -tangent_qa);
  Polyline band = first.sample(std::max(4, static_cast<int>((qb - pa).norm() / 2)));
  for (auto it = run_b.rbegin() + 1; it != run_b.rend(); ++it) band.push_back(*it);
  const Polyline back = second.sample(std::max(4, static_cast<int>((qa - pb).norm() / 2)));
  band.insert(band.end(), back.begin() + 1, back.end());
  for (auto it = run_a.rbegin() + 1; it + 1 != run_a.rend(); ++it) band.push_back(*it);
  return band;
}

Polyline face_join_patch(const Context& ctx, const FaceJoin& join) {
  const int arm = static_cast<int>(std::round(ctx.options->tangent_arm));
  struct Side {
    Polyline run;
    Vec2 tp, tq;
  };
  auto side = [&](int region, int begin, int end) {
    const RegionInfo& info = ctx.regions.at(region);
    const std::vector<cv::Point>& c = info.contour;
    Side s;
    s.run = run_points(c, begin, end);
    // Without visible outline beside an end, the piece is taken to run on
    // straight across its run's chord, away from the piece.
    const Vec2 p = s.run.front(), q = s.run.back();
    Vec2 out(-(q - p).y(), (q - p).x());
    if (out.norm() > 0) out.normalize();
    if (out.dot(info.centroid - 0.5 * (p + q)) > 0) out = -out;
    // The run's own points are hidden outline: the fit stays off them.
    const int n = static_cast<int>(c.size());
    std::vector<char> usable(n, 1);
    for (int i = begin; i <= end; ++i) usable[wrap(i, n)] = 0;
    const bool has_p = outline_tangent(c, begin, -1, arm, usable, &s.tp);
    const bool has_q = outline_tangent(c, end, +1, arm, usable, &s.tq);
    if (!has_p) s.tp = has_q ? s.tq : out;
    if (!has_q) s.tq = has_p ? s.tp : out;
    return s;
  };
  const Side a = side(join.region_a, join.begin_a, join.end_a);
  const Side b = side(join.region_b, join.begin_b, join.end_b);
  return bezier_band(a.run, a.tp, a.tq, b.run, b.tp, b.tq);
}

}  // namespace hair25d::completion::detail
