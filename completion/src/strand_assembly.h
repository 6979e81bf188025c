// Turning matched and grown areas into strands with masks, outlines and
// textures, and filling the background (private).
#pragma once

#include <functional>
#include <vector>

#include "context.h"
#include "face_joins.h"
#include "head_fill.h"

namespace hair25d::completion::detail {

// Which labels lie above some member of a strand (its occluders), as a
// table by label: asked for every pixel of the strand's box and of a window
// around each of its outline pixels, where a search of every member's
// relations cost about a twentieth of the whole model's instructions.
class Occluders {
 public:
  Occluders(const Context& ctx, const std::vector<int>& members) {
    for (int m : members) {
      auto it = ctx.above.find(m);
      if (it == ctx.above.end()) continue;
      for (int up : it->second) {
        if (up >= static_cast<int>(above_.size())) above_.resize(up + 1, 0);
        above_[up] = 1;
      }
    }
  }
  bool operator()(int label) const {
    return label > 0 && label < static_cast<int>(above_.size()) && above_[label] != 0;
  }

 private:
  std::vector<std::uint8_t> above_;
};

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

// The completed shape of `mask` (non-zero inside, crop at `origin`): the
// outer boundary of its largest connected piece, simplified.
Polyline strand_outline(const cv::Mat& mask, const Eigen::Vector2i& origin);

std::vector<CompletedStrand> assemble_strands(const Context& ctx, const StrandPieces& pieces,
                                              std::vector<EdgeReport>* reports,
                                              InpaintResult* inpainted);

// assemble_strands with areas still to be made: late area k completes region
// late_region[k] and is made by make_late(k) (null: none), each k once, in
// `late_order`. On two workers (Options::threads > 1) each strand is built as
// soon as the late areas of its regions are made, while the other worker may
// still be making one (a long growth left it idle while every strand waited).
// The same strands as making every late area first and then assemble_strands
// with them appended to pieces.areas in order of k. on_made(done) is called on
// the calling thread with the number of late areas made so far.
std::vector<CompletedStrand> assemble_strands(
    const Context& ctx, const StrandPieces& pieces, const std::vector<int>& late_region,
    const std::vector<std::size_t>& late_order,
    const std::function<const PieceArea*(std::size_t)>& make_late,
    const std::function<void(std::size_t)>& on_made, std::vector<EdgeReport>* reports,
    InpaintResult* inpainted);

// What the background takes for hair: the regions, their drawn outline and
// rim, and what the hair encloses; and the head behind it.
struct BackgroundHole {
  cv::Mat holes;  // CV_8U, image size: non-zero where the background is filled
  Head head;      // empty mask when there is no face
};

// The model at rest (the background and the textures back to front) gives
// the drawing back: each strand of `groups` (`strands`, in the same order)
// also carries, drawn as they are, the pixels where it would not —
// those `holes` takes that no region holds (the outline's anti-aliased rim,
// lines converging at tips, the bangs' light points, specks the hair
// encloses) and `background` fills with another colour, going to the
// nearest region's strand; and the outline pixels a strand's texture paints
// over because an occluder's line runs there, going to that occluder.
// Within a line's reach of an occluder of the nearest strand a pixel is the
// occluder's: the line between two strands is the front one's outline.
// Strand boxes grow to hold them; outlines are traced again.
void carry_rims(const Context& ctx, const cv::Mat& holes,
                const std::vector<std::vector<int>>& groups, const Image& background,
                std::vector<CompletedStrand>* strands);

// `face`: find_face's (may be empty: no head is filled then).
BackgroundHole background_hole(const Context& ctx, const Face& face);
Image fill_background(const Context& ctx, const BackgroundHole& hole, InpaintResult* inpainted);

}  // namespace hair25d::completion::detail
