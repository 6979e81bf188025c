#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <set>

#include "angle_retry.h"
#include "bank_crossings.h"
#include "context.h"
#include "cover_retry.h"
#include "greedy_matching.h"
#include "hair25d/completion/bezier.h"
#include "join_corridor.h"
#include "join_features.h"
#include "join_paint.h"
#include "join_raster.h"
#include "join_scoring.h"
#include "join_shapes.h"
#include "raster.h"

namespace hair25d::completion::detail {
namespace {

// Weight of the width change half-way along a join (|log(middle / ends)|)
// in the cost; chosen on the annotated cases with the other weights.
constexpr double kBulgeWeight = 4.0;
// Cost of a strand join whose pieces share no occluder (the gap lies under
// two overlapping strands). 0.4 before; 0.2 keeps the preference for a
// common occluder while long strands, which pass under several, still join
// (generated 1000 × 800 drawings: precision 0.702 → 0.754, recall 0.333 →
// 0.358; annotated cases unchanged).
constexpr double kNoCommonOccluderCost = 0.2;
// A join of two back pieces behind the face whose hidden part runs over a
// third back piece (above no region) of another paint is refused: the
// hidden part lies behind what shows there, and back hair of another paint
// showing is no cover of this one. Generated screentone 104: tail 5 was
// joined behind strand 13 to back 27 across the 975 px of piece 25 (another
// tone), 0.089 of the patch; right joins crossing a third back piece crossed
// one of their own paint (flat 101-116: 0.06 of the patch, step 0). Every
// limit from 0 to 0.08 measured the same on all sets (docs/completion-record.md).
constexpr double kMaxOtherBackShare = 0.04;
// Region colours further apart than this are another paint (not screentone).
constexpr double kOtherBackColourStep = 20.0;
// Cost per 30 RGB of the colour step between the pieces that their paint
// does not explain (`paint_step`). Session 4 (0.5, the step between the
// windows' means beyond their spread): on the generated drawings (strands of
// one hair colour with small per-strand changes) the chosen strand joins
// stepped median 3.3 RGB when right and 15.1 when wrong (seeds 101-116); a
// heavier plain colour term lost annotated joins whose edges lie in shading
// bands, and weight 1.0 lost gradient recall (0.557 -> 0.528). Session 10:
// with the step measured by the paint (a gradient's predicted change and a
// cel band's colours no longer count), 1.0: precision / recall 101-116
// two-tone 0.851 / 0.601, gradient 0.970 / 0.601, flat 0.959 / 0.775
// (0.5: 0.806 / 0.566 without the shadow ratio, 0.948 / 0.605, 0.943 /
// 0.731; 1.5: 0.878 / 0.601, 0.969 / 0.583, 0.968 / 0.775); annotated
// unchanged at all three. Between flat paints the step is exact (no fit
// carried across the gap), so it weighs 1.5 there: two-tone 0.856 -> 0.884
// (201-216 0.896 -> 0.920), flat 0.959 -> 0.968, the rest unchanged (2.5:
// two-tone 0.895 / 0.596, flat 0.972 / 0.775).
constexpr double kColourStepWeight = 1.0;
constexpr double kFlatStepWeight = 1.5;
// A gradient that carries on across the gap (`PaintStep::shading_continues`,
// join_paint.cpp, where the figures are) makes a strand join cost this less.
constexpr double kShadingContinuesBonus = 0.6;
// A *nub* — front hair shallower behind its cut than half the cut is wide
// (pixels < kNubDepth × cut width²: a strand's rounded root peeking out from
// under an occluder) — has no outline that runs along the strand, so its
// fitted tangents turn with the rounded end and it made no strand join
// (session 12). The other piece's tangents decide then: both within
// kOneSidedAngleDeg of the chords, at kOneSidedCost more. Seeds 101-116,
// `eval_joins`: penalty 0.3 gave two-tone 0.884 / 0.601 -> 0.877 / 0.627 and
// the annotated six 0.982 -> 0.973 precision (a wrong nub join); 0.8 keeps
// every set's precision.
constexpr double kNubDepth = 0.5;
constexpr double kOneSidedAngleDeg = 30.0;
constexpr double kOneSidedCost = 0.8;
// A bank join through a *window* (bank_crossings.cpp: a piece seen between
// two strands lying over it, too shallow for the banks' depth rule) with a
// piece of back hair steps at most this much by paint (RGB): the path joins'
// back-hair slivers of another shade (4 RGB, mass_joins_test) stay apart.
// Seeds 101-116 give the same pairs from 0.3 to 3.0.
constexpr double kMaxBackWindowStep = 1.0;
// A strand join between two pieces of flat paint (`PaintStep::flat`: the
// step is exact, a cel band explained by the shadow ratio) stepping more
// than this (RGB), one of them a front piece, is refused: the generator
// varies each strand's colour by up to 8 %, and one strand's pieces are one
// paint. Session 12 (joins11), the chosen strand joins of seeds 101-116:
// right ones stepped at most 0.8 RGB (two-tone; flat 0.0, annotated six
// 0.6), the 11 wrong ones of flat and two-tone 1.9-14.0. Pieces of back hair (above no region) are
// left out: a two-tone back is one mass in a base and a band (`RegionCels`), and a right
// back-to-back join stepped 1.9 RGB (two-tone 204, held out). Figures in
// docs/completion-record.md "Session 12: wrong strand joins".
constexpr double kMaxFlatStrandStep = 1.5;
// *Rare paint* (session 13): a strand join between two pieces of one flat
// paint (`PaintStep::flat`, step at most kRarePaintStep RGB), one of them a
// front piece, whose paint no more than kRarePaintSharing flat-painted regions
// of the drawing share (each region's flat colours within kRarePaintMatch RGB
// of the other's, `region_flat_distance`; the pair counts itself) costs
// kRarePaintBonus less. Where the strands are painted apart, one paint on both
// sides of a gap is what a person follows under a long or bending occluder;
// where many regions share it (strands of one hair colour), it says nothing
// and nothing changes. Seeds 101-116, `eval_joins`, precision / recall: flat
// 0.996 / 0.830 -> 0.996 / 0.882, two-tone 0.993 / 0.640 -> 1.000 / 0.724
// (held out 201-216: 0.989 / 0.751 -> 0.984 / 0.798, 0.978 / 0.634 -> 0.979 /
// 0.677); gradient, screentone and the annotated six unchanged. Sharing at
// most 1 (the partner only) lost strands in three pieces, 3 two-tone
// precision; without the front piece a right back-hair join chained into a
// wrong one (flat 201-216 precision 0.964). Figures in docs/completion-record.md
// "Session 13: strand links over the cost limit".
constexpr double kRarePaintBonus = 1.5;
constexpr double kRarePaintStep = 0.5;
constexpr double kRarePaintMatch = 0.5;
constexpr int kRarePaintSharing = 2;
// A region counts as flat paint for the sharing when its three commonest
// colours hold this share of its pixels (join_paint.cpp's kFlatPaintShare).
// Rarity needs regions to compare with: with fewer than kRarePaintRegions
// flat-painted regions nothing is rare (generated flat and two-tone seeds
// 101-104 hold 26-36, the annotated six 0-26). Screentone drawings are
// left to the tone: the dots and the paper are every toned piece's two
// flat colours.
constexpr double kRarePaintFlatShare = 0.85;
constexpr std::size_t kRarePaintRegions = 8;
// *One field* (session 24), the rare paint of gradient drawings: a strand
// join between two pieces not of flat paint that one linear colour field
// paints (`RegionFields::step`, the joint fit missing each piece by at most
// kOneFieldStep RGB beyond its own fit; infinite, nothing said, unless
// both pieces are linear and the field a gradient) costs kOneFieldBonus
// less. The generator shades a strand along its length and the pieces'
// own fits carry that across the gap, where the windows at the cuts see
// 12 px of it: on flat drawings of the same geometry the right joins that
// gradient drawings missed had rare paint (1.5 less), on gradients only
// `shading_continues` (0.6). Of the strand candidates of dev gradient
// 2000-2099 whose fields were measured, the joint fit missed right ones
// by at most 0.1 RGB 1059 times, wrong ones 41. Gradient 2000-2099 with
// the path joins' field below: 0.933 / 0.776 -> 0.940 / 0.795 (step 0.1:
// 0.938 / 0.789, 0.5: 0.936 / 0.796, 1.0: 0.935 / 0.801; bonus 0.6: 0.937 /
// 0.785, 1.2: 0.939 / 0.795). Figures in docs/completion-record.md, "Session 24".
constexpr double kOneFieldStep = 0.25;
constexpr double kOneFieldBonus = 0.9;
// *Uneven gradient* (session 25): a strand candidate `off_gradient` only
// by windows of uneven slopes (`PaintStep::uneven_slopes`) is not refused
// but left to the scorer: its hand cost is put just over max_join_cost
// (kUnevenCostBase above it, plus kUnevenCostShare of the cost, so the hand
// cost never joins it and its rivals keep their order) and it joins when
// the scorer's probability reaches kUnevenThreshold. Every paint rule
// tried (a cost for the step beyond the prediction, a gate on the step's
// direction along the predicted change) joined as many wrong pairs as
// right ones; the scorer, never trained on such candidates, still ranks
// the right ones first (dev gradient 2000-2099: of the 230 candidates
// `off_gradient` alone refused, two right ones top at p 0.40 and 0.31, both
// uneven; the best wrong uneven one is at 0.13, wrong even ones reach 0.30).
// Figures in docs/completion-record.md, "Session 25".
constexpr double kUnevenCostBase = 0.01;
constexpr double kUnevenCostShare = 0.5;

// Joins across a cut of ink only (`Edge::ink`, find_ink_edges): the pieces
// face each other across a crossing tip, so their cut chords are short (at
// most kMaxInkJoinGap px on average), and pieces of flat paint step at most
// kMaxInkFlatStep RGB, back hair too (no occluder says which pieces lie
// where, only the paint and the outline).
constexpr double kMaxInkJoinGap = 16.0;
constexpr double kMaxInkFlatStep = 0.5;

double colour_step_cost(const PaintStep& s) {
  return (s.flat ? kFlatStepWeight : kColourStepWeight) * s.step / 30.0;
}

bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  auto orient = [](const Vec2& p, const Vec2& q, const Vec2& r) {
    return (q - p).x() * (r - p).y() - (q - p).y() * (r - p).x();
  };
  const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a),
               o4 = orient(c, d, b);
  return o1 * o2 < 0 && o3 * o4 < 0;
}

// The distance of two regions' flat paints (RGB): each flat colour of one to
// the nearest of the other's, the worst, the smaller way round.
double region_flat_distance(const RegionPaint& a, const RegionPaint& b) {
  if (a.flats.empty() || b.flats.empty()) return std::numeric_limits<double>::infinity();
  auto one_way = [](const RegionPaint& x, const RegionPaint& y) {
    double worst = 0.0;
    for (const Eigen::Vector3d& c : x.flats) {
      double best = std::numeric_limits<double>::infinity();
      for (const Eigen::Vector3d& d : y.flats) best = std::min(best, (c - d).norm());
      worst = std::max(worst, best);
    }
    return worst;
  };
  return std::min(one_way(a, b), one_way(b, a));
}

// Per flat-painted region, how many other flat-painted regions share its
// paint (within kRarePaintMatch RGB).
std::map<int, int> paint_sharing(const std::map<int, RegionPaint>& paints) {
  std::vector<const std::pair<const int, RegionPaint>*> flat;
  for (const auto& entry : paints)
    if (entry.second.exact_share >= kRarePaintFlatShare && !entry.second.flats.empty())
      flat.push_back(&entry);
  std::map<int, int> sharing;
  if (flat.size() < kRarePaintRegions) return sharing;
  for (std::size_t i = 0; i < flat.size(); ++i) {
    sharing[flat[i]->first];
    for (std::size_t j = i + 1; j < flat.size(); ++j)
      if (region_flat_distance(flat[i]->second, flat[j]->second) <= kRarePaintMatch) {
        ++sharing[flat[i]->first];
        ++sharing[flat[j]->first];
      }
  }
  return sharing;
}

}  // namespace

std::vector<Join> match_edges(const Context& ctx, const std::vector<Edge>& edges,
                              const cv::Mat& face, RegionTones& tones, RegionFields& fields,
                              const std::function<bool(int, int)>& try_join,
                              const std::function<bool(int, int)>& joined) {
  const Options& o = *ctx.options;
  // Back hair: regions above no region. Only the face hides back hair; a
  // strand lying on the face is drawn over it, so the face between two of
  // its pieces means they are not one strand.
  const std::set<int> front = ctx.front();
  const double max_angle = o.max_join_angle_deg * M_PI / 180.0;
  std::vector<BankCrossings> crossings(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i)
    if (edges[i].atoms.size() == 1 && edges[i].ink.empty())
      crossings[i] = cross_occluders(ctx, edges[i]);
  std::vector<EdgePaint> paints(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) paints[i] = edge_paint(ctx, edges[i]);
  std::map<int, RegionPaint> region_paints;
  auto region_paint_of = [&](int region) -> const RegionPaint& {
    auto it = region_paints.find(region);
    if (it == region_paints.end())
      it = region_paints.emplace(region, region_paint(ctx, region)).first;
    return it->second;
  };
  for (const auto& [id, info] : ctx.regions) region_paint_of(id);
  const Eigen::Vector3d shadow = shadow_ratio(region_paints);
  // Session 31: two-tone (a shadow ratio) and gradient (no cel paint)
  // drawings, told from the paint, have their own net (join_scorer.h).
  const bool shaded = shaded_drawing(tones, fields, shadow);
  // The learned scorer (join_scorer.h) sees candidates up to its band's top.
  const JoinScorerOptions& scorer = o.join_scorer;
  const bool scoring = scorer.enabled || ctx.join_log != nullptr;
  // Session 29: up to rescue_high where the retrained net judges over the
  // band (and where candidates are recorded, for its training).
  const bool rescue =
      scorer.rescue_high > scorer.band_high &&
      ((scorer.enabled && rescue_threshold_for(scorer, tones.screentone(), shaded) < 1) ||
       ctx.join_log != nullptr);
  const double limit = !scoring ? o.max_join_cost
                       : rescue ? std::max(o.max_join_cost, scorer.rescue_high)
                                : std::max(o.max_join_cost, scorer.band_high);
  const double wide_limit = std::max(limit, scorer.wide_band_high);
  // Session 29: no wide candidates on screentone drawings but to record
  // them: there the wide net's joins on dev screentone 2000-2099 were 6
  // right pairs and 2 wrong ones over both relations (none right with the
  // layering's); on dev mixed, flat and two-tone 56 right and 6 wrong.
  const double wide_max_angle =
      tones.screentone() && ctx.join_log == nullptr ? 0.0 : scorer.max_angle_deg * M_PI / 180.0;
  const std::map<int, int> sharing =
      tones.screentone() ? std::map<int, int>{} : paint_sharing(region_paints);
  // One flat paint on both pieces that few regions share (kRarePaintBonus).
  auto rare_paint = [&](int ra, int rb, const PaintStep& st) {
    if (!st.flat || st.step > kRarePaintStep || (!front.count(ra) && !front.count(rb)))
      return false;
    const auto ia = sharing.find(ra), ib = sharing.find(rb);
    return ia != sharing.end() && ib != sharing.end() &&
           std::max(ia->second, ib->second) <= kRarePaintSharing;
  };
  // Pixels of the back pieces in `lowest` painted unlike both a and b
  // (screentone: the dots' tones measured and another tone than both).
  auto other_back_share = [&](int ra, int rb, const std::map<int, int>& lowest) {
    double n = 0.0;
    for (const auto& [l, count] : lowest) {
      const bool other = tones.screentone()
                             ? tones.match(l, ra) == RegionTones::Match::kOther &&
                                   tones.match(l, rb) == RegionTones::Match::kOther
                             : (ctx.regions.at(l).colour - ctx.regions.at(ra).colour).norm() >
                                       kOtherBackColourStep &&
                                   (ctx.regions.at(l).colour - ctx.regions.at(rb).colour).norm() >
                                       kOtherBackColourStep;
      if (other) n += count;
    }
    return n;
  };
  std::map<int, int> edge_count;
  for (const Edge& e : edges) edge_count[e.region] += e.atoms.size() == 1;
  std::vector<Join> candidates;
  std::vector<std::optional<JoinTerms>> terms_of;
  // Session 31 (JoinScorerOptions::side_threshold): side-tangent candidates
  // off screentone, their edges' copies and the edges they copy.
  const bool sides = scorer.enabled && scorer.side_threshold < 1 && !tones.screentone();
  // Session 35: angle refusals' second chances, where their net may join
  // them or where candidates are recorded with the scorer off (its
  // training, train_join_scorer collect); recorded with the scorer on and
  // the option off, the candidates are main's.
  const bool retries =
      scorer.enabled ? scorer.angle_refusal_threshold < 1 : ctx.join_log != nullptr;
  // Session 36: cover refusals' second chances, likewise; by default only
  // on two-tone and gradient drawings (cover_refusal_all_shadings); session
  // 37: on flat and screentone ones by their own net and bars.
  const bool cover_retries = scorer.enabled
                                 ? cover_refusal_bar(scorer, tones.screentone(), shaded) < 1
                                 : ctx.join_log != nullptr;
  std::vector<Edge> side_edges;
  std::vector<int> side_origin;
  // Session 40: the candidates' rasters (join_raster.h) on several threads.
  // A first pass collects them, stopping each candidate where its rasters
  // begin; the second goes through every pair again, in order, and reads
  // each answer where it would have computed it. One thread: one pass,
  // each raster computed in place.
  const bool parallel = o.threads > 1;
  std::vector<PatchJob> jobs;
  std::deque<Edge> job_edges;  // side-tangent copies the jobs point to
  std::vector<PatchRaster> rasters;
  std::size_t next_raster = 0;
  for (int pass = parallel ? 0 : 1; pass < 2; ++pass) {
    const bool collecting = pass == 0;
    if (!collecting && parallel) rasters = raster_patches(ctx, front, face, jobs, o.threads);
    for (std::size_t i = 0; i < edges.size(); ++i)
      for (std::size_t j = i + 1; j < edges.size(); ++j) {
        const Edge& ea = edges[i];
        const Edge& eb = edges[j];
        if (ea.region == eb.region) continue;
        // Options::trace_joins: the pair's stage, set by the rule that drops it.
        const int traced =
            ctx.join_trace && !collecting ? static_cast<int>(ctx.join_trace->size()) : -1;
        if (traced >= 0) ctx.join_trace->push_back({ea.region, eb.region});
        const auto drop = [&](JoinStage stage) {
          if (traced >= 0) (*ctx.join_trace)[traced].stage = stage;
        };
        if (ctx.keeps_apart(ea.region, eb.region)) {
          drop(JoinStage::kKeptApart);
          continue;
        }
        // An ink edge joins only a region it faces across the ink.
        const bool ink = !ea.ink.empty() || !eb.ink.empty();
        if (ink && !ea.ink.count(eb.region) && !eb.ink.count(ea.region)) {
          drop(JoinStage::kInkFacing);
          continue;
        }
        const double colour = (ea.colour - eb.colour).norm();
        if (colour > o.max_colour_distance) {
          drop(JoinStage::kColour);
          continue;
        }
        BankJoin bank;
        if (ea.atoms.size() == 1 && eb.atoms.size() == 1 && !ink)
          bank = bank_join(crossings[i], crossings[j], ea, eb);
        // p_a ↔ q_b and p_b ↔ q_a: the outlines traverse both pieces the same way.
        const Vec2 c1 = eb.q - ea.p, c2 = ea.q - eb.p;
        double angles[4] = {angle(ea.tangent_p, c1), angle(-eb.tangent_q, c1),
                            angle(eb.tangent_p, c2), angle(-ea.tangent_q, c2)};
        double worst = *std::max_element(angles, angles + 4);
        const double wide = std::max(ea.width, eb.width), narrow = std::min(ea.width, eb.width);
        // A wide piece's side under a strand (tangents only guessed) is no cut
        // across a strand: on the annotated cases such edges joined the cap to
        // the bangs in front of it.
        const bool cut_pair = !ea.guessed && !eb.guessed && wide > 0 &&
                              narrow / wide >= o.min_width_ratio &&
                              !segments_cross(ea.p, eb.q, eb.p, ea.q);
        // A nub's tangents say nothing; the other piece's alone (its two
        // angles: a's are 0 and 3, b's 1 and 2).
        std::optional<double> one_sided;
        if (cut_pair && worst > max_angle) {
          const double side_a = std::max(angles[0], angles[3]);
          const double side_b = std::max(angles[1], angles[2]);
          auto nub = [&](const Edge& e) {
            return front.count(e.region) > 0 &&
                   ctx.regions.at(e.region).pixels < kNubDepth * e.width * e.width;
          };
          const double limit_one = kOneSidedAngleDeg * M_PI / 180.0;
          if (nub(ea) && side_b <= limit_one) one_sided = side_b;
          if (nub(eb) && side_a <= limit_one && (!one_sided || side_a < *one_sided))
            one_sided = side_a;
        }
        // A cut of ink only runs across a strand, not along it: both pieces
        // reach at least as deep behind it as a nub (pixels ≥ kNubDepth ×
        // width²); a run along a strand's side beside another strand, ink
        // between them all along, is as long as the strand and as shallow.
        const bool across =
            !ink || (ctx.regions.at(ea.region).pixels >= kNubDepth * ea.width * ea.width &&
                     ctx.regions.at(eb.region).pixels >= kNubDepth * eb.width * eb.width &&
                     0.5 * (c1.norm() + c2.norm()) <= kMaxInkJoinGap);
        const bool strand_like = cut_pair && across && (worst <= max_angle || one_sided);
        // Over the angle limit but within the scorer's (JoinScorerOptions::max_angle_deg).
        const bool wide_angle =
            scoring && cut_pair && across && !strand_like && worst <= wide_max_angle;
        // Session 31: refused by the angle with the edges' own tangents, an
        // edge whose tangents are unreliable (Edge::unreliable) may take its
        // side tangent for both ends; the choice with the smallest worst angle,
        // if within the limit, is a candidate the scorer alone may join.
        const double own_worst = worst;
        Edge side_a, side_b;
        bool side = false;
        if (sides && cut_pair && across && !strand_like && !wide_angle && !ink &&
            bank.share < kMinBankShare) {
          auto usable = [](const Edge& e) { return e.unreliable && e.side_tangent.norm() > 0; };
          double best = worst;
          for (int choice = 1; choice <= 3; ++choice) {
            const bool on_a = choice & 1, on_b = choice & 2;
            if ((on_a && !usable(ea)) || (on_b && !usable(eb))) continue;
            const Vec2 ap = on_a ? ea.side_tangent : ea.tangent_p;
            const Vec2 aq = on_a ? ea.side_tangent : ea.tangent_q;
            const Vec2 bp = on_b ? eb.side_tangent : eb.tangent_p;
            const Vec2 bq = on_b ? eb.side_tangent : eb.tangent_q;
            const double tried[4] = {angle(ap, c1), angle(-bq, c1), angle(bp, c2), angle(-aq, c2)};
            const double w = *std::max_element(tried, tried + 4);
            if (w > max_angle || w >= best) continue;
            best = w;
            side = true;
            side_a = ea, side_b = eb;
            side_a.tangent_p = ap, side_a.tangent_q = aq;
            side_b.tangent_p = bp, side_b.tangent_q = bq;
            std::copy(tried, tried + 4, angles);
          }
          if (side) worst = best;
        }
        // Session 35 (JoinScorerOptions::angle_refusal_threshold): what no
        // side tangent brings within the limit (screentone drawings too) is
        // tried with other tangents for each edge; judged by its own net.
        RetriedTangents retried;
        if (retries && !side && cut_pair && across && !strand_like && !wide_angle && !ink &&
            bank.share < kMinBankShare) {
          retried = retry_tangents(ea, eb, c1, c2, max_angle,
                                   scorer.angle_refusal_turned || !scorer.enabled);
          if (retried.found) {
            side = true;
            side_a = ea, side_b = eb;
            side_a.tangent_p = retried.a.p, side_a.tangent_q = retried.a.q;
            side_b.tangent_p = retried.b.p, side_b.tangent_q = retried.b.q;
            std::copy(retried.angles, retried.angles + 4, angles);
            worst = retried.worst;
          }
        }
        const Edge& a = side ? side_a : ea;
        const Edge& b = side ? side_b : eb;
        if (traced >= 0) (*ctx.join_trace)[traced].angle_deg = worst * 180.0 / M_PI;
        if (!strand_like && !wide_angle && !side && bank.share < kMinBankShare) {
          drop(a.guessed || b.guessed                              ? JoinStage::kGuessed
               : !(wide > 0 && narrow / wide >= o.min_width_ratio) ? JoinStage::kWidthRatio
               : !cut_pair                                         ? JoinStage::kCrossingChords
               : !across                                           ? JoinStage::kInkAcross
                                                                   : JoinStage::kAngle);
          continue;
        }
        // Why the candidate is dropped if its cost ends over the limit.
        JoinStage why = JoinStage::kHandCost;
        Join join;
        join.edge_a = static_cast<int>(i);
        join.edge_b = static_cast<int>(j);
        double cost = std::numeric_limits<double>::infinity();
        std::optional<JoinTerms> terms;
        // Session 36 (JoinScorerOptions::cover_refusal_threshold): refused
        // only by the cover, kept for its own net.
        bool cover_retry = false;
        const PaintStep step = paint_step(a, b, paints[i], paints[j], region_paint_of(a.region),
                                          region_paint_of(b.region), shadow);
        // Two pieces of flat paint stepping more than kMaxFlatStrandStep, one
        // of them a strand (above some region), are two strands; so are two
        // linear pieces stepping more than their gradient explains.
        // Off the gradient by uneven windows: for the scorer (kUnevenThreshold).
        const bool uneven = scoring && step.off_gradient && step.uneven_slopes;
        const bool other_paint = (step.flat && step.step > kMaxFlatStrandStep &&
                                  (front.count(a.region) > 0 || front.count(b.region) > 0)) ||
                                 (step.off_gradient && !uneven) ||
                                 (ink && step.flat && step.step > kMaxInkFlatStep);
        if ((strand_like || wide_angle || side) && other_paint) why = JoinStage::kOtherPaint;
        if ((strand_like || wide_angle || side) && !other_paint) {
          // The hidden part keeps a strand's width: half-way along the joins its
          // width lies near the widths at the two cuts (criterion 3 of §5.1 seen
          // from the whole join, not only its ends).
          const CubicBezier first = join_bezier(a.p, a.tangent_p, b.q, -b.tangent_q);
          const CubicBezier second = join_bezier(b.p, b.tangent_p, a.q, -a.tangent_q);
          const double middle = (first.point(0.5) - second.point(0.5)).norm();
          const double ends = 0.5 * (a.width + b.width);
          const double bulge = std::abs(std::log(std::max(middle, 1.0) / std::max(ends, 1.0)));
          const double gap = 0.5 * (c1.norm() + c2.norm());
          // Tangent continuity is the most reliable cue (§5.1 criterion 3);
          // colour varies with shading and widths with the angle of the cut.
          const double mean_angle =
              one_sided ? *one_sided : (angles[0] + angles[1] + angles[2] + angles[3]) / 4;
          const double worst_angle = one_sided ? *one_sided : worst;
          cost = (one_sided ? kOneSidedCost : 0.0) + 2.0 * mean_angle / max_angle +
                 worst_angle / max_angle + 0.4 * colour / o.max_colour_distance +
                 0.5 * (1.0 - narrow / wide) + 0.5 * std::min(gap / wide, 3.0) +
                 kBulgeWeight * bulge;
          // §5.1 matches edges "around a common occluder"; a gap under two
          // overlapping occluders is allowed but costs a little more.
          bool common = ink;  // the ink is the one occluder
          for (int occ : a.occluders) common = common || b.occluders.count(occ) > 0;
          if (!common) cost += kNoCommonOccluderCost;
          // A colour step the paint does not explain: two flat pieces of
          // different colours are two strands; a cel band or a gradient
          // explains its own step (`paint_step`).
          cost += colour_step_cost(step);
          // A gradient seen on both sides that carries on across the gap is
          // what a person follows under the occluder.
          if (step.shading_continues) cost -= kShadingContinuesBonus;
          // One paint that few regions share carries on across the gap.
          const bool rare = rare_paint(a.region, b.region, step);
          if (rare) cost -= kRarePaintBonus;
          // One gradient paints both pieces (kOneFieldBonus).
          if (!step.flat && !rare && !tones.screentone() &&
              fields.step(a.region, b.region) <= kOneFieldStep)
            cost -= kOneFieldBonus;
          // Screentone: the colour says nothing there, the dots' tone does.
          const double tone_cost = tone_join_cost(tones, a.region, b.region);
          cost += tone_cost;
          if (uneven) cost = o.max_join_cost + kUnevenCostBase + kUnevenCostShare * cost;
          if (traced >= 0) (*ctx.join_trace)[traced].hand_cost = cost;
          if (cost <= (wide_angle ? wide_limit : limit)) {  // before the costly coverage raster
            join.behind_face = !face.empty() && !front.count(a.region) && !front.count(b.region);
            PatchJob job;
            job.a = &a, job.b = &b;
            job.cost = cost, job.limit = limit, job.narrow = narrow, job.wide = wide;
            job.ink = ink;
            job.behind_face = join.behind_face;
            job.may_retry = cover_retries && strand_like && !side && cost <= scorer.band_high;
            // Options::join_arm_shares: another shape lets a candidate in
            // only at a hand cost under max_join_cost: the scorer never saw
            // such patches, and in its band they let in wrong joins (dev mixed
            // 2000: +7 right / +0 wrong by the hand cost, −1 / +2 more from
            // the band). Not on screentone drawings: dev screentone 2099 took
            // a wrong one at hand cost 2.38 (+6 wrong pairs with the
            // layering's relations), and with the screentone net's veto
            // (session 30) the shapes there still bought 32 right and 18
            // wrong pairs over six dev runs.
            job.reshape =
                !o.join_arm_shares.empty() && !tones.screentone() && cost <= o.max_join_cost;
            // Options::cover_fringe: on screentone the outlines' light fringe
            // lies in no region of the map; read as the nearest region's, it
            // counts under the occluders. Only where every occluder over the
            // patch lies above a piece by the user's orders, or, without
            // them, by the layering's at a low hand cost: at any cost the
            // fringe let in wrong joins at about a third of those it added
            // (dev screentone 2000 +53 right / +21 wrong pairs).
            job.users = !ctx.user_above.empty();
            job.fringe =
                !ctx.cover_labels.empty() && (job.users || cost <= o.cover_fringe_layering_cost);
            // Options::corridor_width: some strand may fit under the
            // occluders from cut to cut though this patch does not (§5 asks
            // that the hidden part lie there, not that it be these Béziers).
            // The patch's cover term stays in the cost, so a poor patch lands
            // in the scorer's band or over it, and the retrained net has the
            // last word at any cost (score_candidates): unguarded, joins64's
            // corridor (session 29) took wrong joins under the limit on fresh
            // sets. Not on screentone drawings: the retrained net was not
            // made for them, and joins68's shapes took wrong joins there.
            job.corridor =
                o.corridor_width > 0 && scorer.enabled && !tones.screentone() && !wide_angle;
            job.retry_shape = scoring && job.may_retry && !o.join_arm_shares.empty();
            job.front_counts = join.behind_face;
            job.by_label = scoring;
            job.trace = ctx.join_trace != nullptr;  // none in the first pass (`traced`)
            if (collecting) {
              if (side) {  // the copies outlive this pass
                job_edges.push_back(a);
                job.a = &job_edges.back();
                job_edges.push_back(b);
                job.b = &job_edges.back();
              }
              jobs.push_back(job);
              continue;
            }
            PatchRaster r =
                parallel ? std::move(rasters[next_raster++]) : raster_patch(ctx, front, face, job);
            join.patch = std::move(r.patch);
            double cover = r.cover;
            const int hidden = r.hidden;
            const std::map<int, int>& lowest = r.lowest;
            std::map<int, int>& under_by = r.under_by;
            CoverMisses& misses = r.misses;
            misses.a = &a, misses.b = &b;  // the job's may be the first pass's copies
            join.corridor = r.corridor;
            if (traced >= 0) {
              JoinTrace& t = (*ctx.join_trace)[traced];
              t.hole_background = r.holes.hole_background;
              t.hole_below = r.holes.hole_below;
              t.hole_sibling = r.holes.hole_sibling;
              t.hole_other = r.holes.hole_other;
            }
            const bool over_other_back =
                hidden > 0 &&
                other_back_share(a.region, b.region, lowest) / hidden > kMaxOtherBackShare;
            if (traced >= 0) (*ctx.join_trace)[traced].cover = cover;
            const bool uncovered = cover < o.min_join_coverage && !join.corridor;
            if (uncovered)
              why = JoinStage::kCover;
            else if (over_other_back)
              why = JoinStage::kOtherBack;
            // Session 36: a candidate with its own tangents within the
            // angle limit, refused by the cover alone, its hand cost before
            // the cover term in the band.
            cover_retry = cover_retries && uncovered && !over_other_back && strand_like && !side &&
                          cost <= scorer.band_high;
            cost = (uncovered && !cover_retry) || over_other_back
                       ? std::numeric_limits<double>::infinity()
                       : cost + kUncoveredCost * (1.0 - cover);
            if (scoring && std::isfinite(cost)) {
              terms = JoinTerms{mean_angle / max_angle,
                                worst_angle / max_angle,
                                colour / o.max_colour_distance,
                                std::max(0.0, colour - (a.colour_spread + b.colour_spread)) / 30.0,
                                1.0 - narrow / wide,
                                std::min(gap / wide, 3.0),
                                bulge,
                                common,
                                cover,
                                cost,
                                gap,
                                wide,
                                step.step,
                                step.flat,
                                step.shading_continues,
                                rare,
                                tone_cost,
                                one_sided.has_value()};
              add_scorer_terms(tones, a.region, b.region, under_by, &*terms);
              // Session 39: the pieces' own fields across the gap, on shaded
              // drawings painted by fields (not cel paint).
              if (shaded && !step.flat && !fields.cels().cel_drawing()) {
                const auto [most, larger] =
                    fields.cross_miss(a.region, 0.5 * (a.p + a.q), b.region, 0.5 * (b.p + b.q));
                if (std::isfinite(most)) {
                  terms->field_cross_max = most;
                  terms->field_cross_larger = larger;
                }
              }
              if (retried.found)
                add_retry_terms(ea, eb, retried, own_worst / max_angle, o.fit_length, &*terms);
              if (cover_retry) {
                // The cover of joins68's best arm shares, measured here
                // whatever the guards of Options::join_arm_shares say.
                double shape_cover = cover;
                if (!o.join_arm_shares.empty())
                  shape_cover =
                      std::max(shape_cover, r.reshaped_cover >= 0 ? r.reshaped_cover
                                                                  : r.retry_shape_cover.value());
                add_cover_terms(misses, shape_cover, &*terms);
              }
            }
          }
        }
        if (collecting) continue;  // what follows is the second pass's
        // Across the banks of one occluder the rays themselves are the hidden
        // part; the more of them land on the other piece, the surer the join.
        // The paint is compared as for strand joins (session 10: a two-tone
        // back piece was bank-joined across a strand to a piece 39 RGB off).
        const double bank_cost = kBankBaseCost + kBankShareWeight * (1.0 - bank.share) +
                                 0.4 * colour / o.max_colour_distance + colour_step_cost(step);
        // A window of back hair (a piece above no region) is joined only in one
        // paint, as the path joins join back-hair slivers.
        if (bank.window && (!front.count(a.region) || !front.count(b.region)) &&
            step.step > kMaxBackWindowStep)
          bank.share = 0.0;
        // A cover refusal's second chance yields to the bank join as the
        // refusal itself would.
        const double strand_cost = cover_retry ? std::numeric_limits<double>::infinity() : cost;
        if (bank.share >= kMinBankShare && (bank_cost < strand_cost || wide_angle)) {
          cost = bank_cost;
          cover_retry = false;
          join.patch.clear();
          join.behind_face = false;
          join.corridor = false;
          join.bands = std::move(bank.bands);
          terms.reset();
        } else if (wide_angle && std::isfinite(cost)) {
          join.wide = true;
        }
        // Scored with its side tangents: its edges are copies at the end of
        // the scored list, mapped back to their own after scoring.
        // Unscored (over the limit before the cover), it is dropped.
        if (side && !terms) cost = std::numeric_limits<double>::infinity();
        if (side && terms && cost <= limit) {
          join.side_tangent = true;
          join.angle_retry = retried.found;
          join.edge_a = static_cast<int>(edges.size() + side_edges.size());
          side_edges.push_back(std::move(side_a));
          join.edge_b = static_cast<int>(edges.size() + side_edges.size());
          side_edges.push_back(std::move(side_b));
          side_origin.push_back(static_cast<int>(i));
          side_origin.push_back(static_cast<int>(j));
        }
        // A cover refusal's second chance is scored whatever its hand cost
        // with the cover term (its net alone decides).
        join.cover_retry = cover_retry && terms.has_value();
        if (cost > (join.wide ? wide_limit : limit) && !join.cover_retry) {
          drop(why);
          continue;
        }
        join.cost = cost;
        join.trace = traced;
        if (traced >= 0) (*ctx.join_trace)[traced].hand_cost = cost;
        join.uneven_gradient = uneven && join.bands.empty();
        candidates.push_back(std::move(join));
        terms_of.push_back(terms);
      }
  }
  if (scoring && side_edges.empty())
    score_candidates(ctx, edges, front, edge_count, terms_of, tones.screentone(), shaded,
                     shadow.squaredNorm() > 0, &candidates);
  if (scoring && !side_edges.empty()) {
    std::vector<Edge> scored = edges;
    scored.insert(scored.end(), side_edges.begin(), side_edges.end());
    score_candidates(ctx, scored, front, edge_count, terms_of, tones.screentone(), shaded,
                     shadow.squaredNorm() > 0, &candidates);
    const int own = static_cast<int>(edges.size());
    for (Join& x : candidates)
      for (int* e : {&x.edge_a, &x.edge_b})
        if (*e >= own) *e = side_origin[*e - own];
  }
  if (ctx.join_trace)
    for (const Join& x : candidates) {
      if (x.trace < 0) continue;
      JoinTrace& t = (*ctx.join_trace)[x.trace];
      t.probability = x.probability;
      if (x.cost <= o.max_join_cost) continue;
      // Asked under the band: vetoed; over it: not rescued (the hand cost).
      const bool asked = x.probability >= 0;
      t.stage = x.cover_retry                              ? JoinStage::kCover
                : x.wide                                   ? JoinStage::kWideRefused
                : x.uneven_gradient && asked               ? JoinStage::kUnevenRefused
                : asked && t.hand_cost < scorer.band_low   ? JoinStage::kVetoed
                : asked && t.hand_cost <= scorer.band_high ? JoinStage::kBandRefused
                                                           : JoinStage::kHandCost;
    }
  return choose_joins(ctx, edges, tones, shaded, std::move(candidates), try_join, joined);
}

}  // namespace hair25d::completion::detail
