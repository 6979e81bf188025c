// A second chance for a strand-join candidate refused by min_join_coverage
// (session 36, JoinScorerOptions::cover_refusal_threshold): what lies where
// its patch is not under the occluders, for the net trained on such
// candidates. Private to the case-1 joins.
#pragma once

#include <opencv2/core.hpp>

#include "context.h"
#include "join_features.h"

namespace hair25d::completion::detail {

// The net's inputs for it (JoinTerms::cover_retried ...). `patch` is the
// candidate's patch; a pixel outside both pieces is covered as
// match_edges' coverage counts it (a region above a or b, `cover_face`
// behind back hair, the ink across a cut of ink only). The uncovered ones
// are split by what lies there: the face (`face`, the whole face mask, may
// be empty), a drawn line (no region and darker than Options::dark_luma,
// or a region's pixel that was outline in the map as given), paper (no
// region, light), a region under a piece, a region under an occluder of a
// piece, any other region. `shape_cover` is the cover of the best patch of the arm shares
// (best_join_shape), or the patch's own when none was measured.
void add_cover_terms(const Context& ctx, const Polyline& patch, const Edge& a, const Edge& b,
                     const cv::Mat& face, const cv::Mat& cover_face, bool ink, double shape_cover,
                     JoinTerms* t);

}  // namespace hair25d::completion::detail
