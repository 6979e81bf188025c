// A learned look at the whole local configuration of a boundary's junctions,
// an addition to paper §4.2–4.4: the label map around each end, rasterised in
// the boundary's own frame, read by a small neural network (trained with
// OpenCV's ANN_MLP on generated drawings, bench/layering/train_layering_patch.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "hair25d/core/geometry.h"
#include "hair25d/core/image.h"
#include "hair25d/layering/boundary_graph.h"

namespace hair25d::layering::detail {

// A patch is kPatchCells × kPatchCells cells about a junction at each of
// kPatchScales scales (radius r and kPatchWide × r: the junction itself and
// the regions' shapes around it), u along the boundary leaving the junction
// (+u), v toward region A's side (+v), two channels per cell (scale-major,
// then cell-major): the share of region A minus that of region B, and the
// share of other hair regions (background and the outside of the image are 0
// in both). Each cell is the mean of 2 × 2 point samples. After both scales
// come kPatchGreyInputs inputs read off the drawing itself at the first scale,
// one per cell (cell-major): how much darker the cell's mean grey level is
// than the brightest of the 3 × 3 cells about it, in units of `contrast` (a
// typical drawn line's contrast), at most 2 — where the lines run, which the label
// map does not show (a line fading out inside a strand, the paper between
// two outlines, an outline that runs on past a T). Last (session 17) a
// coarse third scale of the same two label channels, radius kPatchCoarse × r
// (each scale three times the last: the strands' shapes well beyond the
// junction), from kPatchCoarseStart on; networks that weigh it 0 read the
// first kPatchCoarseStart inputs exactly as before it was added.
inline constexpr int kPatchCells = 16;
inline constexpr int kPatchChannels = 2;
inline constexpr int kPatchScales = 2;
inline constexpr double kPatchWide = 3.0;
inline constexpr double kPatchCoarse = 9.0;
inline constexpr int kPatchScaleInputs = kPatchCells * kPatchCells * kPatchChannels;
inline constexpr int kPatchLabelInputs = kPatchScales * kPatchScaleInputs;
inline constexpr int kPatchGreyInputs = kPatchCells * kPatchCells;
inline constexpr int kPatchCoarseStart = kPatchLabelInputs + kPatchGreyInputs;
inline constexpr int kPatchInputs = kPatchCoarseStart + kPatchScaleInputs;
using Patch = std::array<float, kPatchInputs>;

// The drawing a patch's grey channel is read from, and the grey-level
// contrast of a typical drawn line (> 0) that scales it.
struct PatchImage {
  const Image* image = nullptr;
  double contrast = 1.0;
  // Samples read with the processor's gathers where it has AVX-512F (the
  // same patch as without).
  bool widest = true;
  // Sample the coarse scale (else its inputs are 0: for networks that weigh
  // it 0, which then need not pay for it).
  bool coarse = true;
  // The label map as bytes (byte_labels over all of it, kByteLabelsPadding
  // bytes more at the end), or null. Where given, patches whose regions a
  // and b are both in [1, kByteLabelMax) read it with the gathers in place
  // of the map (a quarter of the memory: the same patch).
  const std::uint8_t* bytes = nullptr;
};

// The label map as bytes: each label clamped to [0, kByteLabelMax], so that
// a byte tells a label in [1, kByteLabelMax) from any other, and all labels
// <= 0 (no hair) and all >= kByteLabelMax (hair) from those. byte_labels
// writes the pixels x0 <= x < x1, y0 <= y < y1 of `bytes` (width × height
// bytes, row-major).
inline constexpr int kByteLabelMax = 255;
inline constexpr int kByteLabelsPadding = 4;
void byte_labels(const LabelMap& labels, int x0, int x1, int y0, int y1, std::uint8_t* bytes);

// Whether junction_patch reads with the processor's gathers (AVX-512F),
// where PatchImage::widest is set: only then is PatchImage::bytes read.
bool patch_gathers_available();

// The cells of the first scale cover [−radius, radius]² about `centre`
// (pixel-corner coordinates, as junction positions). `direction` is the unit
// direction in which the boundary leaves the junction; `a_on_left` says
// whether region a lies on the left of that walk as seen on the screen (x
// right, y down). Without an image (`drawing.image` null) the grey channel is
// 0. Throws hair25d::Error for a radius that is not finite and > 0, a
// direction that is not a finite non-zero vector, an image of another size
// than the map or a contrast that is not finite and > 0.
Patch junction_patch(const LabelMap& labels, const PatchImage& drawing, const Vec2& centre,
                     const Vec2& direction, int a, int b, bool a_on_left, double radius);

// The same configuration with regions A and B exchanged: mirrored across the
// u axis, the A − B channel negated (the grey channel is only mirrored).
Patch swapped(const Patch& patch);

// The patch radius for a drawing's junction fit length (layering's `reach`,
// where the sectors are measured).
double patch_radius(double reach);

// The grey channel's unit for a drawing's occluding-line threshold (which is
// 0.4 × a typical line's contrast by default): 2.5 × the threshold.
double patch_contrast(double line_threshold);

// A one-hidden-layer perceptron in OpenCV's ANN_MLP form: every unit,
// the output included, applies β (1 − e^{−αx}) / (1 + e^{−αx}). It is the sum
// of kPatchMembers such networks of kPatchMemberHidden hidden units each
// (an ensemble trained from different initial weights): member m owns hidden
// units [m · kPatchMemberHidden, (m + 1) · kPatchMemberHidden) and output
// bias b2[m], and the output is the sum of the members' outputs.
inline constexpr int kPatchMembers = 1;
inline constexpr int kPatchMemberHidden = 32;
inline constexpr int kPatchHidden = kPatchMembers * kPatchMemberHidden;
struct PatchNet {
  // Input-major: w1[k][h] weighs input k into hidden unit h.
  std::array<std::array<float, kPatchHidden>, kPatchInputs> w1{};
  std::array<float, kPatchHidden> b1{};
  std::array<float, kPatchHidden> w2{};
  std::array<float, kPatchMembers> b2{};
  double alpha = 2.0 / 3.0, beta = 1.7159;
  // Second stage: log-odds "A above" = order · (6b log-odds) + patch · score.
  double order_weight = 1.0;
  double patch_weight = 0.0;
};

// The same form for "same depth or ordered", whose score does not change
// when A and B swap; its stage: log-odds of same depth = intercept +
// order_weight · (6c log-odds) + patch_weight · score.
struct SameDepthNet {
  PatchNet net;
  double intercept = 0.0;
};

// The network's raw output for one patch, reading its first `inputs` inputs
// (those past the last one with a non-zero weight add nothing).
double patch_net(const PatchNet& net, const Patch& patch, int inputs = kPatchInputs);

// One past the last input with a non-zero weight (the order network reads
// the fine scale only).
int patch_inputs_used(const PatchNet& net);

// Antisymmetric by construction: net(P) − net(swapped(P)), so exchanging A and
// B flips its sign exactly and it cannot prefer a side.
double patch_score(const PatchNet& net, const Patch& patch);

// Symmetric by construction: net(P) + net(swapped(P)).
double patch_same_score(const PatchNet& net, const Patch& patch);

// Both scores of one patch, exchanging it once: patch_score(order, patch)
// and patch_same_score(same, patch), to the bit; `order_inputs` is
// patch_inputs_used(order).
struct PatchScores {
  double order = 0.0, same = 0.0;
};
PatchScores patch_scores(const PatchNet& order, int order_inputs, const PatchNet& same,
                         const Patch& patch);

// The same for `count` patches at once, out[i] those of patches[i] to the
// bit (the networks' weights are read once for two patches). With `widest`
// the non-zero inputs are found sixteen at a time where the processor has
// AVX-512F (the same lists as the plain loops make). The same-depth network
// reads the first `same_inputs` inputs: patch_inputs_used(same) gives the
// same score without the products of the zero weights past its last one.
void patch_scores(const PatchNet& order, int order_inputs, const PatchNet& same,
                  const Patch* patches, int count, PatchScores* out, bool widest = true,
                  int same_inputs = kPatchInputs);

// The patches of both ends of boundary `b` of `graph` (none for a closed
// loop; an end is left out when its direction is zero), region A = b.left.
// `start_direction` / `end_direction` are the directions leaving each end.
std::vector<Patch> boundary_patches(const LabelMap& labels, const PatchImage& drawing,
                                    const BoundaryGraph& graph, const Boundary& b,
                                    const Vec2& start_direction, const Vec2& end_direction,
                                    double radius);

// The weights in use (layering/src/patch_weights.cpp says how they were made).
const PatchNet& patch_weights();
const SameDepthNet& patch_same_weights();

}  // namespace hair25d::layering::detail
