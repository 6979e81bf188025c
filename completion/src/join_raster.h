// The rasters of a strand-join candidate's hidden part (private): its
// patch's cover by the occluders, other shapes of it (Options::
// join_arm_shares), the outlines' fringe (Options::cover_fringe) and a
// corridor (Options::corridor_width). They are most of match_edges' time
// (session 39, the seed-7 1024² gradient drawing of 40 strands under
// callgrind: 5.8 G of its 6.3 G instructions, on one thread) and read
// nothing but the context, so match_edges hands them to several threads
// (`raster_patches`).
#pragma once

#include <map>
#include <optional>
#include <set>
#include <vector>

#include "context.h"
#include "cover_retry.h"

namespace hair25d::completion::detail {

// What a join costs for each share of its patch off the occluders (§5.1's
// cover term), the same for the patch drawn and for another shape tried.
inline constexpr double kUncoveredCost = 3.0;

// Share of the patch's pixels outside both pieces that lie under an occluder
// of either piece: the hidden part may only be where the drawing shows hair
// in front (§5 "completed part lies under the occluders"). `hidden`
// receives how many pixels were counted.
// `lowest`, when given, receives the pixels of every other region lying
// above no region (not in `front`) that the patch covers. `misses`, when
// given (not with `fringe`), counts what lies where the patch is not
// covered, for a cover refusal's second chance.
double coverage(const Context& ctx, const Polyline& patch, int ra, int rb, const cv::Mat& face,
                int* hidden, const std::set<int>* front = nullptr,
                std::map<int, int>* lowest = nullptr, bool ink = false,
                std::map<int, int>* under_by = nullptr, JoinTrace* trace = nullptr,
                bool fringe = false, CoverMisses* misses = nullptr);

// What match_edges decided of a candidate before its rasters.
struct PatchJob {
  const Edge* a = nullptr;  // the edges, with the tangents the candidate takes
  const Edge* b = nullptr;
  double cost = 0.0;                // the hand cost before the cover term
  double limit = 0.0;               // the cost a corridor's candidate must stay within
  double narrow = 0.0, wide = 0.0;  // the cuts' widths
  bool ink = false;                 // across a cut of ink only
  bool behind_face = false;         // both pieces back hair: the face hides it
  bool may_retry = false;           // may become a cover refusal's second chance
  bool reshape = false;             // other arm shares may be tried
  bool fringe = false;              // the fringe's cover may be taken
  bool corridor = false;            // a corridor may be sought
  bool users = false;               // the fringe's occluders judged by the user's orders
  bool retry_shape = false;         // the best shape's cover wanted for a second chance
  bool front_counts = false;        // `lowest` wanted (behind the face)
  bool by_label = false;            // `under_by` wanted (the scorer's inputs)
  bool trace = false;               // the holes wanted (Options::trace_joins)
};

// The rasters' answers, as match_edges used to compute them in its loop.
struct PatchRaster {
  Polyline patch;  // the patch drawn: a third's arms or the best shape's
  double cover = 0.0;
  int hidden = 0;
  std::map<int, int> lowest, under_by;
  CoverMisses misses;            // of `patch`, when the job may_retry
  double reshaped_cover = -1.0;  // the best shape's cover, once measured
  // The best shape's cover measured for a second chance that had none.
  std::optional<double> retry_shape_cover;
  bool corridor = false;
  JoinTrace holes;  // hole_* only, when the job traces
};

// One job's rasters. `front`: the regions above some region; `face`: the
// drawn face (CV_8U, may be empty).
PatchRaster raster_patch(const Context& ctx, const std::set<int>& front, const cv::Mat& face,
                         const PatchJob& job);

// Every job's, on up to `threads` threads (the answers do not depend on
// how many).
std::vector<PatchRaster> raster_patches(const Context& ctx, const std::set<int>& front,
                                        const cv::Mat& face, const std::vector<PatchJob>& jobs,
                                        int threads);

// Whether each label holding a tenth of the patch's covered pixels lies
// above piece `ra` or `rb` by the user's orders (Context::user_above), or
// by the layering's when `users` is false; label 0, the face or ink, counts.
bool occluders_above_pieces(const Context& ctx, const std::map<int, int>& under_by, int ra, int rb,
                            bool users);

}  // namespace hair25d::completion::detail
