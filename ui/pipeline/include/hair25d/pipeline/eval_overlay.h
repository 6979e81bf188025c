// The picture eval-layering draws per annotated case (paper §4, Fig. 1c; §7
// Table 1): the layering's relations over the drawing, labelled so that they
// stay readable where many regions meet, with the wrong pairs marked in red.
#pragma once

#include "hair25d/core/image.h"
#include "hair25d/layering/evaluation.h"
#include "hair25d/layering/layering.h"

namespace hair25d::pipeline {

// Draws `result` over `image` (same size as the result's labels, else
// hair25d::Error): regions tinted with their id inside, boundaries by kind,
// one arrow per related pair from the occludee to the occluder ("=" for
// equal), each with a label "a>b" (a above b) or "a=b" set where it overlaps
// no other label or mark (a thin leader line back when it had to move). The
// pairs `score` says are wrong are ringed and labelled in red, a pair the
// layering did not relate gets a red "?"; a caption band under the drawing
// names the case, the accuracy, the legend and every wrong pair with its
// annotated relation. Drawings under 670 px a side are drawn 2-4 times as
// large so the labels have room; text and marks scale with the output.
Image render_eval_overlay(const Image& image, const layering::Result& result,
                          const layering::CaseScore& score);

}  // namespace hair25d::pipeline
