// The head behind the hair (private, paper §5.4 "background"): where the
// face continues under the bangs and where the skull lies under the hair,
// moving hair must uncover skin, never a transparent hole or the paper.
#pragma once

#include <opencv2/core.hpp>

#include "context.h"
#include "face_joins.h"
#include "hair25d/completion/inpaint.h"

namespace hair25d::completion::detail {

struct Head {
  // CV_8U, image size: 1 inside the head — the skull (a disc round the head
  // centre as wide as the face, a little wider where hair hides the face's
  // sides) and the convex hull of the face within 1.5 skull radii.
  cv::Mat mask;
  // CV_8U, image size: 1 on skin the drawing shows (the face, not ink, of
  // the face's colour): the exemplars of the hidden forehead and skull.
  cv::Mat skin;
  Rgba colour{};  // the skin's median colour
  int skin_pixels = 0;
};

// The head of the drawing round `face` (find_face's), or one with an empty
// mask when the face is empty or shows too little skin.
Head find_head(const Context& ctx, const Face& face, const InpaintOptions& options);

// Fills the pixels of `image` where `hole` (CV_8U, image size) and the head
// meet with skin: the nearest skin pixels' colours fading into the skin's
// median away from the face, smoothed; where the skin is textured (mean
// |luma − 3×3 median| above `texture_threshold`) exemplar patches copied
// from skin pixels only, guided by it (no eye, line or hair fragment is
// copied in). Returns the pixels filled (and the exemplar pass's patches).
InpaintResult fill_head(Image& image, const cv::Mat& hole, const Head& head,
                        const InpaintOptions& options, double texture_threshold);

}  // namespace hair25d::completion::detail
