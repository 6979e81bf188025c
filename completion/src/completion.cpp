#include "hair25d/completion/completion.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <future>
#include <numeric>
#include <opencv2/imgproc.hpp>
#include <set>
#include <sstream>

#include "bank_crossings.h"
#include "context.h"
#include "cover_labels.h"
#include "face_joins.h"
#include "hair25d/core/error.h"
#include "hair25d/core/firm_equal.h"
#include "join_paint.h"
#include "measured_relations.h"
#include "raster.h"
#include "seam_joins.h"
#include "strand_assembly.h"
#include "strand_continuation.h"
#include "strand_paint.h"

namespace hair25d::completion {
namespace {

struct UnionFind {
  std::map<int, int> parent;
  int find(int x) {
    auto it = parent.find(x);
    if (it == parent.end()) return parent[x] = x;
    if (it->second == x) return x;
    return it->second = find(it->second);
  }
  void unite(int a, int b) { parent[find(a)] = find(b); }
};

// The regions of a's group and of b's group in `strands`.
std::pair<std::vector<int>, std::vector<int>> groups_of(UnionFind& strands,
                                                        const detail::Context& ctx, int a, int b) {
  const int ga = strands.find(a), gb = strands.find(b);
  std::pair<std::vector<int>, std::vector<int>> out;
  for (const auto& [x, info] : ctx.regions) {
    const int g = strands.find(x);
    if (g == ga) out.first.push_back(x);
    if (g == gb) out.second.push_back(x);
  }
  return out;
}

// With Options::strand_paint: whether a's and b's groups hold two pieces
// painted apart (strand_paint.h), recorded as refused once per pair; a
// and b themselves not compared with `but_pair`.
bool refuse_paint(UnionFind& strands, const detail::Context& ctx, detail::RegionTones& tones,
                  detail::RegionFields& fields, int a, int b, Result& result,
                  bool but_pair = false) {
  if (!ctx.options->strand_paint || strands.find(a) == strands.find(b)) return false;
  const auto [group_a, group_b] = groups_of(strands, ctx, a, b);
  const auto clash =
      detail::painted_apart(tones, fields, group_a, group_b,
                            but_pair ? std::optional(detail::PaintClash{a, b}) : std::nullopt);
  if (!clash) return false;
  const bool seen = std::any_of(
      result.paint_refusals.begin(), result.paint_refusals.end(),
      [&](const Result::PaintRefusal& f) { return std::minmax(f.a, f.b) == std::minmax(a, b); });
  if (!seen) result.paint_refusals.push_back({a, b, clash->a, clash->b});
  return true;
}

// Pairs of regions (smaller id first) with 4-neighbouring pixels in `labels`.
std::set<std::pair<int, int>> touching_pairs(const LabelMap& labels) {
  std::set<std::pair<int, int>> out;
  const auto add = [&](int a, int b) {
    if (a != 0 && b != 0 && a != b) out.insert({std::min(a, b), std::max(a, b)});
  };
  for (int y = 0; y < labels.height(); ++y)
    for (int x = 0; x < labels.width(); ++x) {
      if (x + 1 < labels.width()) add(labels.at(x, y), labels.at(x + 1, y));
      if (y + 1 < labels.height()) add(labels.at(x, y), labels.at(x, y + 1));
    }
  return out;
}

// A *remote* order: not the user's, between regions that do not touch once
// the outlines are assigned, whatever its score. The layering measures such
// orders across a thin line or sliver between the two (its own region map
// keeps them neighbours); the annotation, which the join rules were tuned
// on, never relates regions that do not touch. Pieces of one strand on both
// sides of an occluder are such a pair: on dev flat 2000-2099 with the
// layering's relations (main 948ca3c) 16 of 95 links lost against the
// annotation's relations were remote orders between the two pieces (8 of
// them firm), and of all remote orders 40 relate pieces of one strand and
// 375 two strands. A remote order still makes occluders and front hair, but
// neither keeps two pieces' edges apart (match_edges) nor counts as firm
// (try_join). Session 18 (joins29), precision / recall with the layering's
// relations: dev flat 2000-2099 0.934 / 0.779 -> 0.934 / 0.788, mixed
// 2000-2099 0.882 / 0.634 -> 0.887 / 0.650, flat 3000-3099 0.924 / 0.752 ->
// 0.926 / 0.766; fresh flat 4000 / 5000 +10 / +24 right pairs for 0 / +2
// wrong ones, mixed +16 / +19 for +2 / +3, screentone 2000-2099 +31 for +4
// (docs/completion-record.md, "Session 18: joins with the layering's relations").
// With the annotation's relations (the user's) nothing changes.
bool remote(const RegionRelation& r, const std::set<std::pair<int, int>>& touching) {
  return !r.user_fixed && !touching.count({std::min(r.a, r.b), std::max(r.a, r.b)});
}

// A measured relation weaker than this (|score|, the layering's support of
// its boundary states, layering.h) does not keep two regions out of one
// strand; it still makes occluders and front hair. Session 16 (joins22), dev
// sets with the layering's relations, precision / recall at 0 (every
// relation), 1.0, 1.5, 2.0, 3.0: flat 2000-2099 0.938 / 0.661, 0.940 /
// 0.700, 0.942 / 0.725, 0.939 / 0.742, 0.934 / 0.755; mixed 3000-3099 0.896 /
// 0.576, 0.898 / 0.629, 0.889 / 0.640, 0.887 / 0.644, 0.880 / 0.648 (all
// four sets in docs/completion-record.md). The user's relations (the annotation's)
// are always firm.
constexpr double kFirmRelationScore = 2.0;

bool firm(const RegionRelation& r) {
  return r.user_fixed || std::abs(r.score) >= kFirmRelationScore;
}

// The layering's `equal`s it is not sure of (EqualEvidence), not the
// user's: the same-depth model's mean log-odds under the layering's own
// bar for a firm equal (hair25d/core/firm_equal.h), or, for a
// pair equal because its common boundary is open, under 0 (the model leans
// to two depths). Such an equal between pieces painted apart
// (bank_crossings.h `two_paints`) makes no strand of them: it is neither a
// merge nor an order. Every one the layering gives scores 0, so before
// session 23 each such pair was united outright, and the false ones (the
// annotation orders the pair) were the largest source of wrong pairs with
// the layering's relations: on dev mixed 2000-2099 15 relations, 41 of the
// 85 wrong pairs (docs/completion-record.md, "Session 22: joins with the
// layering's relations"). Session 23 (joins39), precision / recall with the
// layering's relations: mixed 2000-2099 0.891 / 0.656 -> 0.912 / 0.659,
// flat 2000-2099 0.934 / 0.788 -> 0.955 / 0.796 (all sets in
// docs/completion-record.md, "Session 23: a confidence for the layering's
// equals"). With the annotation's relations (the user's) nothing changes.

bool weak_equal(const RegionRelation& r) {
  if (r.user_fixed || r.relation != Relation::kEqual || !r.equal_evidence) return false;
  const EqualEvidence& e = *r.equal_evidence;
  return e.log_odds < (e.open ? 0.0 : kFirmEqualLogOdds);
}

// An order the layering measured as an `equal` (it carries EqualEvidence,
// score 0) and its drawing order overrode (depth_order.h: the two were
// already ordered through chains of other relations, taken first): the
// pieces' own common boundary said one depth, the order came from
// elsewhere. Between pieces of one paint (read_relations) it is a seam,
// with no seam geometry: such pairs seldom meet a third region where the
// angles can be read. Its evidence must say one depth: over drawn lines
// with mean log-odds of at least kMinOverriddenEqualLogOdds (half the
// firm bar; below it dev flat 2069's two thin pieces of two strands of one
// flat colour, 0.91), or, for an open pair (no line between the pieces:
// the layering's equal says only that none was drawn), on screentone only,
// where one paint is both pieces' dots measured alike (annotated case1's
// open pair of two strands of one flat colour). Session 26 (joins52),
// precision / recall with the layering's relations: dev mixed 2000-2099
// 0.924 / 0.669 -> 0.924 / 0.672, screentone 3000-3099 0.915 / 0.661 ->
// 0.916 / 0.665 (docs/completion-record.md, "Session 26: equals the
// drawing order overrode").
constexpr double kMinOverriddenEqualLogOdds = 1.0;

bool overridden_equal(const RegionRelation& r, bool screentone) {
  if (r.user_fixed || !r.overridden || !r.equal_evidence || r.relation == Relation::kEqual)
    return false;
  if (r.equal_evidence->open) return screentone;
  return r.equal_evidence->log_odds >= kMinOverriddenEqualLogOdds;
}

// region -> the regions above it through any chain of `occluders` (region ->
// the regions directly above it).
std::map<int, std::set<int>> chains_above(const std::map<int, std::set<int>>& occluders) {
  std::map<int, std::set<int>> out;
  for (const auto& [id, direct] : occluders) {
    std::vector<int> stack(direct.begin(), direct.end());
    std::set<int>& seen = out[id];
    while (!stack.empty()) {
      const int r = stack.back();
      stack.pop_back();
      if (!seen.insert(r).second) continue;
      const auto it = occluders.find(r);
      if (it != occluders.end()) stack.insert(stack.end(), it->second.begin(), it->second.end());
    }
  }
  return out;
}

void check_input(const Input& input, const Options& options) {
  std::string why;
  if (!options.is_valid(&why)) throw Error(why);
  if (input.image == nullptr || input.image->empty())
    throw Error("completion::complete_strands: no image; an image is required");
  if (input.regions == nullptr || input.regions->empty())
    throw Error("completion::complete_strands: no region map; a region map is required");
  detail::require_image_size("completion::complete_strands", "regions are", *input.regions,
                             *input.image);
  if (input.head_center &&
      (!std::isfinite(input.head_center->x()) || !std::isfinite(input.head_center->y())))
    throw Error("completion::complete_strands: head_center is not finite");
}

}  // namespace

const char* to_string(EdgeCase c) {
  switch (c) {
    case EdgeCase::kJoined:
      return "joined";
    case EdgeCase::kRoot:
      return "root";
    case EdgeCase::kTip:
      return "tip";
    case EdgeCase::kNotCompleted:
      return "not-completed";
  }
  return "unknown";
}

const char* to_string(JoinStage s) {
  switch (s) {
    case JoinStage::kKeptApart:
      return "kept-apart";
    case JoinStage::kInkFacing:
      return "ink-facing";
    case JoinStage::kColour:
      return "colour";
    case JoinStage::kGuessed:
      return "guessed";
    case JoinStage::kWidthRatio:
      return "width-ratio";
    case JoinStage::kCrossingChords:
      return "crossing-chords";
    case JoinStage::kInkAcross:
      return "ink-across";
    case JoinStage::kAngle:
      return "angle";
    case JoinStage::kOtherPaint:
      return "other-paint";
    case JoinStage::kHandCost:
      return "hand-cost";
    case JoinStage::kCover:
      return "cover";
    case JoinStage::kOtherBack:
      return "other-back";
    case JoinStage::kWideRefused:
      return "wide-refused";
    case JoinStage::kUnevenRefused:
      return "uneven-refused";
    case JoinStage::kBandRefused:
      return "band-refused";
    case JoinStage::kVetoed:
      return "vetoed";
    case JoinStage::kAtomTaken:
      return "atom-taken";
    case JoinStage::kTwoTones:
      return "two-tones";
    case JoinStage::kRefused:
      return "refused";
    case JoinStage::kChosen:
      return "chosen";
  }
  return "unknown";
}

namespace {

// Reads the relations: equal pairs and seams are united in `strands` (weak
// equals between pieces painted apart refused), orders give each region its
// occluders, remote orders and the chains above go to `ctx`. Returns region
// -> the regions above it through chains of firm relations between touching
// regions, which alone keep two regions out of one strand (try_join).
std::map<int, std::set<int>> read_relations(const std::vector<RegionRelation>& relations,
                                            const std::set<std::pair<int, int>>& touching,
                                            detail::RegionTones& tones,
                                            detail::RegionFields& fields, detail::Context& ctx,
                                            UnionFind& strands, Result& result) {
  // Seams (seam_joins.h): two touching pieces of one paint that the
  // layering orders weakly, whose side outlines run on across the line
  // between them (round the meeting points, seam_geometry, or on slices
  // along the line farther from it, continues_one_strand) or whose order
  // overrode the layering's equal (overridden_equal), are halves of one
  // strand as an `equal` pair is. The slices only with
  // Options::continuation_seams (session 27, joins57).
  const detail::DirectOrders direct(relations, touching);
  const auto directly_above = [&](int x, int y) { return direct.above(x, y); };
  std::set<std::pair<int, int>> seams;
  for (const RegionRelation& r : relations) {
    if (detail::unmeasured(r, touching) || r.relation == Relation::kEqual || firm(r)) continue;
    // One paint (bank_crossings.h). The seam geometry never on screentone:
    // one tone there is shared by several strands (dev mixed 2000-2099, seed
    // 2099: a seam of two strands of one tone, 5 wrong pairs); an equal the
    // drawing order overrode needs no geometry (overridden_equal).
    const bool overridden = overridden_equal(r, tones.screentone());
    if (!overridden && tones.screentone()) continue;
    if (detail::one_paint(tones, fields, r.a, r.b) &&
        (overridden || detail::seam_geometry(ctx, r.a, r.b, directly_above) ||
         (ctx.options->continuation_seams &&
          detail::continues_one_strand(
              detail::strand_continuation(ctx, r.a, r.b, directly_above)))))
      seams.insert({r.a, r.b});
  }
  // Options::remote_across_occluder: the regions each lies directly under,
  // through orders between touching regions.
  std::map<int, std::set<int>> touching_above;
  if (ctx.options->remote_across_occluder)
    for (const RegionRelation& r : relations)
      if (r.relation != Relation::kEqual && !detail::unmeasured(r, touching) &&
          !remote(r, touching))
        touching_above[r.relation == Relation::kBelow ? r.a : r.b].insert(
            r.relation == Relation::kBelow ? r.b : r.a);
  const auto across_occluder = [&](const RegionRelation& r) {
    if (!ctx.options->remote_across_occluder || r.relation == Relation::kEqual ||
        !remote(r, touching) || firm(r))
      return false;
    const std::set<int>& over_a = touching_above[r.a];
    const std::set<int>& over_b = touching_above[r.b];
    const bool common =
        std::any_of(over_a.begin(), over_a.end(), [&](int o) { return over_b.count(o) > 0; });
    return common && detail::one_paint(tones, fields, r.a, r.b);
  };
  for (const RegionRelation& r : relations) {
    if (detail::unmeasured(r, touching)) continue;
    if (across_occluder(r)) continue;
    if (weak_equal(r) && detail::two_paints(tones, fields, r.a, r.b)) {
      ++result.refused_equals;
      continue;
    }
    // The layering's equals and seams are judged as the joins are
    // (try_join, Options::strand_paint): groups holding pieces painted
    // apart are not made one; the equal is then nothing, the seam its
    // order. The pair itself is compared too (off screentone: a false
    // layering `equal` between two strands is a pair painted apart),
    // except on screentone, where the dots measured pieces of one strand
    // apart (dev screentone 2000-2099: 4 of 5 such pairs refused). Session
    // 28 (joins60), with the layering's relations: dev mixed 3000-3099
    // 0.942 / 0.693 (the joins judged alone) -> 0.953 / 0.703.
    const bool merge = r.relation == Relation::kEqual || seams.count({r.a, r.b});
    const bool refused =
        merge && !r.user_fixed &&
        refuse_paint(strands, ctx, tones, fields, r.a, r.b, result, tones.screentone());
    if (refused && r.relation == Relation::kEqual) continue;
    if (merge && !refused) {
      // Same depth and touching: halves of one strand (counted once per two
      // groups made one, so the summary adds up: regions - strands).
      if (strands.find(r.a) != strands.find(r.b)) ++result.equal_merges;
      strands.unite(r.a, r.b);
    } else if (r.relation == Relation::kBelow)
      ctx.regions[r.a].occluders.insert(r.b);
    else
      ctx.regions[r.b].occluders.insert(r.a);
  }

  for (const RegionRelation& r : relations)
    if (r.relation != Relation::kEqual && !detail::unmeasured(r, touching) && remote(r, touching))
      ctx.remote_orders.insert({std::min(r.a, r.b), std::max(r.a, r.b)});
  // Only firm relations between touching regions keep two regions out of one
  // strand (try_join).
  std::map<int, std::set<int>> firm_occluders;
  for (const RegionRelation& r : relations)
    if (r.relation != Relation::kEqual && !remote(r, touching) && firm(r))
      firm_occluders[r.relation == Relation::kBelow ? r.a : r.b].insert(
          r.relation == Relation::kBelow ? r.b : r.a);
  std::map<int, std::set<int>> occluders, user_occluders;
  for (const auto& [id, info] : ctx.regions) occluders[id] = info.occluders;
  for (const RegionRelation& r : relations)
    if (r.relation != Relation::kEqual && r.user_fixed)
      user_occluders[r.relation == Relation::kBelow ? r.a : r.b].insert(
          r.relation == Relation::kBelow ? r.b : r.a);
  ctx.above = chains_above(occluders);
  ctx.user_above = chains_above(user_occluders);
  return chains_above(firm_occluders);
}

}  // namespace

Result complete_strands(const Input& input, const Options& options, Progress* progress) {
  check_input(input, options);
  const Image& image = *input.image;
  Result result;
  detail::Context ctx;
  ctx.image = &image;
  ctx.original = input.regions;
  ctx.options = &options;
  if (options.join_scorer.record) ctx.join_log = &result.join_candidates;
  if (options.trace_joins) ctx.join_trace = &result.join_trace;
  ctx.labels =
      assign_outline_pixels(image, *input.regions, options.outline_reach, options.dark_luma);
  report(progress, "completion", 0.05, "regions");
  detail::describe_regions(ctx);

  UnionFind strands;
  for (const auto& [id, info] : ctx.regions) strands.find(id);
  for (const RegionRelation& r : input.relations) {
    if (!ctx.regions.count(r.a) || !ctx.regions.count(r.b)) {
      throw Error("completion::complete_strands: relation " + std::to_string(r.a) + " / " +
                  std::to_string(r.b) + " names a region that is not in the region map");
    }
  }
  // Head centre: given, else the centroid of the hair (it frames the face).
  if (input.head_center) {
    ctx.head = *input.head_center;
  } else {
    double sx = 0, sy = 0, n = 0;
    for (const auto& [id, info] : ctx.regions) {
      sx += info.centroid.x() * info.pixels;
      sy += info.centroid.y() * info.pixels;
      n += info.pixels;
    }
    ctx.head = n > 0 ? Vec2(sx / n, sy / n) : Vec2(image.width() / 2.0, image.height() / 2.0);
    result.head_center_estimated = true;
  }
  result.head_center = ctx.head;
  // The background fill needs the labels, the regions' colours and the head
  // centre (the face and the head behind the hair), never changed below: it
  // runs beside the relations' reading (session 40: 20-40 ms of one core
  // before it on the seed-7 drawings), the matching, growing and strands.
  // It reads no relation, and the regions' occluders that the relations
  // add are not read by it.
  // The face: hidden back hair is joined across it, and the background
  // fills the head behind the hair from it. With the background on its own
  // thread the face is found there, first (session 40: 15-20 ms of one
  // core that the relations no longer wait for); the matching waits for it.
  detail::Face drawn_face;
  const bool want_face = options.face_joins || options.inpaint_background;
  std::promise<void> face_found;
  std::future<void> face_ready = face_found.get_future();
  // The hole is kept: the strands carry what it takes that they do not show.
  detail::BackgroundHole hole;
  auto fill_background = [&] {
    hole = detail::background_hole(ctx, drawn_face);
    return detail::fill_background(ctx, hole, &result.background_inpaint);
  };
  std::future<Image> background;
  if (options.inpaint_background && options.threads > 1) {
    background = std::async(std::launch::async, [&] {
      try {
        drawn_face = detail::find_face(ctx);
      } catch (...) {
        face_found.set_exception(std::current_exception());
        throw;
      }
      face_found.set_value();
      return fill_background();
    });
  } else {
    if (want_face) drawn_face = detail::find_face(ctx);
    face_found.set_value();
  }

  const std::set<std::pair<int, int>> touching = touching_pairs(ctx.labels);
  // The drawing's tones and paint fields, measured once for all join passes
  // (region paint only: no relation is read).
  detail::RegionTones tones(ctx);
  detail::RegionFields fields(ctx);
  const std::map<int, std::set<int>> firm_above =
      read_relations(input.relations, touching, tones, fields, ctx, strands, result);
  // Options::cover_fringe: read under the user's orders, or the layering's
  // at a low hand cost (cover_fringe_layering_cost; 0 and no user's: no cost).
  if (options.cover_fringe > 0 && tones.screentone() &&
      (!ctx.user_above.empty() || options.cover_fringe_layering_cost > 0))
    ctx.cover_labels = detail::fringe_labels(ctx.labels, options.cover_fringe);
  const auto firmly_above = [&](int upper, int region) {
    const auto it = firm_above.find(region);
    return it != firm_above.end() && it->second.count(upper) > 0;
  };

  // Single-occluder edges ("atoms"), and merged runs of them as further
  // candidates for case 1 (a strand may pass under two neighbouring occluders).
  std::vector<detail::Edge> atoms;
  std::map<int, std::vector<int>> atoms_of_region;
  for (const auto& [id, info] : ctx.regions) {
    std::vector<detail::Edge> found = detail::find_edges(ctx, info, static_cast<int>(atoms.size()));
    for (detail::Edge& e : found) {
      atoms_of_region[id].push_back(static_cast<int>(atoms.size()));
      atoms.push_back(std::move(e));
    }
  }
  std::vector<detail::Edge> candidates = atoms;
  for (const auto& [id, list] : atoms_of_region) {
    std::vector<detail::Edge> mine;
    for (int a : list) mine.push_back(atoms[a]);
    for (detail::Edge& e : detail::merge_edges(ctx, ctx.regions.at(id), mine))
      if (e.atoms.size() > 1) candidates.push_back(std::move(e));
  }
  // Ink edges: join candidates only (never grown), ids past the atoms'.
  int next_id = static_cast<int>(atoms.size());
  for (const auto& [id, info] : ctx.regions)
    for (detail::Edge& e : detail::find_ink_edges(ctx, info, next_id)) {
      ++next_id;
      candidates.push_back(std::move(e));
    }
  if (options.trace_joins) {
    std::set<int> with_edges;
    for (const detail::Edge& e : candidates) with_edges.insert(e.region);
    result.edge_regions.assign(with_edges.begin(), with_edges.end());
  }
  report(progress, "completion", 0.2, "matching");

  // Case 1, then 2 and 3 for the edges left (§5.4).
  detail::StrandPieces pieces;
  std::vector<EdgeReport> reports;
  auto new_report = [&](const detail::Edge& e, EdgeCase c) {
    EdgeReport r;
    r.region = e.region;
    r.p = e.p;
    r.q = e.q;
    r.completion = c;
    reports.push_back(r);
    return static_cast<int>(reports.size()) - 1;
  };
  // A strand cannot lie above itself: two regions one of which is above the
  // other through a chain of firm relations are never joined.
  // Nor, with Options::strand_paint, two groups holding two pieces painted
  // apart (strand_paint.h).
  const auto try_join = [&](int a, int b) {
    if (strands.find(a) == strands.find(b)) return false;
    const auto [group_a, group_b] = groups_of(strands, ctx, a, b);
    for (int x : group_a)
      for (int y : group_b)
        if (firmly_above(y, x) || firmly_above(x, y)) return false;
    if (refuse_paint(strands, ctx, tones, fields, a, b, result)) return false;
    strands.unite(a, b);
    return true;
  };
  // The face hides the back hair as a strand does (it is no region): case-1
  // joins of back hair may run behind it, and face joins (below) join pieces
  // seen on opposite sides of it.
  face_ready.get();
  const detail::Face face = options.face_joins ? drawn_face : detail::Face{};
  const std::vector<detail::Join> joins =
      detail::match_edges(ctx, candidates, face.mask, tones, fields, try_join,
                          [&](int a, int b) { return strands.find(a) == strands.find(b); });
  std::set<int> joined_atoms;
  for (const detail::Join& j : joins) {
    const detail::Edge& a = candidates[j.edge_a];
    const detail::Edge& b = candidates[j.edge_b];
    joined_atoms.insert(a.atoms.begin(), a.atoms.end());
    joined_atoms.insert(b.atoms.begin(), b.atoms.end());
    const int ra = new_report(a, EdgeCase::kJoined);
    reports[ra].joined_region = b.region;
    const int rb = new_report(b, EdgeCase::kJoined);
    reports[rb].joined_region = a.region;
    if (j.patch.size() >= 3)
      pieces.areas.push_back({a.region, j.patch, false, ra, j.behind_face ? &face.mask : nullptr});
    for (const Polyline& band : j.bands) pieces.areas.push_back({a.region, band, false, ra});
    ++result.joins;
  }
  // Back hair cut by a fan of overlapping strands: no single edge pair faces
  // across them, so its pieces are matched region to region (bank_crossings.h).
  // A join whose hidden part is bands between the two pieces; `ends` puts the
  // reports' end points at the first band's ends (the ray joins have them).
  auto join_by_bands = [&](const detail::MassJoin& j, bool ends, const cv::Mat* over = nullptr) {
    if (!try_join(j.region_a, j.region_b)) return;
    EdgeReport ra, rb;
    ra.region = j.region_a, ra.joined_region = j.region_b;
    rb.region = j.region_b, rb.joined_region = j.region_a;
    if (ends) {
      ra.p = ra.q = j.bands.empty() ? Vec2(0, 0) : j.bands.front().front();
      rb.p = rb.q = j.bands.empty() ? Vec2(0, 0) : j.bands.front().back();
    }
    ra.completion = rb.completion = EdgeCase::kJoined;
    reports.push_back(ra);
    reports.push_back(rb);
    for (const Polyline& band : j.bands)
      pieces.areas.push_back({j.region_a, band, false, static_cast<int>(reports.size()) - 2, over});
    ++result.joins;
  };
  for (const detail::MassJoin& j : detail::mass_join_candidates(ctx, tones, fields))
    join_by_bands(j, true);
  std::set<int> front;
  for (const auto& [id, ups] : ctx.above)
    for (int up : ups) front.insert(strands.find(up));
  for (const auto& [id, info] : ctx.regions)
    if (front.count(strands.find(id))) front.insert(id);
  // Tails hanging from under the back hair lie above nothing but are no back
  // hair: the generator's twin tails touch the face's sides below the ears
  // and were joined to each other across it (flat and gradient seeds
  // 101-116: precision 0.893 -> 0.932, 0.895 -> 0.933, recall unchanged).
  // A tail hangs from under one or two pieces; a lowest piece under more
  // (the tail test also takes back hair covered only by strands lying on
  // nothing but back hair: screentone 114 region 20, under five) is kept.
  detail::TailedHair tailed = detail::tailed_hair(ctx, ctx.front());
  detail::untail_back_paint(ctx, ctx.front(), fields.cels(), &tailed);
  for (int t : tailed.tails)
    if (ctx.regions.at(t).occluders.size() <= 2) front.insert(t);
  const cv::Mat near_face =
      options.face_piece_mass_step > 0 ? detail::near_face_mask(face.mask) : cv::Mat();
  for (const detail::FaceJoin& j : detail::face_join_candidates(ctx, face, front)) {
    // On a cel drawing pieces of other flat paints are two locks, as for the
    // mass and path joins (RegionCels::judge, step over 3 RGB): the face
    // joins' colour limit (max_colour_distance, 90) let tails 7-62 RGB off
    // the back's paint join it across the face (session 14, dev seeds
    // 2000-2099: 4 wrong links of flat drawings, 9 pairs).
    if (fields.cels().judge(j.region_a, j.region_b).other) continue;
    // Pieces painted by two gradients (both linear, the joint field missing
    // them by more than kMinOtherFieldStep) are two strands, as for the
    // mass joins: on gradient drawings 2000-2099 and 3000-3099 the face
    // joins made 11 right links and 16 wrong ones (back hair to tails and
    // to strands lying on the face); the field said something on 7 of the
    // right ones (0-0.06) and 12 of the wrong ones (3.6-41) (session 16).
    if (!tones.screentone()) {
      const double field = fields.step(j.region_a, j.region_b);
      if (std::isfinite(field) && field > detail::kMinOtherFieldStep) continue;
    }
    // Screentone pieces of two tones by their dots (session 23: dev 4079's
    // back hair joined across the face to a lighter tail, 2 wrong pairs).
    if (detail::two_tones_by_dots(tones, j.region_a, j.region_b)) continue;
    // A strand lying on the face is no back hair (Options::face_piece_mass_step).
    if (detail::strand_on_face(ctx, tones, near_face, j.region_a, j.region_b)) continue;
    if (!try_join(j.region_a, j.region_b)) continue;
    EdgeReport ra, rb;
    ra.region = j.region_a, ra.p = j.pa, ra.q = j.qa, ra.joined_region = j.region_b;
    rb.region = j.region_b, rb.p = j.pb, rb.q = j.qb, rb.joined_region = j.region_a;
    ra.completion = rb.completion = EdgeCase::kJoined;
    reports.push_back(ra);
    reports.push_back(rb);
    pieces.areas.push_back(
        {j.region_a, j.patch, false, static_cast<int>(reports.size()) - 2, &face.mask});
    ++result.joins;
  }
  // Back-hair pieces linked under the regions above both (mass_paths.cpp).
  const auto one_strand = [&](int a, int b) { return strands.find(a) == strands.find(b); };
  for (const detail::MassJoin& j :
       detail::path_join_candidates(ctx, face.mask, tones, fields, one_strand))
    join_by_bands(j, false);
  // Back-hair pieces on both sides of the neck or body (body_joins.cpp).
  // Session 13's guard (on screentone no body join onto a strand holding a
  // join behind the face) went when match_edges stopped joining back pieces
  // across a third back piece of another paint (generated screentone 104's
  // tail 5 to back 27): held-out screentone 207 gained its 6 pairs.
  cv::Mat body;
  for (const detail::MassJoin& j :
       detail::body_join_candidates(ctx, face, front, tones, fields, &body))
    join_by_bands(j, false, &body);
  // Cases 2 and 3: every open edge grows on its own (grow_edge reads the
  // context only), most of completion's serial time: two workers take the
  // next edge, the results are then used in the edges' order.
  std::vector<detail::Edge> open_edges;
  for (const auto& [id, list] : atoms_of_region) {
    std::vector<detail::Edge> open;
    for (int a : list)
      if (!joined_atoms.count(a)) open.push_back(atoms[a]);
    for (detail::Edge& e : detail::merge_edges(ctx, ctx.regions.at(id), open))
      open_edges.push_back(std::move(e));
  }
  std::map<int, std::vector<int>> groups;
  for (const auto& [id, info] : ctx.regions) groups[strands.find(id)].push_back(id);
  for (auto& [root, members] : groups) pieces.groups.push_back(members);

  // Each open edge's report, in the edges' order, filled in when it has grown.
  std::vector<int> growth_report(open_edges.size());
  for (std::size_t k = 0; k < open_edges.size(); ++k)
    growth_report[k] = new_report(open_edges[k], EdgeCase::kNotCompleted);
  std::vector<detail::Growth> growths(open_edges.size());
  std::vector<detail::PieceArea> grown(open_edges.size());
  const auto grow = [&](std::size_t k) -> const detail::PieceArea* {
    const detail::Edge& e = open_edges[k];
    const detail::Growth& g = growths[k] = detail::grow_edge(ctx, e);
    if (g.area.size() < 3) return nullptr;
    EdgeReport& r = reports[growth_report[k]];
    r.completion = g.tip ? EdgeCase::kTip : EdgeCase::kRoot;
    r.stop = g.stop;
    grown[k] = {e.region, g.area, !g.tip, growth_report[k]};
    return &grown[k];
  };
  // Longest edges first: the longest growths take longest.
  std::vector<std::size_t> grow_order(open_edges.size());
  std::vector<int> grown_region(open_edges.size());
  for (std::size_t k = 0; k < open_edges.size(); ++k)
    grow_order[k] = k, grown_region[k] = open_edges[k].region;
  std::stable_sort(grow_order.begin(), grow_order.end(), [&](std::size_t a, std::size_t b) {
    return open_edges[a].points.size() > open_edges[b].points.size();
  });
  // Cases 2 and 3: every open edge grows on its own (grow_edge reads the
  // context only); a strand is assembled as soon as its regions' edges have
  // grown, beside the growing of the others (assemble_strands).
  report(progress, "completion", 0.2, "growing");
  result.strands = detail::assemble_strands(
      ctx, pieces, grown_region, grow_order, grow,
      [&](std::size_t done) {
        report(progress, "completion", 0.2 + 0.65 * done / open_edges.size(),
               done < open_edges.size() ? "growing" : "strands");
      },
      &reports, &result.strand_inpaint);
  for (const detail::Growth& g : growths)
    if (g.area.size() >= 3) (g.tip ? result.tips : result.roots) += 1;
  report(progress, "completion", 0.85, "background");
  if (background.valid())
    result.background = background.get();
  else if (options.inpaint_background)
    result.background = fill_background();
  else
    result.background = image;
  if (options.inpaint_background)
    detail::carry_rims(ctx, hole.holes, pieces.groups, result.background, &result.strands);
  result.edges = std::move(reports);
  result.regions = std::move(ctx.labels);
  std::ostringstream s;
  s << result.strands.size() << " strands from " << ctx.regions.size()
    << " regions: " << result.equal_merges << " same-depth merges";
  if (result.refused_equals > 0) s << " (" << result.refused_equals << " weak equals refused)";
  s << ", " << result.joins << " joins, " << result.roots << " roots, " << result.tips
    << " tips completed; " << result.strand_inpaint.filled << " strand and "
    << result.background_inpaint.filled << " background pixels inpainted";
  result.summary = s.str();
  report(progress, "completion", 1.0, result.summary);
  return result;
}

}  // namespace hair25d::completion
