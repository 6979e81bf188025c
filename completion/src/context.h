// Shared state of one completion run (private): prepared labels, per-region
// facts, occluding edges.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <opencv2/core.hpp>
#include <optional>
#include <set>
#include <vector>

#include "hair25d/completion/completion.h"

namespace hair25d::completion::detail {

struct RegionInfo {
  int id = 0;
  cv::Rect box;  // bounding box in the image
  int pixels = 0;
  std::set<int> occluders;          // regions above this one
  std::vector<cv::Point> contour;   // outer boundary of its largest piece, image pixels
  Eigen::Vector3d colour{0, 0, 0};  // mean colour of its drawn (non-outline) pixels
  Vec2 centroid{0, 0};
};

struct Edge {
  int region = 0;
  int begin = 0, end = 0;  // contour indices of p and q: begin in [0, n), end >= begin
  std::vector<int> atoms;  // the single-occluder edges it is made of (ids into the atom list)
  Polyline points;         // the occluding boundary from p to q
  Vec2 p{0, 0}, q{0, 0};
  Vec2 tangent_p{0, 0}, tangent_q{0, 0};  // unit, pointing into the hidden part
  Polyline piece_p, piece_q;              // visible outline moving towards p / towards q
  std::set<int> occluders;
  Eigen::Vector3d colour{0, 0, 0};  // the region's colour next to the edge
  double colour_spread = 0.0;       // RGB standard deviation around `colour`
  double width = 0.0;               // |p − q|
  // Neither end has visible outline beside it though the region has some
  // elsewhere (the side of a wide piece running between two occluders): its
  // tangents are only the normal of the chord p q.
  bool guessed = false;
  // An *ink edge* (find_ink_edges): a run facing the regions `ink`, no
  // occluders of it, across a cut of drawn ink only (with, for a whole cut,
  // the occluded runs beside it); empty for an occluding edge.
  std::set<int> ink;
  // Session 31: the edge's end tangents measured unreliable (they part by
  // over kBentEndsDeg, or an end has no arm), and the strand's direction at
  // the cut read from both side outlines instead: the midpoints of the two
  // runs leaving p and q, paired by arc length, trace the strand's middle
  // line (unit, into the hidden part; zero when the runs are too short).
  bool unreliable = false;
  Vec2 side_tangent{0, 0};
  // Session 35 (JoinScorerOptions::angle_refusal_threshold): what backs the
  // end tangents, for the net judging an angle refusal's second chance:
  // visible outline beside p and q (px, up to fit_length), the angle the
  // two ends' own fits part by (radians; 0 when an end has none), and the
  // direction the "trust the longer run" rule dropped (zero when it did
  // not act; joins73's turned tangent).
  double arm_p = 0.0, arm_q = 0.0;
  double ends_part = 0.0;
  Vec2 turned_tangent{0, 0};
};

struct Context {
  const Image* image = nullptr;
  const LabelMap* original = nullptr;  // as given (0 on outlines)
  LabelMap labels;                     // outlines assigned
  // What the cover test reads: `labels` with the outlines' light fringe
  // given to the nearest region (Options::cover_fringe); empty: `labels`.
  LabelMap cover_labels;
  const LabelMap& cover_map() const { return cover_labels.empty() ? labels : cover_labels; }
  std::map<int, RegionInfo> regions;
  Vec2 head{0, 0};
  const Options* options = nullptr;
  // Strand-join candidates are recorded here when Options::join_scorer.record.
  std::vector<JoinCandidate>* join_log = nullptr;
  // Every edge pair's stage is recorded here when Options::trace_joins.
  std::vector<JoinTrace>* join_trace = nullptr;

  int label(int x, int y) const { return labels.contains(x, y) ? labels.at(x, y) : 0; }
  int label(const Vec2& p) const {
    return label(static_cast<int>(std::floor(p.x())), static_cast<int>(std::floor(p.y())));
  }
  // region -> regions above it through any chain of relations (drawn above it).
  std::map<int, std::set<int>> above;
  // Front hair: the regions drawn above some region (the rest is back hair).
  std::set<int> front() const {
    std::set<int> out;
    for (const auto& [id, ups] : above) out.insert(ups.begin(), ups.end());
    return out;
  }
  bool is_above(int upper, int region) const {
    auto it = above.find(region);
    return it != above.end() && it->second.count(upper) > 0;
  }
  // region -> regions above it through chains of the user's orders
  // (RegionRelation::user_fixed: fixed in the studio, or an annotation's).
  std::map<int, std::set<int>> user_above;
  bool is_user_above(int upper, int region) const {
    auto it = user_above.find(region);
    return it != user_above.end() && it->second.count(upper) > 0;
  }
  // Orders between regions that do not touch (completion.cpp `remote`;
  // smaller id first): occluders, but they do not keep two pieces' edges
  // apart in match_edges.
  std::set<std::pair<int, int>> remote_orders;
  // Two regions one of which directly occludes the other, nearby.
  bool keeps_apart(int a, int b) const {
    return (occludes(a, b) || occludes(b, a)) &&
           !remote_orders.count({std::min(a, b), std::max(a, b)});
  }
  bool occludes(int occluder, int region) const {
    auto it = regions.find(region);
    return it != regions.end() && it->second.occluders.count(occluder) > 0;
  }
};

// Whether a pixel of a join's patch, of label `l`, lies hidden: in a
// region above a piece (`above`), on the face where the face hides back
// hair (`face`, empty when it does not), or on the drawn ink across a cut of
// ink only (`ink`). One rule for the cover, the shapes and the corridor,
// its reads set up once for a row `y` of the map (the cover and the shapes
// ask it of every pixel of large patches).
class HiddenRow {
 public:
  HiddenRow() = default;  // a row off the map: no face, no ink
  HiddenRow(const Context& ctx, const cv::Mat& face, bool ink, int y)
      : face_(face.empty() ? nullptr : face.ptr<std::uint8_t>(y)),
        original_(ink ? ctx.original->data() + static_cast<std::size_t>(y) * ctx.original->width()
                      : nullptr) {}
  // Whether pixels of label `l` off every region above a piece differ one
  // from the next (on the face, or across a cut of ink only).
  bool per_pixel(int l) const { return (l == 0 && face_) || original_; }
  // Pixel x of the row.
  bool hidden(bool above, int l, int x) const {
    return above || (l == 0 && face_ && face_[x]) || (original_ && original_[x] == 0);
  }

 private:
  const std::uint8_t* face_ = nullptr;
  const int* original_ = nullptr;
};
inline bool hidden_pixel(const Context& ctx, bool above, int l, int x, int y, const cv::Mat& face,
                         bool ink) {
  return HiddenRow(ctx, face, ink, y).hidden(above, l, x);
}

// Whether a label lies above piece `a` or `b` (never label 0), the
// relations asked once per label: a patch's box holds few labels.
class AboveEither {
 public:
  AboveEither(const Context& ctx, int a, int b) : ctx_(ctx), a_(a), b_(b) {}
  bool operator()(int l) {
    for (const auto& [label, is] : seen_)
      if (label == l) return is;
    seen_.push_back({l, l != 0 && (ctx_.is_above(l, a_) || ctx_.is_above(l, b_))});
    return seen_.back().second;
  }
  // hidden_pixel with this label's relations.
  bool hides(int l, int x, int y, const cv::Mat& face, bool ink) {
    return hidden_pixel(ctx_, (*this)(l), l, x, y, face, ink);
  }

 private:
  const Context& ctx_;
  int a_, b_;
  std::vector<std::pair<int, bool>> seen_;
};

// What a hair region `l` (not 0) left uncovered by a join patch of pieces
// ra and rb is: a region under a piece, a sibling (under a region lying
// above a piece), or any other (the trace's holes, Options::trace_joins,
// and the cover refusals' inputs, cover_retry.h).
enum class HoleKind { kBelow, kSibling, kOther };
inline HoleKind hole_kind(const Context& ctx, int ra, int rb, int l) {
  if (ctx.is_above(ra, l) || ctx.is_above(rb, l)) return HoleKind::kBelow;
  for (int r : {ra, rb})
    if (const auto it = ctx.above.find(r); it != ctx.above.end())
      for (int up : it->second)
        if (ctx.is_above(up, l)) return HoleKind::kSibling;
  return HoleKind::kOther;
}

// Region facts and occluding edges (occluding_edges.cpp).
void describe_regions(Context& ctx);
// Maximal boundary runs under one occluder each ("atoms"), ids from `first_id`.
std::vector<Edge> find_edges(const Context& ctx, const RegionInfo& region, int first_id);
// A strand crossed by the tip of another strand thinner than its outline
// shows two pieces facing each other across ink only: no region lies between
// them, so neither has an occluder there and no occluding edge faces the
// other. Runs of the region's outline facing another region, unrelated to it,
// across at least kMinInkGap px of ink (a line between two touching strands
// is one outline wide, a crossing tip two), as edges with `ink` set; ids from
// `first_id`. Case-1 joins pair them only with the other region's run
// facing back (match_edges); never grown as roots or tips.
std::vector<Edge> find_ink_edges(const Context& ctx, const RegionInfo& region, int first_id);
// Neighbouring edges of one region (sorted by `begin`) merged where the
// visible gap between them is at most merge_gap (§5.2 "ps and sq").
std::vector<Edge> merge_edges(const Context& ctx, const RegionInfo& region,
                              const std::vector<Edge>& edges);

// Case 1 (joins.cpp): a matched pair of edges and its hidden patch.
struct Join {
  int edge_a = 0, edge_b = 0;
  double cost = 0.0;
  Polyline patch;  // closed polygon of the completed area
  // A join across the banks of an occluder (a wide piece cut by a strand
  // lying over it): bands under the occluder instead of one patch.
  std::vector<Polyline> bands;
  bool behind_face = false;   // the patch also counts over the face (both pieces back hair)
  int record = -1;            // index into Context::join_log, or −1
  int trace = -1;             // index into Context::join_trace, or −1
  double probability = -1.0;  // the scorer's, −1 when not asked
  // Tangents over max_join_angle_deg: the scorer alone may join it.
  bool wide = false;
  // Off the gradient by windows of uneven slopes: the scorer alone may join
  // it, at kUnevenThreshold (joins.cpp).
  bool uneven_gradient = false;
  // Session 31 (Options::side_tangents): refused by the angle with the
  // edges' own tangents, within it with an unreliable edge's side tangent;
  // the scorer alone may join it (JoinScorerOptions::side_threshold).
  bool side_tangent = false;
  // Session 35: a side-tangent candidate made by the second chance of
  // JoinScorerOptions::angle_refusal_threshold, judged by its own net.
  bool angle_retry = false;
  // Session 36: under min_join_coverage, kept as the second chance of
  // JoinScorerOptions::cover_refusal_threshold, judged by its own net.
  bool cover_retry = false;
  // Under min_join_coverage, let in by a corridor under the occluders
  // (Options::corridor_width): joins only at the retrained net's
  // corridor_min_probability.
  bool corridor = false;
  // The scorer's inputs for it, when it was scored (session 37: the second
  // partner's net reads them with inputs of its own added).
  std::optional<JoinFeatures> features;
};
// Greedy one-to-one matching, cheapest first; `try_join(a, b)` accepts (and
// records) or refuses joining the strands of regions a and b. `face` (CV_8U,
// image size, 1 = face; may be empty) hides back hair as an occluder does:
// a patch between two pieces that lie above no region may run behind it.
// `tones` and `fields` are the drawing's (bank_crossings.h, join_paint.h),
// shared with the mass and path joins so that its screentone test, dot
// masses and pieces' linear fields are measured once.
class RegionTones;
class RegionFields;
// `joined(a, b)` (may be empty) says whether regions a and b are one
// strand already: a cut's second partner (session 37) between them would add
// nothing, and is neither asked of its net nor recorded.
std::vector<Join> match_edges(const Context& ctx, const std::vector<Edge>& edges,
                              const cv::Mat& face, RegionTones& tones, RegionFields& fields,
                              const std::function<bool(int, int)>& try_join,
                              const std::function<bool(int, int)>& joined = {});

// Cases 2 and 3 (grow.cpp): the completed area of an unmatched edge, or an
// empty polygon when nothing could be grown.
struct Growth {
  Polyline area;  // closed polygon: the edge then the grown curve back
  bool tip = false;
  ContourStop stop = ContourStop::kConverged;
};
Growth grow_edge(const Context& ctx, const Edge& edge);

}  // namespace hair25d::completion::detail
