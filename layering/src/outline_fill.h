// The outline fill (paper §4.1: outline pixels given to the regions they
// separate) split into bands of rows grown on separate cores, internal to
// the layering; fill_outlines (boundary_graph.h) is the public entry.
#pragma once

#include <functional>
#include <vector>

#include "hair25d/layering/boundary_graph.h"
#include "parallel.h"
#include "raster_scan.h"

namespace hair25d::layering::detail {

// Bands fill_outlines splits a large map into, and the fewest rows of the
// label box per band: with fewer, the rows grown twice (the reach beyond
// each band) cost more than a second core saves.
inline constexpr int kFillBands = 4;
inline constexpr int kMinFillBandRows = 96;

// fill_outlines with the label box's rows split into at most `max_bands`
// bands of at least `min_band_rows` rows, each grown on its own over the
// rows within the growth's reach: the result equals one growth over the
// whole map (max_bands = 1) in every pixel, the line width and the radius.
// With `wide_rows` (where the processor has AVX2) the rows are prepared
// sixteen pixels at a time (thirty-two with `widest_rows` where it has
// AVX-512F, BW and VL, which also relaxes a bucket of fronts by masked
// stores and finds the pixels reached by a scan of the rows); the result is
// the same (for tests). The bands run on
// `pool`'s helpers where one is given. With `filled_box`, the box of the
// filled map's non-zero labels is written there (label_box's answer on it,
// without reading the map again). With `ids`, the distinct non-zero labels
// of `labels`, sorted (distinct_labels' answer), are written there, read
// while the map is copied. `before_writes`, where given, is called with the
// line width and the filled map's box once they are known, before the
// pixels are written into the map (at the growth limits of drawings: up to
// 200 px), so that work which needs only those can start early.
using BeforeWrites = std::function<void(double line_width, const LabelBox& filled_box)>;
OutlineFill fill_outlines_in_bands(const LabelMap& labels, const OutlineFillOptions& options,
                                   int max_bands, int min_band_rows, bool wide_rows = true,
                                   Pool* pool = nullptr, LabelBox* filled_box = nullptr,
                                   bool widest_rows = true, std::vector<int>* ids = nullptr,
                                   const BeforeWrites& before_writes = {});

// fill_outlines with its bands on `pool`'s helpers, the filled map's box,
// the map's ids and a call before the writes.
inline OutlineFill fill_outlines(const LabelMap& labels, Pool* pool, LabelBox* filled_box = nullptr,
                                 std::vector<int>* ids = nullptr,
                                 const BeforeWrites& before_writes = {}) {
  return fill_outlines_in_bands(labels, {}, kFillBands, kMinFillBandRows, true, pool, filled_box,
                                true, ids, before_writes);
}

}  // namespace hair25d::layering::detail
