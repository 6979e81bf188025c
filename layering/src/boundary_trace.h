// The crack-grid trace of build_boundary_graph (paper §4: boundaries between
// junctions) with its row scans chosen, internal to the layering.
#pragma once

#include "hair25d/layering/boundary_graph.h"

namespace hair25d::layering::detail {

// build_boundary_graph; with `wide_rows` (where the processor has AVX2) the
// corners are scanned eight at a time (sixteen with `widest_rows` where it
// has AVX-512F) and the scan for closed loops is skipped when the traces
// walked every crack edge between rows. `box`, when given with `any` set,
// holds every non-zero label of the map (the outline fill's box): the rows
// scanned eight or sixteen at a time are scanned only across it (outside it
// no label changes and no crack edge lies between rows). The graph is the
// same either way (for tests).
struct LabelBox;  // raster_scan.h
BoundaryGraph build_boundary_graph(const LabelMap& labels, bool wide_rows, bool widest_rows = true,
                                   const LabelBox* box = nullptr);

}  // namespace hair25d::layering::detail
