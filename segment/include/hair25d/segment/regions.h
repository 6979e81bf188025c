// Regions without strokes (paper §3, DESIGN "automatic regions"): the faces of
// the mesh enclosed by curves, and helpers to label, merge and renumber them so
// a user can pick a strand with one click or a batch job can pick by colour.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "hair25d/core/image.h"
#include "hair25d/core/strokes.h"
#include "hair25d/core/tri_mesh.h"

namespace hair25d::segment {

// Connected components of triangles across edges that are not on a curve,
// numbered from 1 in order of their first triangle. #F ids.
std::vector<int> automatic_regions(const TriMesh2& mesh);

// A pixel belongs to no region below this alpha: transparent paper is not
// hair. An anti-aliased edge pixel more than half transparent is paper too
// (the completion stage draws nothing there either).
inline constexpr std::uint8_t kOpaqueAlpha = 128;

// Per pixel, the id of the triangle holding its centre; 0 where the drawing
// is transparent (alpha < kOpaqueAlpha) or no triangle holds it. This is the
// region map of a segmentation (regions.png). Throws hair25d::Error if the
// sizes do not match.
LabelMap region_map(const Image& image, const TriMesh2& mesh,
                    const std::vector<int>& triangle_regions);

// Sets to 0 every region (id > 0) that lies mostly on transparent paper
// (more than half of its pixels below kOpaqueAlpha): the face round a drawing
// on a transparent sheet is no region. Returns how many regions it cleared.
int clear_paper_regions(const Image& image, const TriMesh2& mesh,
                        std::vector<int>& triangle_regions);

struct RegionStats {
  int id = 0;
  double area = 0.0;             // pixels²
  std::array<double, 3> mean{};  // mean RGB of the pixels off the lines, 0-255
  Vec2 centroid{0.0, 0.0};
  int pixels = 0;  // pixels counted for the mean colour
};

// Area, centroid and mean colour of each region id > 0 of `triangle_regions`.
// `line_mask` (may be empty) keeps line pixels out of the mean colour.
std::vector<RegionStats> region_stats(const Image& image, const TriMesh2& mesh,
                                      const std::vector<int>& triangle_regions,
                                      const LabelMap& line_mask);

struct ColourPick {
  std::array<std::uint8_t, 3> rgb{0, 0, 0};
  double tolerance = 40.0;  // Euclidean RGB distance, 0-255 scale
  double min_area = 0.0;    // regions smaller than this (pixels²) are left out
};

// The regions whose mean colour lies within the tolerance of the pick: one
// label per region (numbered from 1 in region order), as per-triangle labels
// (0 elsewhere). Throws hair25d::Error for a negative tolerance or mismatched sizes.
std::vector<int> label_regions_by_colour(const Image& image, const TriMesh2& mesh,
                                         const std::vector<int>& triangle_regions,
                                         const LabelMap& line_mask, const ColourPick& pick);

// One dot stroke of width `width` at a point inside each labelled region
// (triangle_labels > 0), so a picked region list can go through the stroke
// path (graph cut) like a user's markup.
Strokes strokes_from_labels(const TriMesh2& mesh, const std::vector<int>& triangle_labels,
                            double width = 3.0);

// Every triangle labelled `from` gets `into`. Throws hair25d::Error for negative ids.
void merge_labels(std::vector<int>& triangle_labels, int from, int into);

// Applies `mapping` (old id -> new id, ids not in it are kept). Throws
// hair25d::Error for a negative target id.
void relabel(std::vector<int>& triangle_labels, const std::map<int, int>& mapping);

// Renumbers the positive ids to 1..n in increasing order of the old ids; 0 stays.
// Returns n.
int compact_labels(std::vector<int>& triangle_labels);

// Pairs (a < b) of ids whose triangles share an edge; 0 included.
std::vector<std::array<int, 2>> label_adjacency(const TriMesh2& mesh,
                                                const std::vector<int>& triangle_labels);

}  // namespace hair25d::segment
