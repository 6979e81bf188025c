#include "join_raster.h"

#include <algorithm>
#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>

#include "join_corridor.h"
#include "join_shapes.h"
#include "parallel_each.h"
#include "raster.h"

namespace hair25d::completion::detail {
namespace {

// Options::join_arm_shares: other shapes of the hidden part are tried only
// for a patch at least this much under the occluders. The shapes keep the
// cuts and their tangents and move the band's middle a part of its width;
// a patch mostly off the occluders is another join, not another curve. On
// dev mixed 2000-2099, of 192 candidates tried from cover 0 up, 37 of the
// 38 a shape lets in lie over 0.6 (one over 0.5, none under), and the
// patches under 0.6 were the largest: the seed-7 1024² drawing of 40
// strands spent 51 of its 52 ms of shapes on them.
constexpr double kMinCoverToReshape = 0.6;

// Options::corridor_width: the corridor is sought only for a patch at
// least this much under the occluders (a few ms a large back piece's box
// otherwise).
constexpr double kMinCoverForCorridor = 0.5;

}  // namespace

double coverage(const Context& ctx, const Polyline& patch, int ra, int rb, const cv::Mat& face,
                int* hidden, const std::set<int>* front, std::map<int, int>* lowest, bool ink,
                std::map<int, int>* under_by, JoinTrace* trace, bool fringe, CoverMisses* misses) {
  const LabelMap& labels = fringe ? ctx.cover_map() : ctx.labels;
  if (misses) misses->clear();
  const cv::Rect box = polygon_box(patch);
  if (box.empty()) return 0.0;
  const cv::Point origin = box.tl();
  const int w = box.width, h = box.height;
  thread_local std::vector<std::uint8_t> kept;
  ScratchBytes scratch(kept, static_cast<std::size_t>(w) * h);
  cv::Mat mask(h, w, CV_8U, scratch.data());
  fill_polygon(mask, patch, origin, 255);
  // A patch crosses few labels, each over many pixels: what the relations
  // say of a label is asked once, not per pixel (the tree look-ups were
  // most of the time of the wide candidates' rasters, session 29), and the
  // pixels are counted per label before the maps are.
  struct LabelCount {
    int label;
    bool above, back;  // above a or b; another region above no region
    int pixels = 0, under = 0;
    int missed = 0;  // uncovered pixels left to class by the label (`misses`)
  };
  std::vector<LabelCount> seen;
  std::size_t last = 0;
  auto count_of = [&](int l) -> LabelCount& {
    if (last < seen.size() && seen[last].label == l) return seen[last];
    for (last = 0; last < seen.size(); ++last)
      if (seen[last].label == l) return seen[last];
    seen.push_back({l, l != 0 && (ctx.is_above(l, ra) || ctx.is_above(l, rb)),
                    lowest && l != 0 && !front->count(l)});
    return seen[last];
  };
  int under = 0, total = 0;
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* row = mask.ptr<std::uint8_t>(y);
    const int gy = y + origin.y;
    const bool row_inside = gy >= 0 && gy < labels.height();
    const int* label_row =
        row_inside ? labels.data() + static_cast<std::size_t>(gy) * labels.width() : nullptr;
    const HiddenRow hides = row_inside ? HiddenRow(ctx, face, ink, gy) : HiddenRow();
    const int map_end = std::min(w, labels.width() - origin.x);  // x past the map's right side
    for (int x = 0; x < w; ++x) {
      if (!row[x]) continue;
      const int gx = x + origin.x;
      if (!row_inside || gx < 0 || gx >= labels.width()) {
        ++total;
        if (trace) trace->hole_background += 1;
        if (misses) misses->add_pixel(ctx, false, 0, gx, gy);
        continue;
      }
      const int l = label_row[gx];
      if (l == ra || l == rb) continue;
      // The run of this label under the patch along the row (a row crosses
      // few labels): its pixels are counted at once, and looked at one by
      // one only where each may tell (the face, the ink, a miss's place).
      int end = x + 1;
      while (end < map_end && row[end] && label_row[end + origin.x] == l) ++end;
      const int n = end - x;
      total += n;
      LabelCount& c = count_of(l);
      c.pixels += n;
      if (c.above) {
        under += n;
        c.under += n;
      } else if (hides.per_pixel(l) || misses) {
        for (int k = gx; k < end + origin.x; ++k) {
          // Across a cut of ink only, the drawn ink is what lies over the gap.
          if (hides.hidden(false, l, k)) {
            ++under;
            ++c.under;  // the face and the ink count as 0
          } else if (misses && !misses->add_pixel(ctx, true, l, k, gy)) {
            ++c.missed;
          }
        }
      }
      x = end - 1;
    }
  }
  if (misses) misses->total = total;
  for (const LabelCount& c : seen) {
    if (c.back) (*lowest)[c.label] += c.pixels;
    if (under_by && c.under > 0) (*under_by)[c.label] += c.under;
    if (c.missed > 0) misses->add_region(ctx, c.label, c.missed);
    if (!trace || c.pixels == c.under) continue;
    // Options::trace_joins: what the uncovered pixels are, a label at a time.
    const int l = c.label;
    double* hole = &trace->hole_background;
    if (l != 0) switch (hole_kind(ctx, ra, rb, l)) {
        case HoleKind::kBelow:
          hole = &trace->hole_below;
          break;
        case HoleKind::kSibling:
          hole = &trace->hole_sibling;
          break;
        case HoleKind::kOther:
          hole = &trace->hole_other;
          break;
      }
    *hole += c.pixels - c.under;
  }
  *hidden = total;
  if (trace && total > 0)
    for (double* share :
         {&trace->hole_background, &trace->hole_below, &trace->hole_sibling, &trace->hole_other})
      *share /= total;
  return total > 0 ? static_cast<double>(under) / total : 1.0;
}

bool occluders_above_pieces(const Context& ctx, const std::map<int, int>& under_by, int ra, int rb,
                            bool users) {
  int total = 0;
  for (const auto& [l, n] : under_by) total += n;
  if (total == 0) return false;
  const auto above = [&](int l, int r) {
    return users ? ctx.is_user_above(l, r) : ctx.is_above(l, r);
  };
  for (const auto& [l, n] : under_by)
    if (l != 0 && 10 * n >= total && !above(l, ra) && !above(l, rb)) return false;
  return true;
}

PatchRaster raster_patch(const Context& ctx, const std::set<int>& front, const cv::Mat& face,
                         const PatchJob& job) {
  const Options& o = *ctx.options;
  const Edge& a = *job.a;
  const Edge& b = *job.b;
  const cv::Mat no_face;
  const cv::Mat& cover_face = job.behind_face ? face : no_face;
  PatchRaster r;
  JoinTrace* t = job.trace ? &r.holes : nullptr;
  std::map<int, int>* lowest = job.front_counts ? &r.lowest : nullptr;
  std::map<int, int>* under_by = job.by_label ? &r.under_by : nullptr;
  r.patch = join_patch(a, b);
  // What the patch leaves uncovered, counted in the same pass where the
  // candidate may become a cover refusal's second chance.
  r.misses = CoverMisses{&a, &b, &face};
  CoverMisses* misses = job.may_retry ? &r.misses : nullptr;
  r.cover = coverage(ctx, r.patch, a.region, b.region, cover_face, &r.hidden, &front, lowest,
                     job.ink, under_by, t, false, misses);
  // The patch of a third's arms is one of the shapes, measured by the same
  // rule.
  const JoinShape drawn{1.0 / 3.0, 1.0 / 3.0, r.cover};
  // Options::join_arm_shares: the hidden strand may take any smooth path
  // under the occluders, the patch of a third's arms is one guess (where
  // match_edges lets a shape in: `job.reshape`).
  if (job.reshape && r.cover < o.min_join_coverage && r.cover >= kMinCoverToReshape) {
    const JoinShape shape =
        best_join_shape(ctx, a, b, cover_face, job.ink, o.join_arm_shares, drawn);
    r.reshaped_cover = shape.cover;
    if (shape.cover >= o.min_join_coverage &&
        job.cost + kUncoveredCost * (1.0 - shape.cover) <= o.max_join_cost) {
      r.patch = join_patch(a, b, shape.share_a, shape.share_b);
      r.lowest.clear();
      r.under_by.clear();
      if (t) t->hole_background = t->hole_below = t->hole_sibling = t->hole_other = 0.0;
      r.cover = coverage(ctx, r.patch, a.region, b.region, cover_face, &r.hidden, &front, lowest,
                         job.ink, under_by, t, false, misses);
    }
  }
  // Options::cover_fringe (where match_edges lets it act: `job.fringe`).
  if (job.fringe) {
    int fringe_hidden = 0;
    std::map<int, int> fringe_under;
    const double fringe_cover =
        coverage(ctx, r.patch, a.region, b.region, cover_face, &fringe_hidden, nullptr, nullptr,
                 job.ink, &fringe_under, nullptr, true);
    if (fringe_cover > r.cover &&
        occluders_above_pieces(ctx, fringe_under, a.region, b.region, job.users)) {
      r.cover = fringe_cover;
      r.hidden = fringe_hidden;
      if (job.by_label) r.under_by = fringe_under;
    }
  }
  // Options::corridor_width (where match_edges lets it act: `job.corridor`).
  if (job.corridor && r.cover < o.min_join_coverage && r.cover >= kMinCoverForCorridor &&
      job.cost + kUncoveredCost * (1.0 - r.cover) <= job.limit)
    r.corridor = corridor_under_occluders(ctx, a, b, r.patch, cover_face, job.ink,
                                          o.corridor_width * job.narrow, job.wide);
  // A cover refusal's second chance reads the best shape's cover, measured
  // whatever the guards of the shapes above say; asked here of every
  // candidate that may become one (a few become none: another piece's back
  // hair under the patch refuses them outright).
  if (job.retry_shape && r.cover < o.min_join_coverage && !r.corridor && r.reshaped_cover < 0)
    r.retry_shape_cover =
        best_join_shape(ctx, a, b, cover_face, job.ink, o.join_arm_shares, drawn).cover;
  return r;
}

std::vector<PatchRaster> raster_patches(const Context& ctx, const std::set<int>& front,
                                        const cv::Mat& face, const std::vector<PatchJob>& jobs,
                                        int threads) {
  std::vector<PatchRaster> out(jobs.size());
  parallel_each(jobs.size(), threads,
                [&](std::size_t k) { out[k] = raster_patch(ctx, front, face, jobs[k]); });
  return out;
}

}  // namespace hair25d::completion::detail
