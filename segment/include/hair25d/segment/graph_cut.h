// Labelling the mesh triangles from the user's strokes by a graph cut on the
// mesh's dual graph (paper §3): edge weights φ·‖e‖ (φ = 0 on curves), terminal
// weights from a Gaussian mixture of each label's colours and the distance to
// its strokes, background P(B) = 1 − P(F). Several labels by α-expansion.
#pragma once

#include <string>
#include <vector>

#include "hair25d/core/image.h"
#include "hair25d/core/strokes.h"
#include "hair25d/core/tri_mesh.h"

namespace hair25d::segment {

struct GraphCutOptions {
  double phi_curve = 0.0;   // φ on edges that lie on a drawn curve
  double phi_other = 30.0;  // φ on every other edge (paper: 30)
  // Data term per pixel of triangle area: unary_weight × −ln max(P, min_probability).
  double unary_weight = 0.25;
  double min_probability = 0.01;
  // Distance to a label's strokes enters P as exp(−d² / 2σ²) with σ =
  // distance_sigma_fraction × sqrt(width × height).
  double distance_sigma_fraction = 1.0;
  // Colour similarity uses a Gaussian mixture of up to this many components
  // per label, with at least colour_sigma_min grey levels of spread.
  int gmm_components = 3;
  double colour_sigma_min = 10.0;
  // A triangle that looks like any hair colour keeps this share of a label's
  // colour likelihood (shaded strands whose strokes touch one tone only).
  double hair_colour_share = 0.5;
  // A curve edge counts as drawn (φ = phi_curve) only if no stretch longer
  // than this (pixels) along it is off the line mask; links that close gaps
  // between lines get phi_other.
  int max_undrawn_run = 2;
  // A face closed off by drawn lines that holds no stroke is background (the
  // user marks every strand); false: it takes the hair label that fits it
  // best, or background, by its terminal weights.
  bool unmarked_faces_background = true;
  int max_cycles = 5;  // α-expansion sweeps over the labels

  bool is_valid(std::string* error) const;
};

struct GraphCutResult {
  std::vector<int> labels;  // #F stroke label per triangle, 0 = background
  double energy = 0.0;
  int cycles = 0;         // α-expansion sweeps done (the largest over components)
  bool converged = true;  // false: stopped at max_cycles with the energy still falling
  int components = 0;     // pieces of the dual graph split by curve edges
};

// Labels every triangle with one stroke label or 0. `line_mask` (1 on drawn
// lines, may be empty) keeps line pixels out of the colour models. Strokes
// may leave the image (clipped). Throws hair25d::Error if the strokes hold no
// hair stroke inside the image, if the mesh does not match the image, or for
// invalid options.
GraphCutResult graph_cut_labels(const Image& image, const TriMesh2& mesh, const Strokes& strokes,
                                const LabelMap& line_mask, const GraphCutOptions& options = {});

}  // namespace hair25d::segment
