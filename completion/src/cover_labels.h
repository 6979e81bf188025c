// The labels the cover test reads (Context::cover_labels): the outlines'
// light fringe given to the nearest region.
#pragma once

#include "hair25d/core/image.h"

namespace hair25d::completion::detail {

// `labels` (outlines assigned) with every label-0 pixel within `reach`
// pixels (4-connected steps) of a labelled pixel given the nearest label,
// whatever its luma.
LabelMap fringe_labels(const LabelMap& labels, int reach);

}  // namespace hair25d::completion::detail
