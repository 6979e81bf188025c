#include "cover_labels.h"
#include "hair25d/completion/completion.h"
#include "hair25d/core/error.h"
#include "raster.h"

namespace hair25d::completion {

LabelMap assign_outline_pixels(const Image& image, const LabelMap& regions, int reach,
                               int dark_luma) {
  detail::require_image_size("completion::assign_outline_pixels", "regions are", regions, image);
  // An outline pixel between two regions goes to the one it is nearer to,
  // so the line is split down its middle.
  return detail::grow_labels(
      regions, reach, [&](int x, int y) { return detail::luma(image.at(x, y)) < dark_luma; });
}

}  // namespace hair25d::completion
