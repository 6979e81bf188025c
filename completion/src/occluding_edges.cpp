#include <algorithm>
#include <cmath>
#include <map>
#include <opencv2/imgproc.hpp>
#include <set>

#include "context.h"
#include "raster.h"

namespace hair25d::completion::detail {
namespace {

// Ink edges (find_ink_edges): the ink between two pieces, from the nearest
// pixel of one to the nearest of the other (px), at least this much; each
// searched for within kInkSearch px of the outline.
constexpr double kMinInkGap = 5.0;
constexpr int kInkSearch = 8;
// How far straight out of the outline (outline-assigned labels) another
// piece is looked for across ink (the drawing's own labels): a crossing
// tip's ink is assigned to the tip's own region, not to the pieces.
constexpr int kInkReach = 16;
// An edge whose two end tangents part by more than this is bent (an arm
// round a tip or corner: docs/completion-record.md, session 22).
constexpr double kBentEndsDeg = 45.0;

// Each labelled point of a closed contour takes the label most of its five
// neighbours (itself and two either side) carry, so that one stray pixel at a
// junction does not split a run; unlabelled points stay 0.
std::vector<int> majority_labels(const std::vector<int>& raw) {
  const int n = static_cast<int>(raw.size());
  std::vector<int> out = raw;
  for (int i = 0; i < n; ++i) {
    if (raw[i] == 0) continue;
    std::map<int, int> votes;
    for (int k = -2; k <= 2; ++k)
      if (raw[wrap(i + k, n)] != 0) ++votes[raw[wrap(i + k, n)]];
    int best = raw[i], most = 0;
    for (auto [l, v] : votes)
      if (v > most) most = v, best = l;
    out[i] = best;
  }
  return out;
}

// Per contour point: the nearest occluder within reach, 0 if none, with a
// majority filter so junction pixels do not split runs.
std::vector<int> occluder_labels(const Context& ctx, const RegionInfo& region) {
  const auto& c = region.contour;
  const int n = static_cast<int>(c.size());
  const int reach = ctx.options->occluder_reach;
  std::vector<int> raw(n, 0);
  for (int i = 0; i < n; ++i) {
    int best = 0, best_d = 1 << 30;
    for (int dy = -reach; dy <= reach; ++dy)
      for (int dx = -reach; dx <= reach; ++dx) {
        const int l = ctx.label(c[i].x + dx, c[i].y + dy);
        if (l == 0 || !region.occluders.count(l)) continue;
        const int d = dx * dx + dy * dy;
        if (d < best_d) best_d = d, best = l;
      }
    raw[i] = best;
  }
  return majority_labels(raw);
}

// Builds an edge over contour indices begin..end (unwrapped, end >= begin).
Edge make_edge(const Context& ctx, const RegionInfo& region, const std::vector<int>& labels,
               int begin, int end) {
  const Options& o = *ctx.options;
  const auto& c = region.contour;
  const int n = static_cast<int>(c.size());
  auto at = [&](int i) { return centre(c[wrap(i, n)]); };
  Edge e;
  e.region = region.id;
  e.begin = wrap(begin, n);
  e.end = e.begin + (end - begin);
  for (int i = begin; i <= end; ++i) {
    e.points.push_back(at(i));
    if (labels[wrap(i, n)] != 0) e.occluders.insert(labels[wrap(i, n)]);
  }
  e.p = e.points.front();
  e.q = e.points.back();
  e.width = (e.p - e.q).norm();
  const int fit = static_cast<int>(std::round(o.fit_length));
  const int room = n - (end - begin + 1);
  int free_before = 0, free_after = 0;
  while (free_before < std::min(fit, room) && labels[wrap(begin - 1 - free_before, n)] == 0)
    ++free_before;
  while (free_after < std::min(fit, room) && labels[wrap(end + 1 + free_after, n)] == 0)
    ++free_after;
  // The last pixels before an end bend into the occluder's drawn line: the
  // fields are fitted to the outline a little away from it.
  const int skip_p = std::min(3, free_before / 3), skip_q = std::min(3, free_after / 3);
  for (int i = begin - free_before; i <= begin - skip_p; ++i) e.piece_p.push_back(at(i));
  for (int i = end + free_after; i >= end + skip_q; --i) e.piece_q.push_back(at(i));
  // Without visible outline beside an end, the strand is taken to continue
  // straight out of the region, across the chord p q.
  Vec2 out(-(e.q - e.p).y(), (e.q - e.p).x());
  if (out.norm() > 0) out.normalize();
  if (out.dot(region.centroid - 0.5 * (e.p + e.q)) > 0) out = -out;
  // Tangents by a line fit to the visible outline a little away from the
  // end: the last pixels bend into the occluder's drawn line.
  const int arm = static_cast<int>(std::round(o.tangent_arm));
  auto fit_direction = [&](int from, int step, int free, Vec2* dir) {
    const int skip = std::min(3, free / 3), last = std::min(arm + skip, free);
    if (last - skip < 4) return false;
    Polyline piece;
    for (int k = skip; k <= last; ++k) piece.push_back(at(from - step * k));
    // Oriented towards the end, i.e. into the hidden part.
    *dir = principal_axis(piece, at(from) - at(from - step * last));
    return true;
  };
  const bool has_p = fit_direction(begin, 1, free_before, &e.tangent_p);
  const bool has_q = fit_direction(end, -1, free_after, &e.tangent_q);
  e.arm_p = free_before;
  e.arm_q = free_after;
  if (has_p && has_q) e.ends_part = std::acos(std::clamp(e.tangent_p.dot(e.tangent_q), -1.0, 1.0));
  // Without visible outline beside an end, the band is taken to continue
  // parallel to its other side, or straight out across the chord.
  // A sliver wholly under occluders has nothing better; a piece with visible
  // outline elsewhere whose edge runs between two other occluders is a wide
  // piece's side under a strand, not a cut across a strand.
  const bool enclosed = std::find(labels.begin(), labels.end(), 0) == labels.end();
  e.guessed = !has_p && !has_q && !enclosed;
  if (!has_p) e.tangent_p = has_q ? e.tangent_q : out;
  if (!has_q) e.tangent_q = has_p ? e.tangent_p : out;
  // Session 31: the end tangents are unreliable when an end has no arm or
  // the two ends' own fits part by over kBentEndsDeg (an arm round a tip or
  // a small piece's corner; a band's two sides run roughly parallel). The
  // strand's direction is then read from both sides at once: the midpoint
  // of the two runs leaving p and q, k px of outline from each end, traces
  // the piece's middle line, which a corner on one side bends only half as
  // much and which needs no arm of its own at either end.
  e.unreliable = !e.guessed && (!has_p || !has_q ||
                                e.tangent_p.dot(e.tangent_q) < std::cos(kBentEndsDeg * M_PI / 180));
  if (e.unreliable) {
    const int common = std::min(free_before, free_after);
    const int skip = std::min(3, common / 3), last = std::min(arm + skip, common);
    if (last - skip >= 2) {
      Polyline middle;
      for (int k = skip; k <= last; ++k) middle.push_back(0.5 * (at(begin - k) + at(end + k)));
      const Vec2 into = middle.front() - middle.back();
      if (into.norm() > 1.0) e.side_tangent = principal_axis(middle, into);
    } else if (free_before + free_after >= 4) {
      // One run too short to pair: the middle of the two runs' far ends
      // (all the visible outline each has, up to fit_length) to the cut's.
      const Vec2 into = 0.5 * (e.p + e.q) - 0.5 * (at(begin - free_before) + at(end + free_after));
      if (into.norm() > 1.0) e.side_tangent = into.normalized();
    }
  }
  // Both sides of a band run into the hidden part the same way; opposite
  // tangents mean the shorter visible run turned a corner: trust the longer.
  // (The dropped one is kept: a sliver whose long side lies under a strand
  // running along it may continue either way, session 32.)
  if (e.tangent_p.dot(e.tangent_q) < -0.3) {
    if (free_before >= free_after) {
      e.turned_tangent = e.tangent_q;
      e.tangent_q = e.tangent_p;
    } else {
      e.turned_tangent = e.tangent_p;
      e.tangent_p = e.tangent_q;
    }
  }
  // The region's colour next to the edge (drawn pixels only, not outlines).
  Eigen::Vector3d sum(0, 0, 0);
  double squares = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < e.points.size(); i += 2) {
    const int cx = static_cast<int>(e.points[i].x()), cy = static_cast<int>(e.points[i].y());
    for (int dy = -5; dy <= 5; ++dy)
      for (int dx = -5; dx <= 5; ++dx) {
        const int x = cx + dx, y = cy + dy;
        if (!ctx.original->contains(x, y) || ctx.original->at(x, y) != region.id) continue;
        const Rgba& px = ctx.image->at(x, y);
        const Eigen::Vector3d v(px.r, px.g, px.b);
        sum += v;
        squares += v.squaredNorm();
        ++count;
      }
  }
  e.colour = count > 0 ? Eigen::Vector3d(sum / count) : region.colour;
  e.colour_spread =
      count > 0 ? std::sqrt(std::max(0.0, squares / count - e.colour.squaredNorm())) : 0.0;
  return e;
}

}  // namespace

void describe_regions(Context& ctx) {
  const LabelMap& L = ctx.labels;
  struct Acc {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1, n = 0;
    double sx = 0, sy = 0;
    Eigen::Vector3d colour{0, 0, 0};
    int coloured = 0;
  };
  std::map<int, Acc> acc;
  Acc* run = nullptr;  // a run of one label looks its entry up once
  int run_label = 0;
  for (int y = 0; y < L.height(); ++y)
    for (int x = 0; x < L.width(); ++x) {
      const int l = L.at(x, y);
      if (l == 0) continue;
      if (run == nullptr || l != run_label) run = &acc[l], run_label = l;
      Acc& a = *run;
      a.x0 = std::min(a.x0, x), a.y0 = std::min(a.y0, y);
      a.x1 = std::max(a.x1, x), a.y1 = std::max(a.y1, y);
      ++a.n;
      a.sx += x + 0.5, a.sy += y + 0.5;
      if (ctx.original->at(x, y) == l) {
        const Rgba& c = ctx.image->at(x, y);
        a.colour += Eigen::Vector3d(c.r, c.g, c.b);
        ++a.coloured;
      }
    }
  for (auto& [id, a] : acc) {
    RegionInfo& r = ctx.regions[id];
    r.id = id;
    r.box = cv::Rect(a.x0, a.y0, a.x1 - a.x0 + 1, a.y1 - a.y0 + 1);
    r.pixels = a.n;
    r.centroid = Vec2(a.sx / a.n, a.sy / a.n);
    r.colour = a.coloured > 0 ? Eigen::Vector3d(a.colour / a.coloured) : Eigen::Vector3d(0, 0, 0);
    const cv::Rect padded(r.box.x - 1, r.box.y - 1, r.box.width + 2, r.box.height + 2);
    cv::Mat mask(padded.height, padded.width, CV_8U, cv::Scalar(0));
    for (int y = r.box.y; y < r.box.y + r.box.height; ++y)
      for (int x = r.box.x; x < r.box.x + r.box.width; ++x)
        if (L.at(x, y) == id) mask.at<std::uint8_t>(y - padded.y, x - padded.x) = 255;
    const auto contours = outer_contours(mask);
    r.contour.clear();
    if (!contours.empty())
      for (const cv::Point& p : contours.front()) r.contour.push_back(p + padded.tl());
  }
}

std::vector<Edge> find_edges(const Context& ctx, const RegionInfo& region, int first_id) {
  std::vector<Edge> edges;
  const Options& o = *ctx.options;
  const int n = static_cast<int>(region.contour.size());
  if (region.occluders.empty() || n < 8) return edges;
  const std::vector<int> labels = occluder_labels(ctx, region);
  int start = -1;
  for (int i = 0; i < n && start < 0; ++i)
    if (labels[i] == 0) start = i;
  // A piece wholly surrounded by occluders (a sliver between strands) still
  // has one edge per occluder, split where the occluder changes; with no
  // visible outline its tangents are taken across its cut chords.
  bool enclosed = false;
  if (start < 0) {
    for (int i = 0; i < n && start < 0; ++i)
      if (labels[i] != labels[wrap(i - 1, n)]) start = i;
    if (start < 0) return edges;  // under one occluder all round
    enclosed = true;
  }

  struct Run {
    int begin, end, label;
  };
  std::vector<Run> runs;
  for (int k = enclosed ? 0 : 1; k < n; ++k) {
    const int i = start + k, l = labels[wrap(i, n)];
    if (l == 0) continue;
    if (!runs.empty() && runs.back().end == i - 1 && runs.back().label == l)
      runs.back().end = i;
    else
      runs.push_back({i, i, l});
  }
  // Runs under one occluder with a short visible gap between them are one
  // edge (the gap is an outline wiggle, not the strand showing).
  const int gap = static_cast<int>(std::ceil(o.merge_gap));
  std::vector<Run> merged;
  for (const Run& r : runs) {
    if (!merged.empty() && merged.back().label == r.label && r.begin - merged.back().end - 1 <= gap)
      merged.back().end = r.end;
    else
      merged.push_back(r);
  }
  const int min_len = static_cast<int>(std::ceil(o.min_edge_length));
  for (const Run& r : merged) {
    if (r.end - r.begin + 1 < min_len) continue;
    Edge e = make_edge(ctx, region, labels, r.begin, r.end);
    e.atoms = {first_id + static_cast<int>(edges.size())};
    edges.push_back(std::move(e));
  }
  return edges;
}

std::vector<Edge> find_ink_edges(const Context& ctx, const RegionInfo& region, int first_id) {
  std::vector<Edge> edges;
  const auto& c = region.contour;
  const int n = static_cast<int>(c.size());
  if (n < 8) return edges;
  const std::vector<int> occluded = occluder_labels(ctx, region);
  // The nearest pixel of `label` in the drawing's own labels (outlines 0)
  // within kInkSearch of (x, y); a large value when none.
  auto nearest = [&](int x, int y, int label) {
    int best = 1 << 30;
    for (int dy = -kInkSearch; dy <= kInkSearch; ++dy)
      for (int dx = -kInkSearch; dx <= kInkSearch; ++dx)
        if (ctx.original->contains(x + dx, y + dy) && ctx.original->at(x + dx, y + dy) == label)
          best = std::min(best, dx * dx + dy * dy);
    return std::sqrt(static_cast<double>(best));
  };
  std::vector<int> raw(n, 0);
  bool any = false;
  for (int i = 0; i < n; ++i) {
    if (occluded[i] != 0) continue;
    // The region met first straight out of the outline (its normal, away
    // from the region) in the drawing's own labels, across ink (0) and the
    // region's own pixels only.
    const Vec2 t = centre(c[wrap(i + 3, n)]) - centre(c[wrap(i - 3, n)]);
    if (t.norm() <= 0) continue;
    Vec2 normal(-t.y(), t.x());
    normal.normalize();
    const Vec2 from = centre(c[i]);
    if (ctx.label(from + 2.0 * normal) == region.id && ctx.label(from - 2.0 * normal) != region.id)
      normal = -normal;
    int best = 0;
    for (double s = 1.0; s <= kInkReach; s += 0.5) {
      const Vec2 at = from + s * normal;
      const int x = static_cast<int>(std::floor(at.x())), y = static_cast<int>(std::floor(at.y()));
      if (!ctx.original->contains(x, y)) break;
      const int l = ctx.original->at(x, y);
      if (l == 0 || l == region.id) continue;
      if (ctx.regions.count(l) && !ctx.is_above(l, region.id) && !ctx.is_above(region.id, l))
        best = l;
      break;
    }
    if (best == 0) continue;
    if (nearest(c[i].x, c[i].y, region.id) + nearest(c[i].x, c[i].y, best) < kMinInkGap) continue;
    raw[i] = best;
    any = true;
  }
  if (!any) return edges;
  const std::vector<int> ink = majority_labels(raw);
  // The outline beside an ink run is visible where neither an occluder nor
  // ink faces it (make_edge fits the tangents there).
  std::vector<int> labels(n, 0);
  for (int i = 0; i < n; ++i) labels[i] = occluded[i] != 0 ? occluded[i] : -ink[i];
  // (Negative: facing a region across ink; make_edge counts them occluders,
  // taken out again below.)
  int start = -1;
  for (int i = 0; i < n && start < 0; ++i)
    if (labels[i] == 0) start = i;
  if (start < 0) return edges;
  struct Run {
    int begin, end, label;
  };
  std::vector<Run> runs;
  for (int k = 1; k < n; ++k) {
    const int i = start + k, l = ink[wrap(i, n)];
    if (l == 0 || occluded[wrap(i, n)] != 0) continue;
    if (!runs.empty() && runs.back().end == i - 1 && runs.back().label == l)
      runs.back().end = i;
    else
      runs.push_back({i, i, l});
  }
  const int min_len = static_cast<int>(std::ceil(ctx.options->min_edge_length));
  std::vector<int> run_atom(runs.size(), -1);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const Run& r = runs[k];
    if (r.end - r.begin + 1 < min_len) continue;
    Edge e = make_edge(ctx, region, labels, r.begin, r.end);
    e.occluders.clear();
    e.ink = {r.label};
    run_atom[k] = first_id + static_cast<int>(edges.size());
    e.atoms = {run_atom[k]};
    edges.push_back(std::move(e));
  }
  // A cut faces the other piece only in part (the crossing tip's own region
  // or an occluder faces the rest): the whole run of hidden outline round
  // each ink run, occluded or inked, visible gaps of at most merge_gap
  // bridged, as one more candidate.
  const int gap = static_cast<int>(std::ceil(ctx.options->merge_gap));
  int next = first_id + static_cast<int>(edges.size());
  std::vector<Edge> spans;
  for (int k = 1; k < n;) {
    const int i = start + k;
    if (labels[wrap(i, n)] == 0) {
      ++k;
      continue;
    }
    int end = i, visible = 0;
    for (int m = i + 1; m < start + n; ++m) {
      if (labels[wrap(m, n)] != 0) {
        end = m;
        visible = 0;
      } else if (++visible > gap) {
        break;
      }
    }
    k = end - start + 1;
    std::set<int> faced;
    std::vector<int> inner;
    for (std::size_t r = 0; r < runs.size(); ++r)
      if (runs[r].begin >= i && runs[r].end <= end) {
        faced.insert(runs[r].label);
        if (run_atom[r] >= 0) inner.push_back(run_atom[r]);
      }
    const bool single = inner.size() == 1 && faced.size() == 1 &&
                        std::any_of(runs.begin(), runs.end(),
                                    [&](const Run& r) { return r.begin == i && r.end == end; });
    if (faced.empty() || single || end - i + 1 < min_len || end - i + 1 >= n - 2) continue;
    Edge e = make_edge(ctx, region, labels, i, end);
    std::erase_if(e.occluders, [](int l) { return l <= 0; });
    e.ink = faced;
    e.atoms = inner;
    e.atoms.push_back(next++);
    spans.push_back(std::move(e));
  }
  for (Edge& e : spans) edges.push_back(std::move(e));
  return edges;
}

std::vector<Edge> merge_edges(const Context& ctx, const RegionInfo& region,
                              const std::vector<Edge>& edges) {
  std::vector<Edge> out;
  const int n = static_cast<int>(region.contour.size());
  if (edges.empty() || n == 0) return out;
  const std::vector<int> labels = occluder_labels(ctx, region);
  std::vector<const Edge*> sorted;
  for (const Edge& e : edges) sorted.push_back(&e);
  std::sort(sorted.begin(), sorted.end(),
            [](const Edge* a, const Edge* b) { return a->begin < b->begin; });
  const int gap = static_cast<int>(std::ceil(ctx.options->merge_gap));
  struct Span {
    int begin, end;
    std::vector<int> atoms;
  };
  std::vector<Span> spans;
  for (const Edge* e : sorted) {
    if (!spans.empty() && e->begin - spans.back().end - 1 <= gap) {
      spans.back().end = std::max(spans.back().end, e->end);
      spans.back().atoms.insert(spans.back().atoms.end(), e->atoms.begin(), e->atoms.end());
    } else {
      spans.push_back({e->begin, e->end, e->atoms});
    }
  }
  // The last span may wrap around onto the first.
  if (spans.size() > 1 && spans.front().begin + n - spans.back().end - 1 <= gap) {
    spans.back().end = spans.front().end + n;
    spans.back().atoms.insert(spans.back().atoms.end(), spans.front().atoms.begin(),
                              spans.front().atoms.end());
    spans.erase(spans.begin());
  }
  for (const Span& s : spans) {
    if (s.end - s.begin + 1 >= n - 2) continue;  // (nearly) the whole outline
    Edge e = make_edge(ctx, region, labels, s.begin, s.end);
    e.atoms = s.atoms;
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace hair25d::completion::detail
