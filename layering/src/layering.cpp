#include "hair25d/layering/layering.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>

#include "boundary_trace.h"
#include "colour_line.h"
#include "hair25d/core/error.h"
#include "hair25d/core/firm_equal.h"
#include "hair25d/layering/depth_order.h"
#include "hair25d/layering/metrics.h"
#include "hair25d/layering/optimizer.h"
#include "line_response.h"
#include "neighbours.h"
#include "outline_fill.h"
#include "parallel.h"
#include "patch_model.h"
#include "raster_scan.h"

namespace hair25d::layering {
namespace {

constexpr double kClamp = 1e6;  // unary that pins a user-fixed boundary

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

bool positive_finite(double v) { return std::isfinite(v) && v > 0; }

// One end of a boundary at a junction, walked away from the junction.
struct Ray {
  int boundary = 0;
  bool at_start = true;
  Vec2 direction;
};

std::pair<int, int> key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

Relation relation_of_sign(double s) { return s >= 0 ? Relation::kAbove : Relation::kBelow; }

}  // namespace

bool Options::is_valid(std::string* error) const {
  auto fail = [&](const std::string& what) {
    if (error) *error = "layering::Options::" + what;
    return false;
  };
  if (!positive_finite(learned_scale))
    return fail("learned_scale = " + num(learned_scale) + "; must be finite and > 0");
  if (!(std::isfinite(junction_weight) && junction_weight >= 0))
    return fail("junction_weight = " + num(junction_weight) + "; must be finite and >= 0");
  if (!positive_finite(coupling_cap))
    return fail("coupling_cap = " + num(coupling_cap) + "; must be finite and > 0");
  if (!std::isfinite(line_width))
    return fail("line_width = " + num(line_width) + "; must be finite (<= 0: estimate)");
  if (!std::isfinite(line_threshold))
    return fail("line_threshold = " + num(line_threshold) + "; must be finite (<= 0: automatic)");
  if (!(line_threshold_fraction > 0 && line_threshold_fraction < 1))
    return fail("line_threshold_fraction = " + num(line_threshold_fraction) +
                "; must be in (0, 1)");
  if (!(smooth_angle >= 0 && smooth_angle <= std::numbers::pi))
    return fail("smooth_angle = " + num(smooth_angle) + "; must be in [0, π]");
  if (!positive_finite(fit_reach_widths))
    return fail("fit_reach_widths = " + num(fit_reach_widths) + "; must be finite and > 0");
  if (!positive_finite(fit_reach_min))
    return fail("fit_reach_min = " + num(fit_reach_min) + "; must be finite and > 0");
  if (!std::isfinite(equal_log_odds))
    return fail("equal_log_odds = " + num(equal_log_odds) + "; must be finite");
  if (std::isnan(open_order_log_odds) ||
      open_order_log_odds == std::numeric_limits<double>::infinity())
    return fail("open_order_log_odds = " + num(open_order_log_odds) +
                "; must be finite, or -infinity (off)");
  if (!(equal_fraction >= 0 && equal_fraction <= 1))
    return fail("equal_fraction = " + num(equal_fraction) + "; must be in [0, 1]");
  for (const RegionRelation& r : fixed)
    if (r.a <= 0 || r.b <= 0 || r.a == r.b)
      return fail("fixed has the pair (" + std::to_string(r.a) + ", " + std::to_string(r.b) +
                  "); must be two different hair region ids > 0");
  return true;
}

Result layer_regions(const Image& image, const LabelMap& regions, const Options& options,
                     Progress* progress) {
  std::string why;
  if (!options.is_valid(&why)) throw Error(why);
  if (regions.empty()) throw Error("layering: the region map is empty; need at least one pixel");
  if (image.width() != regions.width() || image.height() != regions.height())
    throw Error("layering: the region map is " + std::to_string(regions.width()) + "x" +
                std::to_string(regions.height()) + " but the image is " +
                std::to_string(image.width()) + "x" + std::to_string(image.height()) +
                "; they must have the same size");
  // Helpers for every parallel step below, started once (parallel.h).
  detail::Pool pool;
  // The region ids are read by the outline fill while it copies the map
  // (else on the pool's helper while this thread goes on), and checked
  // before anything else is, so bad input is refused as before.
  std::optional<detail::DistinctLabels> scan;
  if (!options.fill_outlines) scan.emplace(regions, &pool);
  std::vector<int> ids;
  auto check_ids = [&] {
    if (scan) ids = scan->get();
    if (ids.size() < 2)
      throw Error("layering: the region map has " + std::to_string(ids.size()) +
                  " hair region(s); layering needs at least two");
    for (const RegionRelation& r : options.fixed)
      for (int id : {r.a, r.b})
        if (!std::binary_search(ids.begin(), ids.end(), id))
          throw Error("layering::Options::fixed names region " + std::to_string(id) +
                      ", which is not in the region map");
  };

  Result out;
  // Grey levels are made on a second core (line_response.h) from when the
  // fill knows its box (prepare below), near it: until then the fill has
  // both cores.
  detail::LineResponse lines(image, &regions, true);
  OutlineFill fill;
  detail::LabelBox filled_box;  // of out.labels' non-zero labels, with the fill
  // The early blur of the grey levels (below) needs only the line width and
  // the filled map's box: it starts on a second core as soon as the fill
  // knows them, before it writes the pixels.
  auto blur_early = [&](double fill_width, const detail::LabelBox& box) {
    const double width = options.line_width > 0 ? options.line_width : fill_width;
    if (width > 0) lines.prepare(width, regions, &box);  // (the box given: the map is not read)
  };
  try {
    if (options.fill_outlines)
      fill = detail::fill_outlines(regions, &pool, &filled_box, &ids, blur_early);
  } catch (...) {
    ids = detail::distinct_labels(regions);
    check_ids();
    throw;
  }
  check_ids();
  report(progress, "layering", 0.0, "boundaries");
  if (options.fill_outlines)
    out.labels = std::move(fill.labels);
  else
    out.labels = regions;
  out.line_width = options.line_width > 0 ? options.line_width
                   : fill.line_width > 0  ? fill.line_width
                                          : detail::LineResponse::estimate_line_width(image);
  // The grey levels are smoothed on a second core while the boundaries are traced.
  lines.prepare(out.line_width, out.labels, options.fill_outlines ? &filled_box : nullptr);
  // The filled map as bytes for the junction patches' samples (patch_model.h:
  // a quarter of the memory to read from), on the pool's helper while this
  // thread traces (where that core has nothing else to do), over the box of
  // non-zero labels (outside it the bytes stay 0). Only where the gathers
  // read it.
  std::vector<std::uint8_t> label_bytes;
  detail::BackgroundTask byte_task(&pool, [&] {
    if (options.metric != Metric::kLearned || !options.junction_patches ||
        !detail::patch_gathers_available())
      return;
    label_bytes.resize(static_cast<std::size_t>(out.labels.width()) * out.labels.height() +
                       detail::kByteLabelsPadding);
    detail::LabelBox box = filled_box;
    if (!options.fill_outlines) box = {true, 0, 0, out.labels.width() - 1, out.labels.height() - 1};
    if (box.any)
      detail::byte_labels(out.labels, box.x0, box.x1 + 1, box.y0, box.y1 + 1, label_bytes.data());
  });
  out.graph = detail::build_boundary_graph(out.labels, true, true,
                                           options.fill_outlines ? &filled_box : nullptr);
  const BoundaryGraph& graph = out.graph;
  const auto& bs = graph.boundaries;
  const int nb = static_cast<int>(bs.size());
  out.boundaries.resize(nb);

  const double reach = std::max(options.fit_reach_min, options.fit_reach_widths * out.line_width);
  // The directions in which each boundary leaves its two ends, fitted three
  // ways (over the fit length, 3 × farther, by quadratics), once for the
  // junction patches and both rounds of junction cues below. Each boundary
  // into its own slot, from here on on the pool's helper (while this thread
  // waits for the early blur and measures lines), and on this thread for
  // those left when the cues need them.
  struct Leaving {
    Vec2 near, wide, curved;
  };
  std::vector<Leaving> leave_start(nb), leave_end(nb);
  const double skip = std::max(1.5, out.line_width);
  auto leaving = [&](const Polyline& p) {
    return Leaving{leaving_direction(p, reach), leaving_direction(p, 3 * reach),
                   curved_leaving_direction(p, skip, reach)};
  };
  detail::ParallelLoop leaving_loop(&pool, nb, [&](int i) {
    const Boundary& b = bs[i];
    if (b.closed()) return;
    leave_start[i] = leaving(b.points);
    const Polyline back(b.points.rbegin(), b.points.rend());
    leave_end[i] = leaving(back);
    // From the first direction to the last one (arriving, -leave_end); on
    // the screen (y down) a positive cross product turns right.
    const Vec2 start = leave_start[i].near;
    const Vec2 arrive = -leave_end[i].near;
    const double cross = start.x() * arrive.y() - start.y() * arrive.x();
    out.boundaries[i].cues.turning = -std::atan2(cross, start.dot(arrive));
  });

  // --- Occluding boundaries: on a drawn line (§4.1). ---
  report(progress, "layering", 0.2, "line response");
  // Lines are measured only around the hair: the box of all non-background
  // boundaries, grown by the farthest sample and the smoothing kernels, so
  // that every measurement is the one on the whole image.
  int bx0 = image.width(), by0 = image.height(), bx1 = 0, by1 = 0;
  for (const Boundary& b : bs) {
    if (b.left == kOutsideLabel || b.right == kOutsideLabel) continue;
    for (const Vec2& p : b.points) {
      bx0 = std::min(bx0, static_cast<int>(p.x()));
      by0 = std::min(by0, static_cast<int>(p.y()));
      bx1 = std::max(bx1, static_cast<int>(p.x()));
      by1 = std::max(by1, static_cast<int>(p.y()));
    }
  }
  const int margin = detail::LineResponse::window_margin(out.line_width);
  lines.smooth(out.line_width, bx0 - margin, by0 - margin, bx1 + margin, by1 + margin, true);
  std::set<std::pair<int, int>> fixed_equal;
  for (const RegionRelation& r : options.fixed)
    if (r.relation == Relation::kEqual) fixed_equal.insert(key(r.a, r.b));
  // Lines along the boundaries are measured on all cores (parallel.h), and
  // the grey levels' noise (for the threshold) is the first item.
  std::vector<detail::BoundaryLine> measured(nb);
  detail::parallel_for(&pool, nb + 1, [&](int item) {
    if (item == 0) {
      lines.estimate_noise();
      return;
    }
    const int i = item - 1;
    const Boundary& b = bs[i];
    if (b.left == kOutsideLabel || b.right == kOutsideLabel) return;
    Polyline curve = b.points;
    if (b.closed()) curve.push_back(curve.front());
    measured[i] = lines.measure(curve, 1.5 * out.line_width, out.labels, b.left, b.right);
  });
  // The groups of regions that neighbour each other without a boundary of
  // their own, for the end (neighbours.h): on the pool's helper meanwhile.
  std::optional<detail::IslandGroups> islands;
  detail::BackgroundTask island_task(&pool, [&] {
    islands = detail::island_groups(graph, out.labels, 16.0 * out.line_width, 3.0 * out.line_width);
  });
  std::vector<std::pair<double, double>> weighted;  // (contrast, length)
  for (int i = 0; i < nb; ++i) {
    const Boundary& b = bs[i];
    BoundaryReport& rep = out.boundaries[i];
    rep.left = b.left;
    rep.right = b.right;
    rep.length = b.length();
    if (b.left == kOutsideLabel || b.right == kOutsideLabel) continue;
    const detail::BoundaryLine& line = measured[i];
    rep.line_contrast = line.contrast;
    rep.line_contrast_low = line.contrast_low;
    rep.colour_difference = line.colour_difference;
    weighted.emplace_back(rep.line_contrast, rep.length);
  }
  double noise_floor = 0.0;  // the automatic threshold's floor from the noise
  if (options.line_threshold > 0) {
    out.line_threshold = options.line_threshold;
  } else {
    // Most boundaries of a drawing are drawn lines: the contrast below which a
    // quarter of the boundary length lies is a robust "typical line".
    std::sort(weighted.begin(), weighted.end());
    double total = 0.0;
    for (const auto& [c, len] : weighted) total += len;
    double typical = 0.0, acc = 0.0;
    for (const auto& [c, len] : weighted) {
      acc += len;
      typical = c;
      if (acc >= 0.25 * total) break;
    }
    // The floor is over the noise of the grey levels the lines are measured
    // on (blurred at a quarter line width): 8 σ of them, which is 4 σ of the
    // raw pixels at lines up to 2.4 px (the blur's least σ, 0.6) and less at
    // wider ones, where the blur leaves less noise. A boundary with no line
    // under noise reads about 1–2 σ of the blurred levels (the paper and the
    // centre are extremes of noisy samples); a faint outline of 13–18 grey
    // levels under a hair painted dark, beside noise of σ 6, read under the
    // 4 σ of the raw pixels (17) at 4–5 px lines.
    noise_floor = 8.0 * lines.smoothed_noise_sigma();
    const double floor = std::max(6.0, noise_floor);
    out.line_threshold = std::max(floor, options.line_threshold_fraction * typical);
  }
  // A line the grey levels miss (a black outline on paint as dark as it) is
  // looked for in colour (colour_line.h) on the boundaries under the
  // threshold, those of at least 4 line widths (on shorter ones the
  // cross-sections reach the lines of the junctions).
  // On dark paint (both papers at grey level 64 or less, colour_line.h) the
  // threshold is per boundary and lower: no ink shows more in grey than the
  // paper's grey level, so between strands of black hair a plain outline
  // reads 4–6 grey levels, under the drawing's floor of 6 (a dark backdrop)
  // or far under a threshold set by a light backdrop's outlines (30 or
  // more). There it is 4, or two thirds of the noise floor if more.
  std::vector<double> threshold(nb, out.line_threshold);
  const double dark_threshold =
      std::min(out.line_threshold, std::max(4.0, 2.0 / 3.0 * noise_floor));
  for (int i = 0; i < nb; ++i) {
    const Boundary& b = bs[i];
    BoundaryReport& rep = out.boundaries[i];
    if (b.left == kOutsideLabel || b.right == kOutsideLabel) continue;
    if (rep.line_contrast >= out.line_threshold || rep.length < 4.0 * out.line_width) continue;
    Polyline curve = b.points;
    if (b.closed()) curve.push_back(curve.front());
    const detail::BoundaryLine seen = detail::colour_line(
        image, out.line_width, curve, 1.5 * out.line_width, out.labels, b.left, b.right);
    if (options.line_threshold <= 0 && seen.paper > 0.0 && seen.paper <= detail::kDarkPaper)
      threshold[i] = dark_threshold;
    if (seen.contrast >= threshold[i] && seen.contrast > rep.line_contrast) {
      rep.line_contrast = seen.contrast;
      rep.line_contrast_low = seen.contrast_low;
    }
  }
  for (int i = 0; i < nb; ++i) {
    const Boundary& b = bs[i];
    BoundaryReport& rep = out.boundaries[i];
    if (b.left == kOutsideLabel || b.right == kOutsideLabel) continue;
    rep.occluding =
        rep.line_contrast >= threshold[i] && !fixed_equal.contains(key(b.left, b.right));
  }

  // --- Junction angles, Φ_J, Φ_R, Φ (§4.2–4.4). ---
  report(progress, "layering", 0.4, "metrics");
  const int nj = static_cast<int>(graph.junctions.size());
  std::vector<std::vector<Ray>> rays(nj);
  std::vector<char> cusp(nj, 0);
  leaving_loop.finish();
  // --- Junction patches (an addition): the label map about both ends of
  // each occluding hair boundary, read by two small networks (patch_model.h):
  // one for the order, joined with 6b's log-odds below, one for same depth,
  // joined with 6c's after the cues. They need only the filled map and the
  // leaving directions: they are scored on the pool's helper from here on,
  // while this thread works out the cues (whose serial steps leave that core
  // idle otherwise), and here on the items the helper has not taken when the
  // scores are needed. ---
  const bool use_patches = options.metric == Metric::kLearned && options.junction_patches;
  auto patched = [&](int i) {
    const Boundary& b = bs[i];
    return out.boundaries[i].occluding && b.left > 0 && b.right > 0 && !b.closed();
  };
  struct PatchSums {
    double order = 0.0, same = 0.0;  // over both ends
  };
  std::vector<PatchSums> patch_sums(use_patches ? nb : 0);
  const detail::PatchNet& order_net = detail::patch_weights();
  const detail::SameDepthNet& same_net = detail::patch_same_weights();
  const double patch_size = detail::patch_radius(reach);
  // (The weights are fixed: which inputs they read is found once.)
  static const int order_weighed = detail::patch_inputs_used(order_net);
  static const int same_weighed = detail::patch_inputs_used(same_net.net);
  const int order_inputs = use_patches ? order_weighed : 0;
  const int inputs_used = use_patches ? std::max(order_weighed, same_weighed) : 0;
  // The drawing's grey levels, and the coarse scale, only for networks that
  // weigh them (networks that read the coarse scale read the grey channel).
  const bool read_grey = inputs_used > detail::kPatchLabelInputs;
  byte_task.finish();
  const detail::PatchImage patch_image{
      read_grey ? &image : nullptr, detail::patch_contrast(out.line_threshold), true,
      inputs_used > detail::kPatchCoarseStart, label_bytes.empty() ? nullptr : label_bytes.data()};
  detail::ParallelLoop patch_loop(&pool, use_patches ? nb : 0, [&](int i) {
    if (!patched(i)) return;
    const std::vector<detail::Patch> patches = detail::boundary_patches(
        out.labels, patch_image, graph, bs[i], leave_start[i].near, leave_end[i].near, patch_size);
    // Both ends scored at once (the networks' weights read once for both).
    std::array<detail::PatchScores, 2> scores;
    detail::patch_scores(order_net, order_inputs, same_net.net, patches.data(),
                         static_cast<int>(patches.size()), scores.data(), true, same_weighed);
    for (std::size_t e = 0; e < patches.size(); ++e) {
      patch_sums[i].order += scores[e].order;
      patch_sums[i].same += scores[e].same;
    }
  });
  for (int i = 0; i < nb; ++i) {
    const Boundary& b = bs[i];
    if (b.closed()) continue;
    rays[b.start].push_back({i, true, leave_start[i].near});
    rays[b.end].push_back({i, false, leave_end[i].near});
    const bool on_border = b.left == kOutsideLabel || b.right == kOutsideLabel;
    if (!on_border && !out.boundaries[i].occluding) cusp[b.start] = cusp[b.end] = 1;
  }
  // The circles of the label-map sectors (2.5 and 5 line widths, at least 4
  // and 8 px) as offsets from a junction, the same for every junction.
  std::vector<Vec2> circles[2];
  for (int wide = 0; wide < 2; ++wide) {
    const double radius = std::max(wide ? 8.0 : 4.0, (wide ? 5.0 : 2.5) * out.line_width);
    const int samples = std::max(32, static_cast<int>(std::ceil(2 * std::numbers::pi * radius)));
    for (int k = 0; k < samples; ++k) {
      const double t = 2 * std::numbers::pi * (k + 0.5) / samples;
      circles[wide].emplace_back(radius * std::cos(t), radius * std::sin(t));
    }
  }
  bool hair_junction = false;
  // Φ_J and the sectors at every junction that is not a cusp (run again
  // below when the same-depth model turns more junctions into cusps).
  // Junctions run on all cores: each end of a boundary has one junction, so
  // each writes only the angles of its own rays' ends, and Φ_J is summed
  // from the two ends afterwards.
  std::vector<char> hair_at(nj, 0);
  auto junction_cues = [&] {
    for (int i = 0; i < nb; ++i) {
      BoundaryReport& rep = out.boundaries[i];
      rep.cues.start = rep.cues.end = EndAngles{};
      rep.phi_j = rep.phi_j_start = rep.phi_j_end = 0.0;
    }
    const LabelMap& lab = out.labels;
    detail::parallel_for(&pool, nj, [&](int j) {
      const int n = static_cast<int>(rays[j].size());
      auto end_of = [&](const Ray& r) -> EndAngles& {
        return r.at_start ? out.boundaries[r.boundary].cues.start
                          : out.boundaries[r.boundary].cues.end;
      };
      std::vector<Vec2> dirs(n);
      for (int k = 0; k < n; ++k) dirs[k] = rays[j][k].direction;
      const RaySectors around = sectors_around(dirs);
      for (int k = 0; k < n; ++k) {
        const Ray& r = rays[j][around.order[k]];
        const Boundary& b = bs[r.boundary];
        if (b.left > 0 && b.right > 0) hair_at[j] = 1;
        const double after = around.sectors[k];
        const double before = around.sectors[(k + n - 1) % n];
        // Walking away from the start, `left` fills the sector before the ray;
        // walking away from the end the sides swap.
        const double alpha = r.at_start ? before : after;
        const double beta = r.at_start ? after : before;
        if (cusp[j]) continue;
        const double term = junction_metric(alpha, beta);
        BoundaryReport& rep = out.boundaries[r.boundary];
        end_of(r) = {true, alpha, beta, n};
        (r.at_start ? rep.phi_j_start : rep.phi_j_end) = term;
      }
      if (cusp[j]) return;
      // The sectors again from other leaving directions, into `left` /
      // `right` of each end's angles.
      auto sectors_from = [&](Vec2 Leaving::*kind, double EndAngles::*left,
                              double EndAngles::*right) {
        for (int k = 0; k < n; ++k) {
          const Ray& r = rays[j][k];
          dirs[k] = (r.at_start ? leave_start : leave_end)[r.boundary].*kind;
        }
        const RaySectors other = sectors_around(dirs);
        for (int k = 0; k < n; ++k) {
          const Ray& r = rays[j][other.order[k]];
          const double after = other.sectors[k];
          const double before = other.sectors[(k + n - 1) % n];
          EndAngles& e = end_of(r);
          e.*left = r.at_start ? before : after;
          e.*right = r.at_start ? after : before;
        }
      };
      // Seen from farther away (3 × the fit length): a tip stays narrow, a
      // wedge cut by rasterised lines opens up.
      sectors_from(&Leaving::wide, &EndAngles::wide_left, &EndAngles::wide_right);
      // From quadratics fitted near the junction (a bent outline's own
      // direction there), leaving out the blob where the lines merge.
      sectors_from(&Leaving::curved, &EndAngles::curved_left, &EndAngles::curved_right);
      // And off the label map: each region's share of a circle about the
      // junction.
      std::vector<std::pair<int, int>> count;  // (label, samples), a handful
      auto count_of = [&](int label) {
        for (const auto& [l, c] : count)
          if (l == label) return c;
        return 0;
      };
      const Vec2 centre = graph.junctions[j].position;
      std::vector<int> labels_on;  // the circle's labels, then counted
      for (int wide = 0; wide < 2; ++wide) {
        const std::vector<Vec2>& circle = circles[wide];
        const int samples = static_cast<int>(circle.size());
        // All the labels first: the loads (rows apart in the map, mostly
        // cache misses) overlap instead of each waiting for the counting of
        // the one before.
        labels_on.resize(circle.size());
        for (int k = 0; k < samples; ++k) {
          const int x = static_cast<int>(std::floor(centre.x() + circle[k].x()));
          const int y = static_cast<int>(std::floor(centre.y() + circle[k].y()));
          labels_on[k] = lab.contains(x, y) ? lab.at(x, y) : kOutsideLabel;
        }
        count.clear();
        for (const int label : labels_on) {
          auto it = std::find_if(count.begin(), count.end(),
                                 [&](const auto& p) { return p.first == label; });
          if (it == count.end())
            count.emplace_back(label, 1);
          else
            ++it->second;
        }
        for (const Ray& r : rays[j]) {
          const Boundary& b = bs[r.boundary];
          EndAngles& e = end_of(r);
          const double l = 2 * std::numbers::pi * count_of(b.left) / samples;
          const double rr = 2 * std::numbers::pi * count_of(b.right) / samples;
          (wide ? e.circle_wide_left : e.circle_left) = l;
          (wide ? e.circle_wide_right : e.circle_right) = rr;
        }
      }
    });
    // Φ_J over both ends (ends at a cusp add nothing).
    for (int i = 0; i < nb; ++i) {
      BoundaryReport& rep = out.boundaries[i];
      rep.phi_j = 0.0 + rep.phi_j_start + rep.phi_j_end;
    }
    hair_junction = std::find(hair_at.begin(), hair_at.end(), 1) != hair_at.end();
  };
  junction_cues();
  if (!hair_junction)
    throw Error("layering: no two hair regions meet at a junction (" + std::to_string(ids.size()) +
                " regions, " + std::to_string(nj) +
                " junctions); layering needs regions that meet where three or more do");
  // Φ_R, the features and the learned metric of each boundary on all cores,
  // each into its own report; the sums over regions in between on this one.
  auto unary_cues = [&] {
    detail::parallel_for(&pool, nb, [&](int i) {
      const Boundary& b = bs[i];
      BoundaryReport& rep = out.boundaries[i];
      Polyline curve = b.points;
      if (b.closed()) curve.push_back(curve.front());
      const double chord2 = (curve.back() - curve.front()).squaredNorm();
      // A boundary that nearly returns to where it started has no usable chord:
      // its own size, length/π, stands in (a circle then scores π/4).
      const double scale2 = std::max({chord2, std::pow(rep.length / std::numbers::pi, 2), 1.0});
      rep.phi_r = overlap_metric(curve) / scale2;
      rep.phi = options.junction_weight * rep.phi_j + rep.phi_r;
    });
    // Region areas (Green's theorem over each region's boundaries, walked with
    // the region on their left) and perimeters, for the learned metric.
    std::map<int, double> area, perimeter;
    std::map<std::pair<int, int>, double> common;  // length shared by two regions
    for (int i = 0; i < nb; ++i) {
      const Polyline& p = bs[i].points;
      double twice = 0.0;
      for (std::size_t k = 0; k + 1 < p.size(); ++k)
        twice += p[k].x() * p[k + 1].y() - p[k + 1].x() * p[k].y();
      if (bs[i].closed() && p.size() > 1)
        twice += p.back().x() * p.front().y() - p.front().x() * p.back().y();
      area[bs[i].left] += 0.5 * twice;
      area[bs[i].right] -= 0.5 * twice;
      perimeter[bs[i].left] += out.boundaries[i].length;
      perimeter[bs[i].right] += out.boundaries[i].length;
      if (bs[i].left != bs[i].right)
        common[key(bs[i].left, bs[i].right)] += out.boundaries[i].length;
    }
    for (int i = 0; i < nb; ++i) {
      BoundaryReport& rep = out.boundaries[i];
      rep.cues.phi_r = rep.phi_r;
      rep.cues.area_left = std::abs(area[bs[i].left]);
      rep.cues.area_right = std::abs(area[bs[i].right]);
      rep.cues.perimeter_left = perimeter[bs[i].left];
      rep.cues.perimeter_right = perimeter[bs[i].right];
      const double shared = common[key(bs[i].left, bs[i].right)];
      rep.cues.shared_left = perimeter[bs[i].left] > 0 ? shared / perimeter[bs[i].left] : 0.0;
      rep.cues.shared_right = perimeter[bs[i].right] > 0 ? shared / perimeter[bs[i].right] : 0.0;
    }
    detail::parallel_for(&pool, nb, [&](int i) {
      BoundaryReport& rep = out.boundaries[i];
      rep.features = boundary_features(rep.cues);
      rep.learned = learned_metric(rep.features);
    });
  };
  unary_cues();
  // The same-depth model, with the drawing's typical colour step across its
  // hair boundaries as the yardstick of "same paint".
  std::vector<double> steps;
  for (int i = 0; i < nb; ++i)
    if (bs[i].left > 0 && bs[i].right > 0 && out.boundaries[i].occluding)
      steps.push_back(out.boundaries[i].colour_difference);
  double typical_step = 0.0;
  if (!steps.empty()) {
    auto mid = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
    std::nth_element(steps.begin(), mid, steps.end());
    typical_step = *mid;
  }
  detail::parallel_for(&pool, nb, [&](int i) {
    BoundaryReport& rep = out.boundaries[i];
    EqualCues& e = rep.equal_cues;
    e.length_widths = rep.length / out.line_width;
    e.contrast_ratio = rep.line_contrast / threshold[i];
    e.contrast_low_ratio = rep.line_contrast_low / threshold[i];
    e.colour_difference = rep.colour_difference;
    e.typical_colour_difference = typical_step;
    e.order_log_odds = rep.learned;
    e.area_left = rep.cues.area_left;
    e.area_right = rep.cues.area_right;
    e.start = rep.cues.start;
    e.end = rep.cues.end;
    e.shared_left = rep.cues.shared_left;
    e.shared_right = rep.cues.shared_right;
    rep.equal_features = equal_features(e);
    rep.equal = equal_metric(rep.equal_features);
  });
  // The junction patches' scores (started above), the same-depth one joined
  // with 6c's log-odds.
  patch_loop.finish();
  if (use_patches) {
    for (int i = 0; i < nb; ++i) {
      if (!patched(i)) continue;
      BoundaryReport& rep = out.boundaries[i];
      rep.patch = patch_sums[i].order;
      rep.patch_equal = patch_sums[i].same;
      rep.equal = same_net.intercept + same_net.net.order_weight * rep.equal +
                  same_net.net.patch_weight * rep.patch_equal;
    }
  }
  // A drawn line between two halves of one strand ends on the strand's
  // outline in what looks like a T-junction, but nothing is occluded there:
  // like the ends of a non-occluding boundary (§4.1), the junctions of a
  // same-depth boundary are cusps, and the cues are measured again.
  if (options.learned_equal && options.metric == Metric::kLearned) {
    std::vector<int> new_cusps;
    for (int i = 0; i < nb; ++i) {
      const Boundary& b = bs[i];
      if (b.closed() || b.left <= 0 || b.right <= 0) continue;
      if (!out.boundaries[i].occluding || out.boundaries[i].equal <= 0) continue;
      for (int j : {b.start, b.end})
        if (!cusp[j]) cusp[j] = 1, new_cusps.push_back(j);
    }
    // junction_cues() and unary_cues() again, where they change: each end of
    // a boundary belongs to one junction, and at a cusp junction_cues()
    // leaves its ends as reset; every other end, and the unary cues of a
    // boundary with no end at a new cusp, would come out as they are.
    std::vector<char> again(nb, 0);
    for (int j : new_cusps)
      for (const Ray& r : rays[j]) {
        BoundaryReport& rep = out.boundaries[r.boundary];
        (r.at_start ? rep.cues.start : rep.cues.end) = EndAngles{};
        (r.at_start ? rep.phi_j_start : rep.phi_j_end) = 0.0;
        again[r.boundary] = 1;
      }
    for (int i = 0; i < nb; ++i) {
      if (!again[i]) continue;
      BoundaryReport& rep = out.boundaries[i];
      rep.phi_j = 0.0 + rep.phi_j_start + rep.phi_j_end;
      rep.phi = options.junction_weight * rep.phi_j + rep.phi_r;
      rep.features = boundary_features(rep.cues);
      rep.learned = learned_metric(rep.features);
    }
  }

  // The order network's score joins the order model's final log-odds.
  if (use_patches) {
    const detail::PatchNet& net = detail::patch_weights();
    for (int i = 0; i < nb; ++i) {
      BoundaryReport& rep = out.boundaries[i];
      rep.patch_log_odds =
          patched(i) ? net.order_weight * rep.learned + net.patch_weight * rep.patch : rep.learned;
    }
  }

  // --- Region context (an addition): each boundary's log-odds weighed with
  // how its two regions stand against their other neighbours. ---
  const bool use_context = options.metric == Metric::kLearned && options.region_context;
  if (use_context) {
    std::vector<ContextBoundary> context(nb);
    for (int i = 0; i < nb; ++i) {
      const BoundaryReport& rep = out.boundaries[i];
      const bool same = options.learned_equal && rep.equal > 0;
      context[i] = {bs[i].left, bs[i].right, rep.length, rep.learned, rep.occluding && !same};
    }
    const std::vector<double> diff = context_differences(context);
    for (int i = 0; i < nb; ++i) {
      BoundaryReport& rep = out.boundaries[i];
      rep.context = diff[i];
      rep.context_log_odds = context_metric(rep.learned, diff[i]);
    }
  }

  // --- Eq. (2): boundary states by one minimum cut (§4.5). ---
  report(progress, "layering", 0.6, "optimisation");
  std::map<std::pair<int, int>, Relation> fixed_dir;  // (a<b) → relation of a to b
  for (const RegionRelation& r : options.fixed)
    if (r.relation != Relation::kEqual)
      fixed_dir[key(r.a, r.b)] = r.a < r.b ? r.relation : reversed(r.relation);
  std::vector<int> state_of(nb, -1);
  StateProblem problem;
  std::vector<int> boundary_of;
  for (int i = 0; i < nb; ++i) {
    const Boundary& b = bs[i];
    const BoundaryReport& rep = out.boundaries[i];
    if (!rep.occluding || b.left == kOutsideLabel || b.right == kOutsideLabel) continue;
    if (!options.background_states && (b.left == 0 || b.right == 0)) continue;
    double unary = options.metric == Metric::kLearned
                       ? options.learned_scale * (use_context   ? rep.context_log_odds
                                                  : use_patches ? rep.patch_log_odds
                                                                : rep.learned)
                       : rep.phi;
    auto f = fixed_dir.find(key(b.left, b.right));
    if (f != fixed_dir.end()) {
      const bool left_above = (f->second == Relation::kAbove) == (b.left < b.right);
      unary = left_above ? kClamp : -kClamp;
    }
    state_of[i] = static_cast<int>(problem.unary.size());
    problem.unary.push_back(unary);
    boundary_of.push_back(i);
  }
  for (int j = 0; j < nj; ++j) {
    const auto& rs = rays[j];
    struct Candidate {
      int bi, bj;
      double theta;
      bool same;
    };
    std::vector<Candidate> cands;
    for (std::size_t p = 0; p < rs.size(); ++p) {
      for (std::size_t q = p + 1; q < rs.size(); ++q) {
        const int bi = rs[p].boundary, bj = rs[q].boundary;
        if (bi == bj || state_of[bi] < 0 || state_of[bj] < 0) continue;
        const Boundary& u = bs[bi];
        const Boundary& v = bs[bj];
        // The region the two boundaries share; "agree" means it lies on the
        // same side (above or below) of both.
        int shared = 0, count = 0;
        for (int l : {u.left, u.right})
          if (l == v.left || l == v.right) shared = l, ++count;
        if (count != 1) continue;
        const double theta = std::acos(std::clamp(rs[p].direction.dot(rs[q].direction), -1.0, 1.0));
        const bool same = (shared == u.left) == (shared == v.left);
        cands.push_back({bi, bj, theta, same});
      }
    }
    if (options.coupling == Coupling::kNone) cands.clear();
    if (options.coupling == Coupling::kSmoothestPair && !cands.empty()) {
      // Three boundaries at a junction pairwise share a region, so their three
      // couplings can never all be satisfied, and with measured (noisy)
      // angles the non-smooth pairs weigh as much as the metric itself. The
      // pair Fig. 10 is about — the one continuing smoothly — is kept alone.
      const Candidate best = *std::max_element(
          cands.begin(), cands.end(),
          [](const Candidate& a, const Candidate& b) { return a.theta < b.theta; });
      cands.clear();
      if (best.theta >= options.smooth_angle) cands.push_back(best);
    }
    for (const Candidate& c : cands) {
      const double weight = coupling_weight(c.theta, options.coupling_cap);
      if (weight <= 0) continue;
      problem.couplings.push_back({state_of[c.bi], state_of[c.bj], weight, c.same});
    }
  }
  const StateSolution solution = solve_states(problem);

  out.states = static_cast<int>(problem.unary.size());
  out.dropped_couplings = solution.dropped_couplings;
  // How much each state is held by the energy: half the cost of flipping it.
  std::vector<double> support(problem.unary.size());
  for (std::size_t s = 0; s < problem.unary.size(); ++s)
    support[s] = problem.unary[s] * solution.x[s];
  for (const StateCoupling& c : problem.couplings) {
    const double e = c.weight * (c.same ? 1.0 : -1.0) * solution.x[c.i] * solution.x[c.j];
    support[c.i] += e;
    support[c.j] += e;
  }
  for (std::size_t s = 0; s < boundary_of.size(); ++s)
    out.boundaries[boundary_of[s]].state = solution.x[s];

  // --- Relations per pair of hair regions. ---
  report(progress, "layering", 0.8, "relations");
  struct PairAccumulator {
    double total = 0, occluding = 0, score = 0, same = 0;
    // Over the open (non-occluding) boundaries: length, length-weighted
    // same-depth log-odds and order log-odds (toward the smaller id above).
    double open = 0, open_same = 0, open_order = 0;
    int longest = -1;
  };
  std::map<std::pair<int, int>, PairAccumulator> pairs;
  for (int i = 0; i < nb; ++i) {
    const Boundary& b = bs[i];
    if (b.left <= 0 || b.right <= 0) continue;
    PairAccumulator& acc = pairs[key(b.left, b.right)];
    const BoundaryReport& rep = out.boundaries[i];
    acc.total += rep.length;
    if (acc.longest < 0 || rep.length > bs[acc.longest].length()) acc.longest = i;
    if (!rep.occluding) {
      acc.open += rep.length;
      acc.open_same += rep.equal * rep.length;
      acc.open_order += (b.left < b.right ? 1 : -1) * rep.learned * rep.length;
    }
    if (state_of[i] < 0) continue;
    acc.occluding += rep.length;
    acc.same += rep.equal * rep.length;
    // Oriented to the smaller id: x = +1 means the left region is above.
    const int toward_a = (b.left < b.right ? 1 : -1) * solution.x[state_of[i]];
    acc.score += toward_a * (std::max(support[state_of[i]], 0.0) + 1e-3) * rep.length;
  }
  auto anchor_of = [&](int boundary, int a) {
    const Boundary& b = bs[boundary];
    const Polyline& pts = b.points;
    const std::size_t m = pts.size() / 2;
    const Vec2 t = pts[std::min(pts.size() - 1, m + 2)] - pts[m >= 2 ? m - 2 : 0];
    // On the screen the left of travel t is (t.y, −t.x).
    Vec2 left_normal = Vec2(t.y(), -t.x());
    if (left_normal.squaredNorm() == 0) left_normal = Vec2(1, 0);
    left_normal.normalize();
    return RelationAnchor{pts[m], b.left == a ? Vec2(-left_normal) : left_normal};
  };
  // Same-depth pairs the joined model (6c with the patch network) is sure
  // of: mean log-odds over kFirmEqualLogOdds (core/firm_equal.h). They go before the orders
  // (depth_order.h), which otherwise override an "equal" between regions
  // ordered through others.
  std::vector<char> firm;
  // The same-depth model (6c) speaks only with the learned metric.
  const bool learned_same = options.learned_equal && options.metric == Metric::kLearned;
  for (const auto& [k, acc] : pairs) {
    RegionRelation r;
    r.a = k.first;
    r.b = k.second;
    const bool same_depth =
        learned_same && acc.occluding > 0 && acc.same > options.equal_log_odds * acc.occluding;
    const bool open_pair = acc.occluding < options.equal_fraction * acc.total || acc.occluding == 0;
    // An open pair the same-depth model calls two depths (open_order_log_odds).
    const bool open_ordered = open_pair && !same_depth && learned_same && acc.open > 0 &&
                              acc.open_same < options.open_order_log_odds * acc.open;
    if (open_ordered) {
      firm.push_back(0);
      r.score = options.learned_scale * acc.open_order / acc.open;
      r.relation = relation_of_sign(r.score);
    } else if (open_pair || same_depth) {
      r.relation = Relation::kEqual;
      r.score = 0.0;
      // Its confidence, for completion to weigh (EqualEvidence): the
      // log-odds of the boundaries that made it equal.
      EqualEvidence e;
      e.open = !same_depth;
      e.log_odds = same_depth     ? acc.same / acc.occluding
                   : acc.open > 0 ? acc.open_same / acc.open
                                  : 0.0;
      e.open_fraction = acc.total > 0 ? acc.open / acc.total : 0.0;
      r.equal_evidence = e;
      firm.push_back(same_depth && use_patches && acc.same > kFirmEqualLogOdds * acc.occluding);
    } else {
      firm.push_back(0);
      r.score = acc.score / acc.occluding;
      r.relation = relation_of_sign(r.score);
    }
    out.relations.push_back(r);
    out.anchors.push_back(anchor_of(acc.longest, r.a));
  }
  for (const RegionRelation& f : options.fixed) {
    const auto k = key(f.a, f.b);
    const Relation rel = f.a < f.b ? f.relation : reversed(f.relation);
    auto it =
        std::find_if(out.relations.begin(), out.relations.end(),
                     [&](const RegionRelation& r) { return r.a == k.first && r.b == k.second; });
    if (it == out.relations.end()) {
      out.relations.push_back({k.first, k.second, rel, 0.0, true, false});
      firm.push_back(0);
      out.anchors.push_back({});
      continue;
    }
    it->relation = rel;
    it->user_fixed = true;
    it->equal_evidence.reset();  // the user's word, not the measure
  }

  DepthOrder order = order_regions(ids, out.relations, firm);
  out.relations = std::move(order.relations);
  out.depth = std::move(order.depth);
  out.overridden = std::move(order.overridden);
  island_task.finish();
  detail::add_island_neighbours(*islands, out);
  std::ostringstream s;
  s << out.states << " boundary states, " << problem.couplings.size() << " couplings, "
    << (solution.exact() ? "exact minimum cut"
                         : "minimum cut without " + std::to_string(solution.dropped_couplings) +
                               " frustrated couplings")
    << "; " << out.relations.size() << " relations, " << out.overridden.size()
    << " overridden to break cycles";
  out.summary = s.str();
  report(progress, "layering", 1.0, "done");
  return out;
}

}  // namespace hair25d::layering
