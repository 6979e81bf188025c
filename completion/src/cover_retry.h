// A second chance for a strand-join candidate refused by min_join_coverage
// (session 36, JoinScorerOptions::cover_refusal_threshold): what lies where
// its patch is not under the occluders, for the net trained on such
// candidates. Private to the case-1 joins.
#pragma once

#include <opencv2/core.hpp>

#include "context.h"
#include "join_features.h"

namespace hair25d::completion::detail {

// The uncovered pixels of a candidate's patch, counted in match_edges'
// `coverage` pass over the region map as given (session 37: a pass of
// their own cost about 5% of `hair25d model`'s time). A pixel outside both
// pieces is covered as `coverage` counts it (a region above a or b,
// `cover_face` behind back hair, the ink across a cut of ink only). The
// uncovered ones are split by what lies there: the face (`face`, the whole
// face mask, may be empty), a drawn line (no region and darker than
// Options::dark_luma, or a region's pixel that was outline in the map as
// given), paper (no region, light), a region under a piece, a region under
// an occluder of a piece, any other region.
struct CoverMisses {
  // Given: the candidate's two cuts and the face.
  const Edge* a = nullptr;
  const Edge* b = nullptr;
  const cv::Mat* face = nullptr;
  // Counted, in pixels: the patch's outside both pieces, the uncovered,
  // those of them near a cut, and each class.
  int total = 0, missed = 0, at_cuts = 0;
  double paper = 0, on_face = 0, on_ink = 0, below = 0, sibling = 0, other = 0;

  // Within this of a cut (px) a miss is at the cut; set by `clear`.
  double reach = 0.0;

  // Back to no pixel counted (a new patch), the cuts' reach measured.
  void clear();
  // One uncovered pixel at (x, y), of label `l` (`inside` false: off the
  // map). False when it is a hair region's, which `add_region` counts by
  // its label once the pass is over (a patch crosses few labels).
  bool add_pixel(const Context& ctx, bool inside, int l, int x, int y);
  // `n` uncovered pixels of hair region `l`, by hole_kind.
  void add_region(const Context& ctx, int l, int n);
};

// The net's inputs for a cover refusal's second chance (JoinTerms::
// cover_retried ...) from its patch's misses. `shape_cover` is the cover
// of the best patch of the arm shares (best_join_shape), or the patch's
// own when none was measured.
void add_cover_terms(const CoverMisses& misses, double shape_cover, JoinTerms* t);

}  // namespace hair25d::completion::detail
