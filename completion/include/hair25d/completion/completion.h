// Cartoon hair completion (paper §5): from hair regions and their depth
// relations to whole strands — pieces split by an occluder joined (case 1),
// occluded roots and tips grown under their occluders (cases 2 and 3) — with
// the hidden colours inpainted and the background behind the hair filled.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hair25d/completion/active_contour.h"
#include "hair25d/completion/background.h"
#include "hair25d/completion/inpaint.h"
#include "hair25d/completion/join_scorer.h"
#include "hair25d/core/geometry.h"
#include "hair25d/core/hair_model.h"
#include "hair25d/core/image.h"
#include "hair25d/core/progress.h"

namespace hair25d::completion {

struct Options {
  // Outline pixels (label 0, dark) are given to the nearest region within this
  // many pixels first (FORMATS.md).
  int outline_reach = 4;
  int dark_luma = 140;  // a pixel darker than this (0..255) can be an outline pixel
  // The cover test (min_join_coverage) reads label-0 pixels this near a
  // labelled one as that label's, whatever their luma: the outlines' light
  // anti-aliased fringe lies in no region of the map. 0 reads them as holes.
  // Only on screentone drawings (there the fringe is paper-white and the
  // cover class is 8 times flat's: dev 64 lost links against 8) and only
  // where the occluders over the patch lie above a piece (joins.cpp
  // `occluders_above_pieces`): by the user's orders when there are some, else by
  // the layering's and at a hand cost under cover_fringe_layering_cost.
  int cover_fringe = 2;
  // With the layering's orders the fringe let in wrong joins at a third of
  // those it added at any cost (dev screentone 2000: +53 right / +21 wrong
  // pairs); under hand cost 1.5 it added 50 right and 3 wrong pairs on dev
  // screentone and mixed 2000 and 3000 (session 32). 0: never.
  double cover_fringe_layering_cost = 1.5;
  // Screentone: two pieces whose dots step more than this (a share of the
  // larger dot mass) while one runs along the face for most of its outline
  // are a strand lying on the face and a piece of something else: the
  // back-hair passes (path, back paint, face and body joins) leave them
  // apart. RegionTones's "one tone" reaches 0.04; back hair took strands on
  // the face at 0.030-0.039 (dev screentone 2003, 2009), a face-bordering
  // piece of its own at 0.021 (3070). 0: no such test. Session 33: at
  // 0.025 it removed 45 wrong and 12 right pairs over the helper's dev and
  // fresh runs and the lead's held and fresh 10700 ones, but 56 right and
  // 1 wrong over the lead's fresh 10200 runs (back pieces split from the
  // back hair in 10254 and 10279): off (docs/completion-record.md).
  double face_piece_mass_step = 0.0;
  // Screentone: a tone path join of two front pieces (mass_paths.cpp) needs
  // at least this many landings (distinct pixels of one piece reached by
  // the paths under the common occluders) per square root of the smaller
  // piece's pixels. A strand passing under an occluder lands across its
  // whole width; two strands side by side, or a tip reaching past a
  // neighbour's end, meet on a few pixels. 0: no such test (only the
  // path joins' fixed three landings). Session 38 (joins92): at 0.3 dev
  // screentone and mixed 2000 and 3000 (both relations) lost 11 wrong
  // pairs and no right one, fresh screentone and mixed 31400-31599 10
  // wrong and no right one; at 0.5 dev lost 13 wrong and 3 right, at
  // 0.65 17 wrong and 5 right. Off (lead, session 38): at 0.3 the lead's
  // held and fresh sets lost 39 right pairs and 12 wrong ones, most of the
  // right ones in long strands whose one tone path link carries 4-6 pairs
  // (fresh screentone 31600 -24 / -4, 10200 -9 / -4, mixed 31000 -6 / 0;
  // docs/completion-record.md).
  double tone_path_landing_share = 0.0;
  // A region's boundary pixel is occluded when an occluder pixel lies within
  // this many pixels; occluding runs closer than `merge_gap` are merged.
  int occluder_reach = 2;
  double merge_gap = 8.0;        // pixels along the boundary
  double min_edge_length = 4.0;  // pixels; shorter occluding runs are ignored
  double tangent_arm = 10.0;     // pixels of visible outline used for a tangent

  // Case 1 matching (§5.1).
  double max_join_angle_deg = 70.0;   // tangent vs the join chord, at each end
  double max_colour_distance = 90.0;  // RGB distance of the pieces' colours
  double min_join_coverage = 0.85;    // share of the join patch under occluders
  // Tangent arms (shares of the chord, at each piece's end) tried for the
  // join patch's two Bézier sides when the patch of join_bezier's arms (a
  // third) lies under min_join_coverage: the hidden strand may take any
  // smooth path under the occluders, and the patch of the best covered
  // shape is judged and drawn; such a candidate joins by the hand cost
  // alone (not the scorer's band), off screentone drawings, from a patch
  // cover of 0.6 (joins.cpp). Empty: the third only. Session 30 (joins68):
  // +101 right pairs over 22 dev and fresh runs of both relations, 5 wrong
  // added and 5 removed (docs/completion-record.md).
  std::vector<double> join_arm_shares = {0.2, 1.0 / 3.0, 0.5, 0.7};
  // A strand candidate whose patch (after join_arm_shares) lies under
  // min_join_coverage is let in when a corridor corridor_width × the
  // narrower cut wide runs under the occluders from cut to cut (the hidden
  // strand need not be the patch's shape), off screentone drawings; it keeps
  // its patch's cover term in the hand cost and joins only when the
  // retrained net's p (retrained_join_scorer) reaches
  // corridor_min_probability, whatever its cost. 0: no corridor. Session
  // 31 (joins70): at 0.5 / 0.9, +28 right pairs and 3 wrong added, 3
  // removed over 12 dev runs of both relations, +19 / 0 over 8 fresh ones
  // (docs/completion-record.md): off, little gain at the bar's precision.
  double corridor_width = 0.0;
  double corridor_min_probability = 0.9;
  double min_width_ratio = 0.2;  // narrower / wider occluding edge
  // A candidate refused only because one of its cuts already joins another
  // piece (its atoms taken, each once) joins too when the scorer gives it at
  // least second_partner_p: one cut may face two pieces of a strand, as a
  // back-hair piece's cut faces two pieces of the back hair split by a
  // strand, and the greedy one-to-one matching let only the cheaper join in
  // (census "atom taken: right rival", dev screentone 2000: 9 links, 48
  // pairs). 0: never. Session 33: at 0.95, +137 right / +2 wrong pairs over
  // 14 dev runs (docs/completion-record.md).
  double second_partner_p = 0.95;
  double max_join_cost = 2.4;
  JoinScorerOptions join_scorer;  // a learned scorer for ambiguous strand joins
  // Back-hair pieces on opposite sides of the face joined across it (the
  // face hides them as a strand would; it is no region).
  bool face_joins = true;
  // Back-hair pieces joined through the regions lying above both of them
  // (a path under their common occluders, the colour continuing across).
  bool path_joins = true;
  // Weakly ordered touching pieces of one paint (off screentone) whose side
  // outlines, read on slices along the line between them up to 24 px from
  // it, run on across it are read as one strand's halves (a seam), where the
  // angles round the meeting points say nothing. Off by default: with the
  // layering's relations it gains recall on every set (dev mixed 2000-2099
  // 0.672 -> 0.679) but cost precision on fresh flat drawings (two seams of
  // two strands on 7000-7099, 0.963 -> 0.961; docs/completion-record.md,
  // "Session 27").
  bool continuation_seams = false;
  // A weak remote order (not the user's, |score| under the firm bar, between
  // regions that do not touch once the outlines are assigned) between two
  // pieces of one paint that a third region lies above, touching both,
  // makes no occluder: the two are likely pieces of one strand on both sides
  // of that occluder, and the order the layering measured across it cuts a
  // run into one piece beside the strand's cut, or turns its strand front
  // hair (session 33, joins77, docs/completion-record.md). Firm ones still
  // do: on dev mixed 2000 one firm such order kept a piece of another strand
  // out of a path join.
  bool remote_across_occluder = false;
  // Two groups of pieces are made one strand (a join, or the layering's
  // equal or seam; never the user's relations refused) only when no piece
  // of one is painted apart from a piece of the other (strand_paint.h: two
  // tones by the dots, two flat paints, two gradients), not only the two
  // pieces a join links. On by default (the lead, session 28): it raised
  // precision on every dev and fresh set measured (fresh mixed 9000-9099
  // with the layering's relations 0.920 -> 0.933) for 8 right pairs fewer
  // against 58 wrong ones fewer over the eight fresh runs; with the recall
  // options on, fresh flat 9100-9199 still lost precision, so they stay off
  // (docs/completion-record.md, "Session 28").
  bool strand_paint = true;
  // Record why each case-1 edge pair was or was not joined
  // (Result::join_trace), for the census of lost joins (eval_joins --census).
  bool trace_joins = false;

  // Cases 2 and 3 (§5.2–5.4).
  ContourOptions contour;
  double fit_length = 16.0;          // pixels of visible outline the Hamiltonian is fitted to
  double fit_regularization = 0.02;  // pull of the fit towards a straight flow (A = 0)
  bool sharp_tips = true;            // case 3 makes a sharp tip (§5.3)

  // Colour (§5.4).
  bool inpaint_strands = true;
  bool inpaint_background = true;
  InpaintOptions inpaint;
  BackgroundOptions background;  // the background behind the hair, filled at full resolution
  int threads = 2;  // strands and background filled by up to this many threads (1 = serial)

  // False, with a message naming the option, its value and the rule, if unusable.
  bool is_valid(std::string* error) const;
};

struct Input {
  const Image* image = nullptr;           // the drawing
  const LabelMap* regions = nullptr;      // hair region ids, 0 = background and outlines
  std::vector<RegionRelation> relations;  // between neighbouring regions
  // Where the head is (strokes.json head_center); without it, the centroid of
  // all hair pixels (hair frames the face, so this falls on the head).
  std::optional<Vec2> head_center;
};

enum class EdgeCase { kJoined, kRoot, kTip, kNotCompleted };
const char* to_string(EdgeCase c);

// One occluding edge of a region and what completion did with it.
struct EdgeReport {
  int region = 0;
  Vec2 p{0, 0}, q{0, 0};  // outermost endpoints
  EdgeCase completion = EdgeCase::kNotCompleted;
  int joined_region = 0;                       // case 1: the region it was joined to
  ContourStop stop = ContourStop::kConverged;  // cases 2, 3
  int hidden_pixels = 0;                       // pixels this edge added under the occluders
};

// How far a case-1 edge pair got in the matching (joins.cpp `match_edges`),
// in the order its rules are applied: the first rule that refused it, or
// the greedy matching's fate. Later stages are nearer to a join.
enum class JoinStage {
  kKeptApart,       // one region directly occludes the other
  kInkFacing,       // an ink edge not facing the other region
  kColour,          // colours further apart than max_colour_distance
  kGuessed,         // an edge's tangents only guessed (a wide piece's side)
  kWidthRatio,      // narrower / wider under min_width_ratio
  kCrossingChords,  // the two cut chords cross
  kInkAcross,       // across ink: too shallow or too far for a cut
  kAngle,           // tangents over the angle limit (and the scorer's)
  kOtherPaint,      // painted apart (flat step, off the gradient)
  kHandCost,        // hand cost (with the cover's) over the limit
  kCover,           // patch under the occluders below min_join_coverage
  kOtherBack,       // behind the face across back hair of another paint
  kWideRefused,     // over the angle limit, the wide scorer refused it
  kUnevenRefused,   // uneven gradient, the scorer refused it
  kBandRefused,     // in the scorer's band, the scorer refused it
  kVetoed,          // under the cost limit, the retrained net refused it (veto_below)
  kAtomTaken,       // an edge already joined by a cheaper candidate
  kTwoTones,        // two tones by the dots (screentone)
  kRefused,         // try_join: a firm order or the strand paint
  kChosen,          // joined
};
const char* to_string(JoinStage s);

// One case-1 edge pair (Options::trace_joins).
struct JoinTrace {
  int region_a = 0, region_b = 0;
  JoinStage stage = JoinStage::kKeptApart;
  double hand_cost = -1.0;       // −1 when not reached
  double angle_deg = -1.0;       // the worst tangent angle to the chords, −1 when not reached
  double probability = -1.0;     // the scorer's, −1 when not asked
  double cover = -1.0;           // share of the patch under occluders, −1 when not measured
  int rival_a = 0, rival_b = 0;  // kAtomTaken: the regions of the join that took the edge
  // Shares of the patch (outside both pieces) under no occluder, by what
  // lies there: the background (or outside the image), a region below a
  // piece, a region under a region lying above a piece (a sibling of the
  // pieces), any other region.
  double hole_background = 0.0, hole_below = 0.0, hole_sibling = 0.0, hole_other = 0.0;
};

struct CompletedStrand {
  std::vector<int> regions;  // source region ids, sorted
  // Crop of the image: 0 outside, 1 visible (the strand's own pixels), 2 completed.
  LabelMap mask;
  Eigen::Vector2i origin{0, 0};  // image pixel of mask(0, 0)
  Polyline outline;              // the completed shape, one closed polygon, pixels
  // The same without the drawn rim the strand carries beyond its regions
  // (their outline's anti-aliased edge, converging lines at a point): the
  // shape its skeleton follows, free of the rim's one-pixel spurs.
  Polyline body;
  Image texture;                  // RGBA crop at `origin`, transparent outside the mask
  std::optional<Vec2> root_hint;  // centre of a completed root, if there is one
  int visible_pixels = 0, completed_pixels = 0;
};

struct Result {
  LabelMap regions;  // the input regions with outline pixels assigned
  std::vector<CompletedStrand> strands;
  std::vector<EdgeReport> edges;
  Image background;        // the drawing with the hair removed and filled
  Vec2 head_center{0, 0};  // used (given or estimated)
  bool head_center_estimated = false;
  int joins = 0, roots = 0, tips = 0;
  // Regions made one strand by "equal" relations (two groups becoming one
  // counts one); with the joins, regions - strands = equal_merges + joins.
  int equal_merges = 0;
  // The layering's weak "equal"s between pieces painted apart, not merged
  // (EqualEvidence in core/hair_model.h; the user's are always merged).
  int refused_equals = 0;
  // Joins refused because the strand they would make holds two pieces
  // painted apart (Options::strand_paint): the regions the join would link
  // and the two pieces measured apart, once per region pair.
  struct PaintRefusal {
    int a = 0, b = 0, piece_a = 0, piece_b = 0;
  };
  std::vector<PaintRefusal> paint_refusals;
  InpaintResult strand_inpaint, background_inpaint;
  std::vector<JoinCandidate> join_candidates;  // with Options::join_scorer.record
  // With Options::trace_joins: every case-1 edge pair of two regions, and
  // the regions that have an occluding or ink edge (sorted).
  std::vector<JoinTrace> join_trace;
  std::vector<int> edge_regions;
  std::string summary;
};

// Completes every strand. Throws hair25d::Error for missing image or regions,
// sizes that differ, relations naming unknown regions or invalid options.
Result complete_strands(const Input& input, const Options& options = {},
                        Progress* progress = nullptr);

// Gives label-0 outline pixels (darker than `dark_luma`) to the nearest region
// within `reach` pixels (FORMATS.md); other pixels keep their label.
LabelMap assign_outline_pixels(const Image& image, const LabelMap& regions, int reach,
                               int dark_luma);

}  // namespace hair25d::completion
