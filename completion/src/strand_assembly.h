// Turning matched and grown areas into strands with masks, outlines and
// textures, and filling the background (private).
#pragma once

#include <vector>

#include "context.h"
#include "face_joins.h"

namespace hair25d::completion::detail {

struct PieceArea {
  int region = 0;     // the region the area completes
  Polyline polygon;   // closed, image pixels
  bool root = false;  // a completed root (case 2)
  int edge = -1;      // index into the edge reports
  // Behind the face (face_joins.h): the area also counts over these pixels.
  const cv::Mat* face = nullptr;
};

struct StrandPieces {
  std::vector<PieceArea> areas;
  std::vector<std::vector<int>> groups;  // region ids of each strand
};

std::vector<CompletedStrand> assemble_strands(const Context& ctx, const StrandPieces& pieces,
                                              std::vector<EdgeReport>* reports,
                                              InpaintResult* inpainted);

// `face`: find_face's (may be empty: no head is filled then).
Image fill_background(const Context& ctx, const Face& face, InpaintResult* inpainted);

}  // namespace hair25d::completion::detail
