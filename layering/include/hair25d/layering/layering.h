// Cartoon hair layering (paper §4): from a drawing and its region label map to
// a relation (above / below / equal, with a score) for every pair of
// neighbouring regions and a drawing order, optionally with user-fixed pairs.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "hair25d/core/geometry.h"
#include "hair25d/core/hair_model.h"
#include "hair25d/core/image.h"
#include "hair25d/core/progress.h"
#include "hair25d/layering/boundary_graph.h"
#include "hair25d/layering/learned_metric.h"

namespace hair25d::layering {

// Which boundaries meeting at a junction are coupled in Eq. (2).
enum class Coupling {
  kSmoothestPair,  // only the pair continuing most smoothly, if θ >= smooth_angle
  kAllPairs,       // every pair sharing a region, as the paper writes Eq. (2)
  kNone,           // no pairwise term: each boundary follows its own Φ
};

// The unary term of Eq. (2).
enum class Metric {
  kLearned,  // learned_metric (learned_metric.h) over the paper's cues and region shape
  kPaper,    // Φ of Eq. (1) as the paper defines it
};

struct Options {
  Metric metric = Metric::kLearned;
  // The learned log-odds are multiplied by this before Eq. (2), which puts
  // them on the scale of Φ and of the coupling weights φ_ij.
  double learned_scale = 0.5;
  double junction_weight = 0.25;  // w in Eq. (1)
  // Cap of φ_ij = tan(|(θ mod π) − π/2|) in Eq. (2); θ near 0 or π would be infinite.
  double coupling_cap = 0.5;
  Coupling coupling = Coupling::kSmoothestPair;
  double smooth_angle = 2.356194490192345;  // 3π/4: a smooth continuation, radians
  // Width of the drawn lines in pixels; <= 0 estimates it from the outlines
  // of the label map, or from the image when the map has none.
  double line_width = 0.0;
  // A boundary is occluding when its line contrast (grey levels, 0..255) is at
  // least this; <= 0 sets it from the image's own statistics (a fraction of the
  // typical contrast of its boundaries, above its noise level).
  double line_threshold = 0.0;
  double line_threshold_fraction = 0.4;  // of the typical boundary contrast, when automatic
  // Junction angles are measured on a line fitted to the boundary within this
  // arc length of the junction, in line widths ...
  double fit_reach_widths = 6.0;
  // ... and never under this many pixels: the raster's steps are a pixel
  // whatever the line width, so thin lines need a longer fit than 6 widths.
  // 18 (12 before session 11) is the reach of 3-px lines, the scale at which
  // lines of 1.5–2.5 px were always read (their maps measure 3 px wide).
  double fit_reach_min = 18.0;
  // A pair of regions is "equal" when less than this share of their common
  // boundary length is occluding.
  double equal_fraction = 0.5;
  // With the learned metric, a pair is also "equal" when the learned
  // same-depth model (equal_metric) says so for its occluding boundaries,
  // length-weighted: a drawn line between two halves of one strand.
  bool learned_equal = true;
  // ... when that length-weighted mean log-odds exceeds this.
  double equal_log_odds = 0.0;
  // A pair that would be "equal" only because its common boundary is open
  // (under equal_fraction occluding, not the same-depth model's call) is
  // ordered instead when the same-depth model (6c) is sure it is no cusp:
  // when its open boundaries' length-weighted mean same-depth log-odds is
  // below this. Their mean order log-odds (6b) then picks which region is
  // above. A sliver of a strand over another, whose outline the threshold
  // missed, reads about -11 (case1's region 17).
  // -infinity: never (every open pair stays equal, as before session 19).
  double open_order_log_odds = -8.0;
  // With the learned metric, a second stage weighs each boundary's log-odds
  // with the region context (context_metric in learned_metric.h): how each
  // region stands against its other neighbours.
  bool region_context = false;
  // With the learned metric, the label map about each end of an occluding
  // hair boundary is read by a small learned network (junction patches, an
  // addition) and joined with the boundary's log-odds.
  bool junction_patches = true;
  // Give label-0 outline pixels to the regions they separate first (FORMATS.md).
  bool fill_outlines = true;
  // Boundaries between hair and background take part in Eq. (2) (they carry
  // the strands' outlines through junctions); relations with background are
  // never reported.
  bool background_states = true;
  // User decisions kept when re-solving (the studio's "flip this arrow"):
  // their boundaries are clamped to the given relation.
  std::vector<RegionRelation> fixed;

  // False, naming the option, its value and the rule, if unusable.
  bool is_valid(std::string* error) const;
};

// What was measured on one boundary (diagnostics and overlays).
struct BoundaryReport {
  int left = 0, right = 0;         // labels, left/right walking start → end
  double length = 0.0;             // pixels
  double line_contrast = 0.0;      // median grey-level contrast of a dark line on it
  double line_contrast_low = 0.0;  // its lower quartile
  double colour_difference = 0.0;  // paint across it (LineResponse), 0..255
  bool occluding = false;
  double phi_j = 0.0;        // Φ̂_J, left region above right when positive
  double phi_j_start = 0.0;  // its term at the start junction (0 at a cusp)
  double phi_j_end = 0.0;    // its term at the end junction
  double phi_r = 0.0;        // Φ_R / ‖L‖²
  double phi = 0.0;          // Eq. (1)
  BoundaryCues cues;         // what the learned metric is computed from
  BoundaryFeatures features{};
  double learned = 0.0;           // learned_metric(features), log-odds of left above
  double context = 0.0;           // context_differences: left's standing minus right's
  double context_log_odds = 0.0;  // context_metric(learned, context)
  double patch = 0.0;             // junction patch score, both ends, left above
  double patch_log_odds = 0.0;    // learned joined with the patch score
  double patch_equal = 0.0;       // junction patch score of same depth, both ends
  EqualCues equal_cues;           // what the same-depth model is computed from
  EqualFeatures equal_features{};
  double equal = 0.0;  // equal_metric(equal_features) (joined with patch_equal when
                       // junction_patches), log-odds of same depth
  int state = 0;       // +1 left above, −1 right above, 0 no state
};

// Where the relation of a pair is drawn: a point on their longest common
// boundary and the unit normal there pointing from a's side into b's side.
struct RelationAnchor {
  Vec2 point = Vec2::Zero();
  Vec2 normal = Vec2(1, 0);
};

struct Result {
  // One per pair of neighbouring hair regions (a < b), plus fixed pairs;
  // relations contradicting the order are flipped and marked overridden.
  std::vector<RegionRelation> relations;
  std::vector<RelationAnchor> anchors;          // parallel to `relations`
  std::map<int, int> depth;                     // region id → depth, 0 = back-most
  std::vector<std::pair<int, int>> overridden;  // pairs dropped to break cycles
  // Diagnostics.
  BoundaryGraph graph;                     // on `labels`
  std::vector<BoundaryReport> boundaries;  // parallel to graph.boundaries
  LabelMap labels;                         // the regions after outline filling
  double line_width = 0.0;                 // used, pixels
  double line_threshold = 0.0;             // used, grey levels
  int states = 0;                          // boundary states in Eq. (2)
  int dropped_couplings = 0;               // frustrated couplings left out (0: exact)
  std::string summary;                     // one line: what was solved and how
};

// Layers the hair regions of `regions` (non-zero labels; 0 = background and
// outlines) drawn in `image`. Throws hair25d::Error when the sizes differ,
// there are fewer than two hair regions, no two hair regions meet at a
// junction, or the options are invalid.
Result layer_regions(const Image& image, const LabelMap& regions, const Options& options = {},
                     Progress* progress = nullptr);

}  // namespace hair25d::layering
