// Back-hair pieces joined through the regions lying above both (case 1 of
// §5.1 at region level, after the ray mass joins of bank_crossings.cpp).
#include <algorithm>
#include <cmath>
#include <complex>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <opencv2/imgproc.hpp>
#include <set>
#include <utility>

#include "bank_crossings.h"
#include "join_paint.h"
#include "parallel_each.h"

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
// Or the pieces are painted by one linear field (RegionFields::step, RGB):
// on gradient seeds 101-116 path candidates (the field without its gates) of one strand measured
// 0-0.45 (a few 0.67-2.13), of two strands one 0.09 (a bang and the cap), then 0.51 and up.
// Gradient 101-116: 0.3 gave 0.967 / 0.749, 0.4 0.968 / 0.771, 0.5 0.968 / 0.793, 0.7 0.885 / 0.793
// (a wrong back-hair join).
constexpr double kMaxPathFieldStep = 0.5;
// A piece whose outline runs this close to the face (within 3 px) all round
// but for a sliver lies on the face: back hair is hidden by the face, so
// part of its outline runs along other things (generated 1000 x 800 seed 14:
// two bangs lying on the face, joined under a third; screentone 116 bangs
// 5 and 6).
constexpr double kMaxFaceShare = 0.97;
// A piece whose outline runs this much along the face lies on it or
// borders it (strand_on_face). Dev screentone 2003 and 2009: the strands
// on the face that back hair took measured 0.99 and 0.79.
constexpr double kOnFaceShare = 0.75;

// Hair hanging from under a back-hair piece is covered by at most this many
// regions (the back and a strand lying on both; completion.cpp keeps tails
// hanging from under one or two pieces out of the face joins alike). A cap
// lies on back hair covered by more, and strand pieces lying on a back piece
// cover it together (the tests' strand_under_band: two pieces and the band
// over them). Generated seeds 101-116, precision / recall, with the
// stacked locks below: 2 gave flat 0.969 / 0.812, two-tone 0.948 / 0.640,
// gradient 0.970 / 0.830; 3 flat 0.970 / 0.827, two-tone 0.951 / 0.680,
// gradient 0.970 / 0.838 (but the tests' strand pieces joined); 4 flat
// 0.970 / 0.830, two-tone 0.950 / 0.671 (the same); without stacking and no
// limit flat 0.961 / 0.823 (the cap lying on the whole back taken, flat 116:
// then path-joined to a strand on the face of its colour). Screentone
// unchanged with each (no such pieces there, below).
constexpr int kMaxHangingCover = 2;
// Or by at most kMaxRestingCover when the piece touches it along at most
// kMaxRestingShare of its outline: back hair rests on a tail's top end (a
// two-tone back piece on a tail that two back pieces and a bang cover),
// while a strand lying on a back piece borders it along most of its outline
// (strand_under_band's pieces: ~0.7). Session 13, seeds 101-116, precision /
// recall: cover 3 / share 0.1 or 0.2 two-tone 0.993 / 0.640 -> 0.993 /
// 0.654; 4 / 0.2 0.993 / 0.662; 4 / 0.3 or 0.4 0.994 / 0.689, flat 0.996 /
// 0.830 -> 0.996 / 0.841, gradient 0.979 / 0.845 -> 0.979 / 0.852; 9 / 0.3
// as 4 / 0.3; any share (cover 3 alone) 0.994 / 0.680 and the tests' strand
// pieces joined.
constexpr int kMaxRestingCover = 4;
constexpr double kMaxRestingShare = 0.3;
// How near (px) an outline point lies to a region it touches.
constexpr int kTouchReach = 3;

struct Landing {
  Vec2 from{0, 0}, to{0, 0};
};

// The paths' mean direction: the sum of their unit directions.
Vec2 mean_direction(const std::vector<Landing>& landings) {
  Vec2 direction(0, 0);
  for (const Landing& l : landings)
    if ((l.to - l.from).norm() > 0) direction += (l.to - l.from).normalized();
  return direction;
}

// |cos| of the angle between `dir` and region `id`'s long axis (second
// moments of its outline); 1 for a piece less than twice as long as wide.
double axis_cos(const Context& ctx, int id, const Vec2& dir) {
  const std::vector<cv::Point>& c = ctx.regions.at(id).contour;
  if (c.size() < 3 || dir.norm() == 0) return 1.0;
  const cv::Moments m = cv::moments(c);
  if (m.m00 <= 0) return 1.0;
  const double a = m.mu20 / m.m00, b = m.mu11 / m.m00, d = m.mu02 / m.m00;
  const double mean = 0.5 * (a + d), root = std::sqrt(0.25 * (a - d) * (a - d) + b * b);
  const double large = mean + root, small = mean - root;
  if (large < 4.0 * std::max(small, 1e-9)) return 1.0;
  const double theta = 0.5 * std::atan2(2.0 * b, a - d);
  const Vec2 axis(std::cos(theta), std::sin(theta));
  return std::abs(axis.dot(dir.normalized()));
}

// Rare cel paint (session 14): two pieces whose flat colours lie within
// kMaxRareCelStep RGB (`RegionCels::step`) of each other and of no third
// region's. Two-tone / flat 101-116: sharing with one other region allowed
// 1.000 / 0.833 and 0.980 / 0.926 (flat 102: three regions of one paint,
// two strands); step 1.0: 1.000 / 0.803, 0.992 / 0.908 (more regions share).
constexpr double kMaxRareCelStep = 0.5;
// Drawings not of cel paint (session 24): the pieces' one paint is one
// linear field, the joint fit missing each piece by at most
// kMaxRareFieldStep RGB beyond its own (`RegionFields::step`), with no
// third region. The generator's gradients run along each strand, so a
// strand's pieces share its field while its neighbours' differ in colour,
// direction or offset: of the region pairs of dev gradient 2000-2099 that
// lie neither above the other, at most 0.05 RGB and no third region held
// 112 of one strand and 16 of two (any sharing 573 / 67). Gradient
// 2000-2099 0.932 / 0.762 -> 0.933 / 0.776 (one third region allowed:
// 0.930 / 0.787, the added pairs a quarter wrong; 0.1 RGB the same as
// 0.05).
constexpr double kMaxRareFieldStep = 0.05;
// Rarity needs regions to compare with (as joins.cpp's kRarePaintRegions),
// and screentone drawings are left to the tone: their dots and paper are
// every toned piece's two flat colours (the tone tests' hand-built pieces
// of two tones were joined without these two conditions).
constexpr std::size_t kMinRarePaintRegions = 8;
// The mean path at most this share of the path search's reach (half the
// hair's larger side): right candidates 6-92 px, the wrong one 217 px of 268.
constexpr double kMaxRarePathReach = 0.5;
// The paths' mean direction within 60 degrees of the long axis of at least
// one piece (a piece less than twice as long as wide has every direction).
constexpr double kMinAxisCos = 0.5;
// Tone path joins of two pieces lying above some region under a single
// common occluder: the paths within 60 degrees of both pieces' long axes
// (session 21, dev screentone 2000-2099 and 3000-3099: of such links one
// piece was crossed sideways in 10 right and 11 wrong ones).
constexpr double kMinToneAxisCos = 0.5;

// Whether `landings` are fewer than Options::tone_path_landing_share times
// the square root of the smaller piece's pixels (about its width for the
// generator's strand pieces, two to ten times as long as wide). On dev
// screentone 2000-2099 and 3000-3099, both relations, the tone path links
// of two front pieces under 0.3 were 5 wrong (11 pairs) and none right;
// under 0.65 9 wrong (23 pairs) and 5 right (5 pairs); tone path joins of
// a front piece and back hair land on few pixels when right too (a back
// piece's pixels say nothing of the strand's width), so they are left.
bool few_landings(const Context& ctx, int a, int b, std::size_t landings) {
  const double share = ctx.options->tone_path_landing_share;
  if (share <= 0) return false;
  const int smaller = std::min(ctx.regions.at(a).pixels, ctx.regions.at(b).pixels);
  return static_cast<double>(landings) < share * std::sqrt(static_cast<double>(smaller));
}

// Share of region `id`'s outline within kTouchReach px of region `other`.
double outline_share(const Context& ctx, int id, int other) {
  const std::vector<cv::Point>& c = ctx.regions.at(id).contour;
  if (c.empty()) return 1.0;
  int touch = 0;
  for (const cv::Point& q : c) {
    bool near = false;
    for (int dy = -kTouchReach; dy <= kTouchReach && !near; ++dy)
      for (int dx = -kTouchReach; dx <= kTouchReach && !near; ++dx)
        near = ctx.label(q.x + dx, q.y + dy) == other;
    touch += near;
  }
  return static_cast<double>(touch) / static_cast<double>(c.size());
}

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
  // Seeds in the box's row order; a's pixels lie in its own box.
  const cv::Rect own = (ctx.regions.at(a).box & box) - box.tl();
  for (int y = own.y; y < own.y + own.height; ++y)
    for (int x = own.x; x < own.x + own.width; ++x)
      if (ctx.labels.at(x + box.x, y + box.y) == a) {
        const int i = y * w + x;
        origin[i] = i;
        queue.push_back(i);
      }
  std::vector<Landing> out;
  std::vector<std::uint8_t> landed(origin.size(), 0);
  // `common` as a table by label (the search's inner loop).
  std::vector<std::uint8_t> is_common(common.empty() ? 0 : std::max(0, *common.rbegin() + 1), 0);
  for (int c : common)
    if (c >= 0) is_common[static_cast<std::size_t>(c)] = 1;
  const auto in_common = [&](int l) {
    return l >= 0 && static_cast<std::size_t>(l) < is_common.size() &&
           is_common[static_cast<std::size_t>(l)] != 0;
  };
  const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
  while (!queue.empty()) {
    const int i = queue.front();
    queue.pop_front();
    // Breadth first, the steps never decrease along the queue: the rest is
    // beyond reach too.
    if (steps[i] > reach) break;
    const int x = i % w, y = i / w;
    for (int k = 0; k < 4; ++k) {
      const int nx = x + dx[k], ny = y + dy[k];
      if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
      const int j = ny * w + nx;
      if (origin[j] >= 0) continue;
      const int l = ctx.labels.at(nx + box.x, ny + box.y);
      if (l == b) {
        if (crossed[i] && !landed[j]) {
          landed[j] = 1;
          const int o = origin[i];
          out.push_back({Vec2(o % w + box.x + 0.5, o / w + box.y + 0.5),
                         Vec2(nx + box.x + 0.5, ny + box.y + 0.5)});
        }
        continue;
      }
      const bool zero = l == 0;
      if (!zero && !in_common(l)) continue;
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

// The landings of paths that cross their occluders, not ones that run along
// one (two strand tops lying on the face, joined through the cap above
// both): the straight line between a path's ends lies under them too.
std::vector<Landing> crossing_paths(const Context& ctx, int a, int b, const std::set<int>& common,
                                    double reach) {
  std::vector<Landing> landings = paths_between(ctx, a, b, common, reach);
  std::erase_if(landings, [&](const Landing& l) {
    const double length = (l.to - l.from).norm();
    int under = 0, total = 0, zeros = 0;
    for (double t = 0.0; t <= length; t += 1.0, ++total) {
      const int label = ctx.label(l.from + (length > 0 ? t / length : 0.0) * (l.to - l.from));
      zeros = label == 0 ? zeros + 1 : 0;
      under +=
          label == a || label == b || (label == 0 && zeros <= kMaxZeroRun) || common.count(label);
    }
    return under < kMinStraightCover * total;
  });
  return landings;
}

// The hidden part of a path join: kBandWidth px bands along up to kBands of
// its chords.
std::vector<Polyline> path_bands(const std::vector<Landing>& landings) {
  std::vector<Polyline> out;
  const int n = static_cast<int>(landings.size());
  const int bands = std::min(n, kBands);
  for (int s = 0; s < bands; ++s) {
    const Landing& l = landings[static_cast<std::size_t>(s) * n / bands];
    Vec2 side(-(l.to - l.from).y(), (l.to - l.from).x());
    if (side.norm() < 1e-9) continue;
    side *= 0.5 * kBandWidth / side.norm();
    out.push_back({l.from + side, l.to + side, l.to - side, l.from - side});
  }
  return out;
}

// The regions lying above both pieces, the path joins' common occluders.
std::set<int> common_above(const std::set<int>& above_a, const std::set<int>& above_b) {
  std::set<int> common;
  for (int u : above_a)
    if (above_b.count(u)) common.insert(u);
  return common;
}

// A path join of a and b along `landings`, ranked by `colour`.
MassJoin path_join(int a, int b, const std::vector<Landing>& landings, double colour) {
  MassJoin j;
  j.region_a = a;
  j.region_b = b;
  j.rays = static_cast<int>(landings.size());
  j.colour = colour;
  j.bands = path_bands(landings);
  return j;
}

// Best first: the least colour step, then the most paths.
void sort_by_colour(std::vector<MassJoin>& joins) {
  std::sort(joins.begin(), joins.end(), [](const MassJoin& x, const MassJoin& y) {
    return x.colour != y.colour ? x.colour < y.colour : x.rays > y.rays;
  });
}

// A front piece (above some region) and a piece above none are joined by
// their tone when their dot masses differ by at most this share: the
// strands' tones (the generator's 0.12-0.45) overlap the back hair's
// (0.35-0.55), and a bang's end lying on the face lies above no region
// either. On screentone seeds 101-116 such candidates of one strand (a cap
// sliver and the cap, a side lock's end on the face) differed by 0-0.012,
// of two strands by 0.016-0.028.
constexpr double kMaxMixedMassStep = 0.012;

// Share of a region's outline within 3 px of the face.
double face_share(const Context& ctx, const cv::Mat& near_face, int region) {
  const std::vector<cv::Point>& contour = ctx.regions.at(region).contour;
  if (near_face.empty() || contour.empty()) return 0.0;
  int n = 0;
  for (const cv::Point& p : contour) n += near_face.at<std::uint8_t>(p.y, p.x) != 0;
  return static_cast<double>(n) / contour.size();
}

// At most this many regions that are no path-join piece (strands, tails)
// share the back hair's paint. Generated flat 2000-2099 and mixed 3000-3099:
// 0 on 153 of 200 drawings, at most 5; the annotated six: 0, 0, 0, 5, 7, 11
// (their hair is one paint; with no limit their precision fell 0.982 ->
// 0.807). Limits 2 and 3 gave the same pairs on the generated sets.
constexpr int kMaxBackPaintSharers = 2;

// Regions lying above `id` (none when it has no entry).
const std::set<int>& above_of(const Context& ctx, int id) {
  static const std::set<int> kNone;
  auto it = ctx.above.find(id);
  return it == ctx.above.end() ? kNone : it->second;
}

// The joins of pieces in the back hair's paint through the regions lying
// above either (path_join_candidates, session 15): `pieces` are the path
// joins' pieces, `found` the path candidates already found (pairs they link,
// chained, are left out, as are pairs in one strand).
std::vector<MassJoin> back_paint_joins(const Context& ctx, const std::vector<int>& pieces,
                                       const std::set<int>& front, const cv::Mat& near_face,
                                       RegionTones& tones, RegionFields& fields,
                                       const std::vector<MassJoin>& found,
                                       const std::function<bool(int, int)>& one_strand,
                                       double reach) {
  // The back hair: the largest piece lying above no region.
  int back = 0;
  for (int p : pieces)
    if (!front.count(p) && (back == 0 || ctx.regions.at(p).pixels > ctx.regions.at(back).pixels))
      back = p;
  if (back == 0) return {};
  const bool screentone = tones.screentone();
  const bool cel = !screentone && fields.cels().cel_drawing();
  const auto one_paint = [&](int a, int b) {
    return a == b || detail::one_paint(tones, fields, a, b);
  };
  std::map<int, int> parent;
  const std::function<int(int)> find = [&](int x) {
    auto it = parent.find(x);
    if (it == parent.end() || it->second == x) return x;
    return it->second = find(it->second);
  };
  for (const MassJoin& j : found) parent[find(j.region_a)] = find(j.region_b);
  std::vector<int> painted;
  for (int p : pieces)
    if (one_paint(p, back)) painted.push_back(p);
  // The paint must be the back hair's own: on drawings whose hair is all
  // one paint (the annotated cases: 5-11 regions that are no piece share
  // the back's) it says nothing.
  int others = 0;
  for (const auto& [id, info] : ctx.regions)
    others += std::find(pieces.begin(), pieces.end(), id) == pieces.end() && one_paint(id, back);
  if (others > kMaxBackPaintSharers) return {};
  std::vector<MassJoin> out;
  for (std::size_t i = 0; i < painted.size(); ++i)
    for (std::size_t k = i + 1; k < painted.size(); ++k) {
      const int a = painted[i], b = painted[k];
      if (find(a) == find(b) || (one_strand && one_strand(a, b))) continue;
      if (ctx.is_above(a, b) || ctx.is_above(b, a)) continue;
      if (!one_paint(a, b)) continue;
      if (strand_on_face(ctx, tones, near_face, a, b)) continue;
      if (std::min(face_share(ctx, near_face, a), face_share(ctx, near_face, b)) >= kMaxFaceShare)
        continue;
      std::set<int> either = above_of(ctx, a);
      either.insert(above_of(ctx, b).begin(), above_of(ctx, b).end());
      const std::vector<Landing> landings = crossing_paths(ctx, a, b, either, reach);
      if (static_cast<int>(landings.size()) < kMinLandings) continue;
      out.push_back(path_join(a, b, landings,
                              screentone ? 0.0
                              : cel      ? fields.cels().step(a, b)
                                         : fields.step(a, b)));
    }
  sort_by_colour(out);
  return out;
}

}  // namespace

cv::Mat near_face_mask(const cv::Mat& face) {
  cv::Mat near_face;
  if (!face.empty())
    cv::dilate(face, near_face, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(7, 7)));
  return near_face;
}

bool strand_on_face(const Context& ctx, RegionTones& tones, const cv::Mat& near_face, int a,
                    int b) {
  const double limit = ctx.options->face_piece_mass_step;
  if (limit <= 0 || near_face.empty() || !tones.screentone()) return false;
  const double step = tones.mass_step(a, b);
  if (!std::isfinite(step) || step <= limit) return false;
  return std::max(face_share(ctx, near_face, a), face_share(ctx, near_face, b)) >= kOnFaceShare;
}

Eigen::Vector3d light_colour_near(const Context& ctx, int region, const Vec2& at) {
  std::vector<std::pair<double, Eigen::Vector3d>> px;
  px.reserve(121);
  for (int dy = -5; dy <= 5; ++dy)
    for (int dx = -5; dx <= 5; ++dx) {
      const int x = static_cast<int>(std::floor(at.x())) + dx;
      const int y = static_cast<int>(std::floor(at.y())) + dy;
      if (!ctx.original->contains(x, y) || ctx.original->at(x, y) != region) continue;
      const Rgba& p = ctx.image->at(x, y);
      px.push_back({0.299 * p.r + 0.587 * p.g + 0.114 * p.b, Eigen::Vector3d(p.r, p.g, p.b)});
    }
  if (px.empty()) return ctx.regions.at(region).colour;
  const std::size_t k = (px.size() - 1) * 3 / 4;
  std::nth_element(px.begin(), px.begin() + static_cast<std::ptrdiff_t>(k), px.end(),
                   [](const auto& u, const auto& v) { return u.first < v.first; });
  return px[k].second;
}

double RegionTones::tone(int region) {
  auto it = tones_.find(region);
  if (it != tones_.end()) return it->second;
  const cv::Rect box = ctx_->regions.at(region).box;
  const LabelMap& labels = *ctx_->original;
  const auto own = [&](int x, int y) { return labels.contains(x, y) && labels.at(x, y) == region; };
  int n = 0, dark = 0;
  for (int y = box.y; y < box.y + box.height; ++y)
    for (int x = box.x; x < box.x + box.width; ++x) {
      // Pixels 2 px inside the region: its drawn line's anti-aliased rim is
      // no tone.
      if (!own(x, y) || !own(x - 2, y) || !own(x + 2, y) || !own(x, y - 2) || !own(x, y + 2))
        continue;
      const Rgba& p = ctx_->image->at(x, y);
      ++n;
      dark += 0.299 * p.r + 0.587 * p.g + 0.114 * p.b < ctx_->options->dark_luma;
    }
  tone_pixels_[region] = n;
  return tones_[region] = n > 0 ? static_cast<double>(dark) / n : 0.0;
}

double RegionTones::dot_period() { return lattice().valid ? lattice().period : 0.0; }

int RegionTones::tone_pixels(int region) {
  tone(region);
  return tone_pixels_.at(region);
}

bool RegionTones::same_tone(int a, int b, bool* textured) {
  const double ta = tone(a), tb = tone(b);
  *textured = ta >= kMinTone && tb >= kMinTone;
  return !*textured || std::abs(ta - tb) <= kMaxToneStep;
}

double RegionTones::dot_mass(int region) {
  auto it = masses_.find(region);
  if (it != masses_.end()) return it->second;
  const cv::Rect box = ctx_->regions.at(region).box;
  const LabelMap& labels = *ctx_->original;
  const auto own = [&](int x, int y) {
    return labels.contains(box.x + x, box.y + y) && labels.at(box.x + x, box.y + y) == region;
  };
  cv::Mat dark(box.height, box.width, CV_8U, cv::Scalar(0));
  cv::Mat luma(box.height, box.width, CV_32F, cv::Scalar(255));
  std::vector<float> lumas;
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) {
      if (!own(x, y)) continue;
      const Rgba& p = ctx_->image->at(box.x + x, box.y + y);
      const auto l = static_cast<float>(0.299 * p.r + 0.587 * p.g + 0.114 * p.b);
      luma.at<float>(y, x) = l;
      dark.at<std::uint8_t>(y, x) = l < ctx_->options->dark_luma ? 255 : 0;
      lumas.push_back(l);
    }
  if (lumas.empty()) return masses_[region] = -1.0;
  const std::size_t k = (lumas.size() - 1) * 9 / 10;
  std::nth_element(lumas.begin(), lumas.begin() + static_cast<std::ptrdiff_t>(k), lumas.end());
  const float paper = lumas[k];
  cv::Mat comp, stats, centroids;
  const int n = cv::connectedComponentsWithStats(dark, comp, stats, centroids, 8, CV_32S);
  // Whole dots only: small, their rim inside the region (not cut by its
  // outline). The ink is the dots' own (median of their darkest pixels): a
  // drawn line may be darker.
  std::vector<int> dots;
  std::vector<float> cores;
  for (int c = 1; c < n; ++c) {
    if (stats.at<int>(c, cv::CC_STAT_AREA) > kMaxDotArea) continue;  // a drawn line
    const int cx = stats.at<int>(c, cv::CC_STAT_LEFT), cy = stats.at<int>(c, cv::CC_STAT_TOP);
    const int cw = stats.at<int>(c, cv::CC_STAT_WIDTH), ch = stats.at<int>(c, cv::CC_STAT_HEIGHT);
    bool whole = true;
    float core = 255;
    for (int y = cy - 1; y <= cy + ch && whole; ++y)
      for (int x = cx - 1; x <= cx + cw && whole; ++x) {
        whole = own(x, y);
        if (whole && comp.at<int>(y, x) == c) core = std::min(core, luma.at<float>(y, x));
      }
    if (!whole) continue;
    dots.push_back(c);
    cores.push_back(core);
    centres_[region].emplace_back(box.x + centroids.at<double>(c, 0),
                                  box.y + centroids.at<double>(c, 1));
  }
  dots_[region] = static_cast<int>(dots.size());
  if (static_cast<int>(dots.size()) < kMinMassDots) return masses_[region] = -1.0;
  std::nth_element(cores.begin(), cores.begin() + static_cast<std::ptrdiff_t>(cores.size() / 2),
                   cores.end());
  const float range = std::max(1.0f, paper - cores[cores.size() / 2]);
  std::vector<double> masses;
  for (int c : dots) {
    const int cx = stats.at<int>(c, cv::CC_STAT_LEFT), cy = stats.at<int>(c, cv::CC_STAT_TOP);
    const int cw = stats.at<int>(c, cv::CC_STAT_WIDTH), ch = stats.at<int>(c, cv::CC_STAT_HEIGHT);
    double mass = 0.0;
    for (int y = cy - 1; y <= cy + ch; ++y)
      for (int x = cx - 1; x <= cx + cw; ++x) {
        const int l = comp.at<int>(y, x);
        if (l == c || l == 0)
          mass += std::clamp((paper - luma.at<float>(y, x)) / range, 0.0f, 1.0f);
      }
    masses.push_back(mass);
  }
  if (static_cast<int>(masses.size()) < kMinMassDots) return masses_[region] = -1.0;
  const std::size_t m = masses.size() / 2;
  std::nth_element(masses.begin(), masses.begin() + static_cast<std::ptrdiff_t>(m), masses.end());
  return masses_[region] = masses[m];
}

const RegionTones::Lattice& RegionTones::lattice() {
  if (lattice_state_ >= 0) return lattice_;
  lattice_state_ = 0;
  // Nearest-neighbour steps between whole dots of one region: one period
  // along the lattice's axes (the diagonal is sqrt(2) longer); their angle
  // modulo 90° is the lattice's.
  constexpr std::size_t kMaxDotsPerRegion = 200;
  std::vector<std::pair<double, double>> steps;
  double c4 = 0.0, s4 = 0.0;
  for (const auto& [id, info] : ctx_->regions) {
    dot_mass(id);
    auto it = centres_.find(id);
    if (it == centres_.end() || static_cast<int>(it->second.size()) < kMinDots) continue;
    const auto& pts = it->second;
    const std::size_t n = std::min(pts.size(), kMaxDotsPerRegion);
    for (std::size_t i = 0; i < n; ++i) {
      double best = std::numeric_limits<double>::infinity(), bx = 0.0, by = 0.0;
      for (std::size_t j = 0; j < pts.size(); ++j) {
        if (j == i) continue;
        const double dx = pts[j].first - pts[i].first, dy = pts[j].second - pts[i].second;
        const double d = dx * dx + dy * dy;
        if (d < best) best = d, bx = dx, by = dy;
      }
      if (!std::isfinite(best)) continue;
      steps.emplace_back(bx, by);
      const double t = 4.0 * std::atan2(by, bx);
      c4 += std::cos(t), s4 += std::sin(t);
    }
  }
  constexpr std::size_t kMinSteps = 10;
  if (steps.size() < kMinSteps) return lattice_;
  std::vector<double> lengths;
  for (const auto& [x, y] : steps) lengths.push_back(std::hypot(x, y));
  std::nth_element(lengths.begin(),
                   lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2),
                   lengths.end());
  const double median = lengths[lengths.size() / 2];
  // The mean of the steps turned onto one axis (a quarter turn at a time)
  // and near the median length: the period to a hundredth of a pixel, so
  // that the phase holds across the drawing.
  const double axis = std::atan2(s4, c4) / 4.0;
  double sx = 0.0, sy = 0.0;
  int used = 0;
  for (auto [x, y] : steps) {
    if (std::abs(std::hypot(x, y) - median) > 0.15 * median) continue;
    for (int k = 0; k < 4; ++k) {
      if (std::cos(std::atan2(y, x) - axis) > std::cos(M_PI / 4)) break;
      const double t = x;
      x = y, y = -t;  // a quarter turn
    }
    sx += x, sy += y, ++used;
  }
  if (used < static_cast<int>(kMinSteps)) return lattice_;
  Lattice l;
  l.period = std::hypot(sx, sy) / used;
  l.angle = std::atan2(sy, sx);
  if (l.period < 2.0) return lattice_;
  // Refined by least squares over each region's dots against its first
  // one, the lattice indices from the estimate so far, over growing
  // distances (an index is sure while the estimate's drift stays under
  // half a cell): Δ = i a + j a⊥ for the axis vector a.
  double ax = l.period * std::cos(l.angle), ay = l.period * std::sin(l.angle);
  for (double reach : {6.0, 20.0, 60.0, 1e9}) {
    double num_x = 0.0, num_y = 0.0, den = 0.0;
    const double p2 = ax * ax + ay * ay;
    for (const auto& [id, pts] : centres_) {
      if (static_cast<int>(pts.size()) < kMinDots) continue;
      const auto& [x0, y0] = pts.front();
      for (const auto& [x, y] : pts) {
        const double dx = x - x0, dy = y - y0;
        if (dx * dx + dy * dy > reach * reach * p2) continue;
        const double i = std::round((dx * ax + dy * ay) / p2);
        const double j = std::round((-dx * ay + dy * ax) / p2);
        num_x += i * dx + j * dy;
        num_y += i * dy - j * dx;
        den += i * i + j * j;
      }
    }
    if (den <= 0.0) return lattice_;
    ax = num_x / den, ay = num_y / den;
  }
  l.period = std::hypot(ax, ay);
  l.angle = std::atan2(ay, ax);
  l.valid = true;
  lattice_ = l;
  return lattice_;
}

double RegionTones::cell_mass(int region) {
  auto it = cells_.find(region);
  if (it != cells_.end()) return it->second;
  double& out = cells_[region] = -1.0;
  if (!screentone() || !lattice().valid) return out;
  const Lattice& l = lattice_;
  const cv::Rect box = ctx_->regions.at(region).box;
  const LabelMap& labels = *ctx_->original;
  const auto own = [&](int x, int y) { return labels.contains(x, y) && labels.at(x, y) == region; };
  const auto luma_at = [&](int x, int y) {
    const Rgba& p = ctx_->image->at(x, y);
    return static_cast<float>(0.299 * p.r + 0.587 * p.g + 0.114 * p.b);
  };
  // Pixels 2 px inside the region (as `tone`): its drawn line's
  // anti-aliased rim is no dot.
  std::vector<cv::Point> inside;
  std::vector<float> lumas;
  for (int y = box.y; y < box.y + box.height; ++y)
    for (int x = box.x; x < box.x + box.width; ++x)
      if (own(x, y) && own(x - 2, y) && own(x + 2, y) && own(x, y - 2) && own(x, y + 2)) {
        inside.emplace_back(x, y);
        lumas.push_back(luma_at(x, y));
      }
  if (lumas.empty()) return out;
  const auto percentile = [&](int pc) {
    const std::size_t k = (lumas.size() - 1) * pc / 100;
    std::nth_element(lumas.begin(), lumas.begin() + static_cast<std::ptrdiff_t>(k), lumas.end());
    return lumas[k];
  };
  const float paper = percentile(90), ink = percentile(2);
  const float range = std::max(1.0f, paper - ink);
  const auto darkness = [&](const cv::Point& q) {
    return std::clamp((paper - luma_at(q.x, q.y)) / range, 0.0f, 1.0f);
  };
  // The lattice's phase here: the darkness-weighted circular mean of the
  // lattice coordinates of the pixels round the region (kPhaseReach periods;
  // its own and those of regions showing whole dots, 2 px inside their
  // region: dots lie on the lattice's points, whole, cut or touching; the
  // region's own dots alone, cut by its border, would pull the mean off). The region's own dots
  // must lie on that phase (their resultant along it at least kMinPhaseStrength): a tone of another
  // lattice, or none, measures nothing.
  const double ca = std::cos(l.angle) / l.period, sa = std::sin(l.angle) / l.period;
  const auto resultant = [&](const cv::Point& q, double w, double* c) {
    const double u = ca * q.x + sa * q.y, v = -sa * q.x + ca * q.y;
    c[0] += w * std::cos(2 * M_PI * u), c[1] += w * std::sin(2 * M_PI * u);
    c[2] += w * std::cos(2 * M_PI * v), c[3] += w * std::sin(2 * M_PI * v);
  };
  // Along a row the lattice coordinates' phasors turn by a fixed step.
  using Phasor = std::complex<double>;
  const Phasor step_u = std::polar(1.0, 2 * M_PI * ca), step_v = std::polar(1.0, -2 * M_PI * sa);
  Phasor near_u = 0.0, near_v = 0.0;
  const int reach = static_cast<int>(std::ceil(kPhaseReach * l.period));
  std::vector<char> dotted(static_cast<std::size_t>(ctx_->regions.rbegin()->first) + 1, 0);
  for (const auto& [id, info] : ctx_->regions) dotted[id] = id == region || dot_mass(id) > 0;
  const int x0 = std::max(0, box.x - reach), x1 = std::min(labels.width(), box.br().x + reach);
  const int y0 = std::max(0, box.y - reach), y1 = std::min(labels.height(), box.br().y + reach);
  for (int y = y0; y < y1; ++y) {
    Phasor zu = std::polar(1.0, 2 * M_PI * (ca * x0 + sa * y));
    Phasor zv = std::polar(1.0, 2 * M_PI * (-sa * x0 + ca * y));
    for (int x = x0; x < x1; ++x, zu *= step_u, zv *= step_v) {
      const int id = labels.at(x, y);
      // Its own pixels and those of regions showing whole dots: plain
      // fills are no dots.
      if (id <= 0 || id >= static_cast<int>(dotted.size()) || !dotted[id]) continue;
      const double w = darkness(cv::Point(x, y));
      if (w <= 0.0) continue;
      const auto in = [&](int px, int py) {
        return labels.contains(px, py) && labels.at(px, py) == id;
      };
      if (!in(x - 2, y) || !in(x + 2, y) || !in(x, y - 2) || !in(x, y + 2)) continue;
      near_u += w * zu, near_v += w * zv;
    }
  }
  const double near[4] = {near_u.real(), near_u.imag(), near_v.real(), near_v.imag()};
  const std::pair<double, double> phase{std::atan2(near[1], near[0]) / (2 * M_PI),
                                        std::atan2(near[3], near[2]) / (2 * M_PI)};
  double mine[4] = {0, 0, 0, 0}, weight = 0.0;
  for (const cv::Point& q : inside) {
    const double w = darkness(q);
    if (w <= 0.0) continue;
    resultant(q, w, mine);
    weight += w;
  }
  const auto along = [&](double c, double s, double p) {
    return c * std::cos(2 * M_PI * p) + s * std::sin(2 * M_PI * p);
  };
  if (weight <= 0.0 || along(mine[0], mine[1], phase.first) < kMinPhaseStrength * weight ||
      along(mine[2], mine[3], phase.second) < kMinPhaseStrength * weight)
    return out;
  // The dots' radial profile: the mean darkness of the pixels at each
  // distance (bins of kProfileBin px) from their nearest lattice point, out
  // to half a period. A dot cut by the region's border still shows its
  // profile from the lattice point outwards, so slivers between strands
  // (every dot cut) and dense tones (dots touching) are measured as well.
  const int bins = static_cast<int>(0.5 * l.period / kProfileBin) + 1;
  std::vector<double> sum(bins, 0.0);
  std::vector<int> count(bins, 0);
  for (const cv::Point& q : inside) {
    const double u = ca * q.x + sa * q.y - phase.first, v = -sa * q.x + ca * q.y - phase.second;
    const double fu = u - std::round(u), fv = v - std::round(v);
    const int b = static_cast<int>(l.period * std::sqrt(fu * fu + fv * fv) / kProfileBin);
    if (b >= bins) continue;
    sum[b] += darkness(q);
    ++count[b];
  }
  // The radius: where the profile falls through one half, interpolated
  // between the centres of the sampled bins on both sides (bins near a
  // lattice point hold few pixels: they are skipped).
  double radius = -1.0;
  int inner = -1;
  for (int b = 0; b < bins; ++b) {
    if (count[b] < kMinProfilePixels) continue;
    const double m = sum[b] / count[b];
    if (m >= 0.5) {
      inner = b;
      continue;
    }
    if (inner < 0) return out;
    const double mi = sum[inner] / count[inner];
    const double t = (mi - 0.5) / std::max(1e-9, mi - m);
    radius = kProfileBin * (inner + 0.5 + t * (b - inner));
    break;
  }
  if (radius < 0.0) return out;
  return out = M_PI * radius * radius;
}

bool RegionTones::screentone() {
  if (screentone_ < 0) {
    int dotted = 0;
    for (const auto& [id, info] : ctx_->regions) {
      dot_mass(id);
      dotted += dots_[id] >= kMinDots;
    }
    screentone_ = ctx_->regions.empty() ? 0 : 4 * dotted >= static_cast<int>(ctx_->regions.size());
  }
  return screentone_ == 1;
}

bool RegionTones::two_tones(int a, int b) {
  if (match(a, b) != Match::kOther) return false;
  if (std::min(dots_[a], dots_[b]) >= kMinShareDots) return true;
  const double ca = cell_mass(a), cb = cell_mass(b);
  return ca <= 0 || cb <= 0 || std::abs(ca - cb) / std::max(ca, cb) > kMinOtherMassStep;
}

double RegionTones::whole_dot_mass(int region) {
  const double m = dot_mass(region);
  if (m <= 0) return m;
  const double cell = cell_mass(region);
  return cell > 0 && m > kMaxMergedDotRatio * cell ? -1.0 : m;
}

double RegionTones::mass_step(int a, int b) {
  const double ma = whole_dot_mass(a), mb = whole_dot_mass(b);
  if (ma > 0 && mb > 0) return std::abs(ma - mb) / std::max(ma, mb);
  const double ca = cell_mass(a), cb = cell_mass(b);
  if (ca > 0 && cb > 0) return std::abs(ca - cb) / std::max(ca, cb);
  return std::numeric_limits<double>::infinity();
}

RegionTones::Match RegionTones::match(int a, int b) {
  if (!screentone()) return Match::kUnknown;
  const double ma = whole_dot_mass(a), mb = whole_dot_mass(b), ta = tone(a), tb = tone(b);
  if (ta < kMinTone || tb < kMinTone) return Match::kUnknown;
  if (ma <= 0 || mb <= 0) {
    // A piece without a whole dot: both pieces' dots weighed on the
    // lattice (cell_mass), which fixes the period, so the dark share (which
    // moves with how a small piece cuts the dots) is not asked.
    const double step = mass_step(a, b);
    if (!std::isfinite(step)) return Match::kUnknown;
    if (step <= kMaxSameCellStep) return Match::kSame;
    if (step > kMinOtherMassStep) return Match::kOther;
    return Match::kUnknown;
  }
  const double mass_step = std::abs(ma - mb) / std::max(ma, mb), tone_step = std::abs(ta - tb);
  if (mass_step <= kMaxSameMassStep && tone_step <= kMaxSameToneStep) return Match::kSame;
  // The dark share moves with how a small piece cuts the dots: it tells two
  // tones only where both pieces hold kMinShareDots whole dots.
  if (mass_step > kMinOtherMassStep ||
      (tone_step > kMinOtherToneStep && std::min(dots_[a], dots_[b]) >= kMinShareDots))
    return Match::kOther;
  return Match::kUnknown;
}

double tone_join_cost(RegionTones& tones, int a, int b) {
  // Chosen on generated screentone seeds 101-116 (precision / recall 0.852 /
  // 0.462 -> 0.952 / 0.500 with the path joins' rule off); the bonus lets
  // strand joins of one tone up to 3.6 through, where the candidates of one
  // strand were 131 of 320 and those of one tone 90 % right.
  constexpr double kSameToneBonus = 1.2, kOtherTonePenalty = 1.0;
  constexpr double kWhiteBonus = 0.6, kWhiteTonePenalty = 0.6;
  constexpr double kWhite = RegionTones::kPaperWhite;
  if (!tones.screentone()) return 0.0;
  switch (tones.match(a, b)) {
    case RegionTones::Match::kSame:
      return -kSameToneBonus;
    case RegionTones::Match::kOther:
      return kOtherTonePenalty;
    case RegionTones::Match::kUnknown:
      break;
  }
  if (std::max(tones.tone(a), tones.tone(b)) < kWhite) return -kWhiteBonus;
  if (dark_shares_apart(tones, a, b)) return kWhiteTonePenalty;
  return 0.0;
}

std::vector<MassJoin> path_join_candidates(const Context& ctx, const cv::Mat& face,
                                           RegionTones& tones, RegionFields& fields,
                                           const std::function<bool(int, int)>& one_strand) {
  if (!ctx.options->path_joins) return {};
  const cv::Mat near_face = near_face_mask(face);
  const std::set<int> front = ctx.front();
  TailedHair tailed = tailed_hair(ctx, front);
  untail_back_paint(ctx, front, fields.cels(), &tailed);
  // Back hair lying on hair that hangs from under it (tails, strands hanging
  // behind it: lowest regions covered by at most kMaxHangingCover regions)
  // lies above some region, so it is front hair by its relations, and was
  // no piece (tailed_hair's tails are narrower: their every cover lies on
  // lowest regions only, so a side lock lying on the back and on a tail
  // made the back front hair: flat 103, 112).
  // On screentone drawings they stay front pieces, which the tone path joins
  // below take to a piece above no region only when the dots agree closely.
  // A lock may hang from under a lock (the generator stacks up to four): a
  // piece lying on such a lock hangs it too (flat 112: back 1 on tails 3,
  // 11 and on tail 6, which lies on tail 10; at a limit of 4, flat 101-116
  // 0.969 / 0.815 -> 0.970 / 0.830 with it, at 2 no change).
  std::set<int> over_hanging;
  // (piece, region below it): whether the piece rests on it, measured once.
  std::map<std::pair<int, int>, bool> resting;
  for (bool grew = !tones.screentone(); grew;) {
    grew = false;
    for (const auto& [id, info] : ctx.regions) {
      if (!front.count(id) || info.occluders.empty() || over_hanging.count(id)) continue;
      bool hanging = true;
      for (const auto& [low, low_info] : ctx.regions) {
        if (!hanging) break;
        if (!low_info.occluders.count(id)) continue;
        const int covers = static_cast<int>(low_info.occluders.size());
        hanging = (!front.count(low) || over_hanging.count(low)) && covers <= kMaxRestingCover;
        if (!hanging || covers <= kMaxHangingCover) continue;
        auto it = resting.find({id, low});
        if (it == resting.end())
          it = resting.emplace(std::pair{id, low}, outline_share(ctx, id, low) <= kMaxRestingShare)
                   .first;
        hanging = it->second;
      }
      if (hanging) grew = over_hanging.insert(id).second;
    }
  }
  std::vector<int> pieces;
  for (const auto& [id, info] : ctx.regions)
    if ((!front.count(id) || tailed.over_tails.count(id) || over_hanging.count(id)) &&
        !info.occluders.empty() && !tailed.tails.count(id))
      pieces.push_back(id);
  cv::Rect hair;
  for (const auto& [id, info] : ctx.regions) hair = hair.area() == 0 ? info.box : (hair | info.box);
  const double reach = 0.5 * std::max(hair.width, hair.height);
  const auto above = [&](int r) -> const std::set<int>& {
    static const std::set<int> kNone;
    auto it = ctx.above.find(r);
    return it == ctx.above.end() ? kNone : it->second;
  };
  // The pairs that pass the paint's tests, then their paths: the paths are
  // most of this pass's time (session 40: 0.55 G of the seed-7 screentone
  // drawing's 13.5 G instructions, on one core while the other waited) and
  // read only the context, so they are found on several threads.
  struct Pair {
    int a, b;
    std::set<int> common;
    RegionTones::Match match;
    bool textured;
    RegionCels::Judgement cel;
  };
  std::vector<Pair> pairs;
  for (std::size_t i = 0; i < pieces.size(); ++i)
    for (std::size_t k = i + 1; k < pieces.size(); ++k) {
      const int a = pieces[i], b = pieces[k];
      if (ctx.is_above(a, b) || ctx.is_above(b, a)) continue;
      if (one_strand && one_strand(a, b)) continue;
      if ((ctx.regions.at(a).colour - ctx.regions.at(b).colour).norm() >
          ctx.options->max_colour_distance)
        continue;
      const std::set<int> common = common_above(above(a), above(b));
      if (common.empty()) continue;
      if (std::min(face_share(ctx, near_face, a), face_share(ctx, near_face, b)) >= kMaxFaceShare)
        continue;
      // Dots measured on both pieces decide alone: one tone, whatever the
      // light percentile says (on screentone seeds 101-116 right path
      // candidates stepped up to 390 RGB there, the back hair's windows
      // holding drawn lines), or two.
      const RegionTones::Match match = tones.match(a, b);
      if (match == RegionTones::Match::kOther) continue;
      if (strand_on_face(ctx, tones, near_face, a, b)) continue;
      bool textured = match == RegionTones::Match::kSame;
      // On a cel drawing the pieces' paint (RegionCels::judge): a piece in
      // the other's base or band, on its side of the band's level, passes
      // whatever the windows say; pieces of other flat colours are refused.
      // The dark share says nothing there (two-tone 104: the back's band
      // lies below dark_luma, so pieces in the band passed for textured).
      const RegionCels::Judgement cel = fields.cels().judge(a, b);
      if (cel.other) continue;
      if (!textured && !tones.same_tone(a, b, &textured) && !cel.same) continue;
      pairs.push_back({a, b, common, match, textured, cel});
    }
  std::vector<std::vector<Landing>> paths(pairs.size());
  parallel_each(pairs.size(), ctx.options->threads, [&](std::size_t k) {
    paths[k] = crossing_paths(ctx, pairs[k].a, pairs[k].b, pairs[k].common, reach);
  });
  std::vector<MassJoin> out;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto& [a, b, common, match, textured, cel] = pairs[k];
    const std::vector<Landing>& landings = paths[k];
    if (static_cast<int>(landings.size()) < kMinLandings) continue;
    std::vector<double> colour_steps;
    const int n = static_cast<int>(landings.size());
    const int samples = std::min(n, kColourSamples);
    for (int s = 0; s < samples; ++s) {
      const Landing& l = landings[static_cast<std::size_t>(s) * n / samples];
      // Under a tone the paper between the dots (a window's mean moves
      // with the dots' phase); elsewhere the mean, which anti-aliased rims
      // and shading move (flat drawings of one paint: pieces of different
      // strands step 0 at the light percentile, annotated precision 0.982
      // -> 0.865).
      const Eigen::Vector3d ca =
          textured ? light_colour_near(ctx, a, l.from) : colour_near(ctx, a, l.from, Vec2(0, 0));
      const Eigen::Vector3d cb =
          textured ? light_colour_near(ctx, b, l.to) : colour_near(ctx, b, l.to, Vec2(0, 0));
      colour_steps.push_back((ca - cb).norm());
    }
    const auto median = [](std::vector<double> v) {
      std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
      return v[v.size() / 2];
    };
    const double step = median(colour_steps);
    // Or one linear field paints both pieces (a gradient over the back
    // hair steps across the strand between the windows).
    const double field =
        tones.screentone() ? std::numeric_limits<double>::infinity() : fields.step(a, b);
    if (step > kMaxPathColourStep && match != RegionTones::Match::kSame &&
        field > kMaxPathFieldStep && !cel.same)
      continue;
    out.push_back(path_join(a, b, landings, std::min({step, field, cel.same ? cel.step : step})));
  }
  sort_by_colour(out);
  // Cel drawings: two pieces of a strand (one of them at least lying above
  // some region) in one flat paint that no other region shares, linked
  // under the regions lying above both (session 14). The generator paints
  // each strand in its own colour, so one rare paint on both sides of the
  // strands lying over them is what a person follows, whatever the
  // pieces' cut edges say (tangents turned away at a root, a cap sliver
  // between bangs, no edge pair at all: the strand joins' open links).
  // Two guards: a strand runs on along its length, so the paths must run
  // along at least one piece (two bangs of one paint side by side, flat
  // 115); and they stay within half the back hair's reach (the cap joined
  // to a side lock's tip of its paint far below, two-tone 108).
  // Elsewhere one linear field (kMaxRareFieldStep) is the one paint.
  if (!tones.screentone() && ctx.regions.size() >= kMinRarePaintRegions) {
    const bool cel = fields.cels().cel_drawing();
    const double max_step = cel ? kMaxRareCelStep : kMaxRareFieldStep;
    std::vector<int> ids;
    for (const auto& [id, info] : ctx.regions) ids.push_back(id);
    std::map<int, int> sharing;
    for (std::size_t i = 0; i < ids.size(); ++i)
      for (std::size_t k = i + 1; k < ids.size(); ++k)
        if (fields.paint_step(ids[i], ids[k]) <= max_step) ++sharing[ids[i]], ++sharing[ids[k]];
    std::vector<MassJoin> rare;
    for (std::size_t i = 0; i < ids.size(); ++i)
      for (std::size_t k = i + 1; k < ids.size(); ++k) {
        const int a = ids[i], b = ids[k];
        if (!front.count(a) && !front.count(b)) continue;
        if (sharing[a] != 1 || sharing[b] != 1) continue;
        if (ctx.is_above(a, b) || ctx.is_above(b, a)) continue;
        if (one_strand && one_strand(a, b)) continue;
        const double step = fields.paint_step(a, b);
        if (step > max_step) continue;
        const std::set<int> common = common_above(above(a), above(b));
        if (common.empty()) continue;
        const std::vector<Landing> landings = crossing_paths(ctx, a, b, common, reach);
        if (static_cast<int>(landings.size()) < kMinLandings) continue;
        double length = 0.0;
        for (const Landing& l : landings) length += (l.to - l.from).norm();
        length /= static_cast<double>(landings.size());
        if (length > kMaxRarePathReach * reach) continue;
        const Vec2 direction = mean_direction(landings);
        if (std::max(axis_cos(ctx, a, direction), axis_cos(ctx, b, direction)) < kMinAxisCos)
          continue;
        rare.push_back(path_join(a, b, landings, step));
      }
    sort_by_colour(rare);
    out.insert(out.end(), std::make_move_iterator(rare.begin()),
               std::make_move_iterator(rare.end()));
  }
  // Screentone: pieces of a strand crossed by another strand (a bang under
  // a bang, a side lock under a bang) are front hair, lying above some
  // region, and their dots are the one cue they carry. Two such pieces of
  // one tone (dot masses and dark shares agree) linked under the strands
  // lying above both are joined, after the back hair's joins. A front piece
  // and one lying above no region only when their masses agree closely
  // (kMaxMixedMassStep): on screentone seeds 101-116 every wrong candidate
  // of one tone paired a strand with such a piece (back hair, a bang's end
  // on the face), none two front pieces. Two pieces above no region are
  // left to the rules above.
  if (tones.screentone()) {
    const auto mass_step = [&](int a, int b) { return tones.mass_step(a, b); };
    std::vector<MassJoin> toned;
    for (auto i = ctx.regions.begin(); i != ctx.regions.end(); ++i)
      for (auto k = std::next(i); k != ctx.regions.end(); ++k) {
        const int a = i->first, b = k->first;
        const int fronts = static_cast<int>(front.count(a) + front.count(b));
        if (fronts == 0) continue;
        if (ctx.is_above(a, b) || ctx.is_above(b, a)) continue;
        if (tones.match(a, b) != RegionTones::Match::kSame) continue;
        if (fronts == 1 && mass_step(a, b) > kMaxMixedMassStep) continue;
        const std::set<int> common = common_above(above(a), above(b));
        if (common.empty()) continue;
        const std::vector<Landing> landings = crossing_paths(ctx, a, b, common, reach);
        if (static_cast<int>(landings.size()) < kMinLandings) continue;
        // Two strands side by side under one occluder: a path across it
        // from one strand's side to the other's runs across a piece's long
        // axis, where a strand passing under runs along both (session 21).
        if (fronts == 2 && common.size() == 1) {
          const Vec2 direction = mean_direction(landings);
          if (std::min(axis_cos(ctx, a, direction), axis_cos(ctx, b, direction)) < kMinToneAxisCos)
            continue;
        }
        // Two strands side by side, or a strand's tip reaching past a
        // neighbour's end, meet on a few pixels of the smaller piece; a
        // strand passing under lands across its width
        // (Options::tone_path_landing_share, session 38).
        if (fronts == 2 && few_landings(ctx, a, b, landings.size())) continue;
        // Ranked by the dot masses' step, not an RGB step.
        toned.push_back(path_join(a, b, landings, mass_step(a, b)));
      }
    sort_by_colour(toned);
    out.insert(out.end(), std::make_move_iterator(toned.begin()),
               std::make_move_iterator(toned.end()));
  }
  // The back hair's own paint, no common occluder (session 15): the top of
  // the back seen round the cap and its lower part beside the face or neck
  // share no region lying above both (the cap lies on the top, side locks
  // and bangs on the lower part), so the path joins above find no path.
  // Pieces in the paint of the largest piece lying above no region (the
  // back hair: the generator paints it darker than its strands, so strands
  // seldom share it) are linked by paths through regions lying above
  // either of them. Pieces of a strand in another paint are left to the
  // passes above: two strands of one flat paint are common (the generator
  // varies each strand's colour a little; on flat 2000-2099 and mixed
  // 3000-3099 such candidates between the cap and strands lying on the
  // face were 7 of 11 wrong ones).
  const std::vector<MassJoin> behind =
      back_paint_joins(ctx, pieces, front, near_face, tones, fields, out, one_strand, reach);
  out.insert(out.end(), behind.begin(), behind.end());
  return out;
}

}  // namespace hair25d::completion::detail
