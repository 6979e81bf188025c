// Back-hair pieces joined through the regions lying above both (case 1 of
// §5.1 at region level, after the ray mass joins of bank_crossings.cpp).
#include <algorithm>
#include <cmath>
#include <deque>
#include <set>

#include "bank_crossings.h"

namespace hair25d::completion::detail {
namespace {

// Landing pixels a path join needs (distinct pixels of the other piece
// reached under the common occluders), as the ray mass joins need 3 rays.
constexpr int kMinLandings = 3;
// Landings whose colour step is measured (evenly spaced in the order found,
// nearest first).
constexpr int kColourSamples = 16;
// A path goes on through this many pixels of label 0 in a row (the light rim
// of a drawn line, 4-connected steps); longer runs are the face or paper.
constexpr int kMaxZeroRun = 4;
// The hidden part: a band this wide (px) along each of up to kBands straight
// lines between a path's ends (the assembly keeps its pixels under the
// strand's occluders only).
constexpr double kBandWidth = 3.0;
constexpr int kBands = 48;
// Share of the straight line between a path's ends that must lie under the
// common occluders (or on the two pieces, or on drawn lines).
constexpr double kMinStraightCover = 0.9;
// Largest median RGB step between the windows at a path's two ends.
constexpr double kMaxPathColourStep = 0.8;

struct Landing {
  Vec2 from{0, 0}, to{0, 0};
};

// Pixels of b reached from a through pixels of `common` (and short runs of
// label 0), within `reach` steps; each with the pixel of a its path left.
std::vector<Landing> paths_between(const Context& ctx, int a, int b, const std::set<int>& common,
                                   double reach) {
  cv::Rect box = ctx.regions.at(a).box | ctx.regions.at(b).box;
  for (int c : common) box |= ctx.regions.at(c).box;
  box.x -= 4, box.y -= 4, box.width += 8, box.height += 8;
  box &= cv::Rect(0, 0, ctx.labels.width(), ctx.labels.height());
  const int w = box.width, h = box.height;
  // Per pixel of the box: the origin (index into the box) of the path that
  // reached it first, -1 unvisited; its path length; its run of label 0;
  // whether it has crossed an occluder (pieces meeting across one line,
  // with no occluder between, are not joined this way).
  std::vector<int> origin(static_cast<std::size_t>(w) * h, -1), steps(origin.size(), 0);
  std::vector<std::uint8_t> zeros(origin.size(), 0), crossed(origin.size(), 0);
  std::deque<int> queue;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (ctx.labels.at(x + box.x, y + box.y) == a) {
        const int i = y * w + x;
        origin[i] = i;
        queue.push_back(i);
      }
  std::vector<Landing> out;
  std::set<int> landed;
  const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
  while (!queue.empty()) {
    const int i = queue.front();
    queue.pop_front();
    if (steps[i] > reach) continue;
    const int x = i % w, y = i / w;
    for (int k = 0; k < 4; ++k) {
      const int nx = x + dx[k], ny = y + dy[k];
      if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
      const int j = ny * w + nx;
      if (origin[j] >= 0) continue;
      const int l = ctx.labels.at(nx + box.x, ny + box.y);
      if (l == b) {
        if (crossed[i] && landed.insert(j).second) {
          const int o = origin[i];
          out.push_back({Vec2(o % w + box.x + 0.5, o / w + box.y + 0.5),
                         Vec2(nx + box.x + 0.5, ny + box.y + 0.5)});
        }
        continue;
      }
      const bool zero = l == 0;
      if (!zero && !common.count(l)) continue;
      if (zero && zeros[i] + 1 > kMaxZeroRun) continue;
      origin[j] = origin[i];
      steps[j] = steps[i] + 1;
      zeros[j] = zero ? zeros[i] + 1 : 0;
      crossed[j] = crossed[i] || !zero;
      queue.push_back(j);
    }
  }
  return out;
}

}  // namespace

std::vector<MassJoin> path_join_candidates(const Context& ctx) {
  if (!ctx.options->path_joins) return {};
  std::set<int> front;
  for (const auto& [id, ups] : ctx.above) front.insert(ups.begin(), ups.end());
  const TailedHair tailed = tailed_hair(ctx, front);
  std::vector<int> pieces;
  for (const auto& [id, info] : ctx.regions)
    if ((!front.count(id) || tailed.over_tails.count(id)) && !info.occluders.empty() &&
        !tailed.tails.count(id))
      pieces.push_back(id);
  cv::Rect hair;
  for (const auto& [id, info] : ctx.regions) hair = hair.area() == 0 ? info.box : (hair | info.box);
  const double reach = 0.5 * std::max(hair.width, hair.height);
  const auto above = [&](int r) -> const std::set<int>& {
    static const std::set<int> kNone;
    auto it = ctx.above.find(r);
    return it == ctx.above.end() ? kNone : it->second;
  };
  std::vector<MassJoin> out;
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (std::size_t k = i + 1; k < pieces.size(); ++k) {
      const int a = pieces[i], b = pieces[k];
      if (ctx.is_above(a, b) || ctx.is_above(b, a)) continue;
      if ((ctx.regions.at(a).colour - ctx.regions.at(b).colour).norm() >
          ctx.options->max_colour_distance)
        continue;
      std::set<int> common;
      for (int u : above(a))
        if (above(b).count(u)) common.insert(u);
      if (common.empty()) continue;
      std::vector<Landing> landings = paths_between(ctx, a, b, common, reach);
      // A path that crosses its occluders, not one that runs along one (two
      // strand tops lying on the face, joined through the cap above both):
      // the straight line between its ends lies under them too.
      std::erase_if(landings, [&](const Landing& l) {
        const double length = (l.to - l.from).norm();
        int under = 0, total = 0, zeros = 0;
        for (double t = 0.0; t <= length; t += 1.0, ++total) {
          const int label = ctx.label(l.from + (length > 0 ? t / length : 0.0) * (l.to - l.from));
          zeros = label == 0 ? zeros + 1 : 0;
          under += label == a || label == b || (label == 0 && zeros <= kMaxZeroRun) ||
                   common.count(label);
        }
        return under < kMinStraightCover * total;
      });
      if (static_cast<int>(landings.size()) < kMinLandings) continue;
      std::vector<double> colour_steps;
      const int n = static_cast<int>(landings.size());
      const int samples = std::min(n, kColourSamples);
      for (int s = 0; s < samples; ++s) {
        const Landing& l = landings[static_cast<std::size_t>(s) * n / samples];
        const Eigen::Vector3d ca = colour_near(ctx, a, l.from, Vec2(0, 0));
        const Eigen::Vector3d cb = colour_near(ctx, b, l.to, Vec2(0, 0));
        colour_steps.push_back((ca - cb).norm());
      }
      const auto median = [](std::vector<double> v) {
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
      };
      const double step = median(colour_steps);
      if (step > kMaxPathColourStep) continue;
      MassJoin j;
      j.region_a = a;
      j.region_b = b;
      j.rays = n;
      j.colour = step;
      const int bands = std::min(n, kBands);
      for (int s = 0; s < bands; ++s) {
        const Landing& l = landings[static_cast<std::size_t>(s) * n / bands];
        Vec2 side(-(l.to - l.from).y(), (l.to - l.from).x());
        if (side.norm() < 1e-9) continue;
        side *= 0.5 * kBandWidth / side.norm();
        j.bands.push_back({l.from + side, l.to + side, l.to - side, l.from - side});
      }
      out.push_back(std::move(j));
    }
  std::sort(out.begin(), out.end(), [](const MassJoin& x, const MassJoin& y) {
    return x.colour != y.colour ? x.colour < y.colour : x.rays > y.rays;
  });
  return out;
}

}  // namespace hair25d::completion::detail
