// Layering and completion's strand joins together (issues 3 and 5): the
// layering decides each pair of regions from local evidence; the joins then
// group regions into strands; the relations are revised to agree with the
// strands (the pieces of one strand at one depth, a region's relations to the
// pieces of one strand in one direction) where they are weak, and made
// globally consistent again.
#pragma once

#include <vector>

#include "hair25d/completion/completion.h"
#include "hair25d/core/hair_model.h"
#include "hair25d/core/image.h"
#include "hair25d/core/progress.h"
#include "hair25d/layering/layering.h"

namespace hair25d::pipeline {

struct JointOptions {
  // Only relations weaker than this (|score|) are revised; user-fixed ones never.
  double weak_score = 2.0;
  // Measured orders between two pieces of one strand become "equal".
  bool same_depth = false;
  // Relations between two strands (a region alone is a strand of one piece)
  // that disagree with their summed score are turned to agree with it.
  bool agree = true;
  // ... only when the summed |score| is at least this.
  double agree_min_sum = 2.0;
};

// The region groups completion's joins make (complete_strands without colour:
// no inpainting, no background), each sorted; a region in no strand is left out.
std::vector<std::vector<int>> join_strand_groups(const Image& image, const LabelMap& regions,
                                                 const std::vector<RegionRelation>& relations,
                                                 completion::Options options = {});

struct JointRevision {
  int to_equal = 0;  // orders within one strand made "equal"
  int flipped = 0;   // orders between strands turned to the strands' summed direction
  int undone = 0;    // revisions undone: the rest of the order contradicts them
};

// Revises `relations` (as layering returns them: consistent, overridden ones
// flipped) to agree with `strands` where weak (JointOptions); a turned
// relation is marked overridden and keeps its score. Then orders the regions
// again (layering::order_regions: the layering's relations first, the
// revisions after them), undoes every revision that order contradicts, and
// sets `depth` when given. Regions named by no strand are strands of one.
// Returns what changed.
JointRevision revise_with_strands(const std::vector<int>& region_ids,
                                  const std::vector<std::vector<int>>& strands,
                                  const JointOptions& options,
                                  std::vector<RegionRelation>* relations,
                                  std::map<int, int>* depth = nullptr);

struct JointLayering {
  layering::Result layering;  // relations and depth revised
  std::vector<std::vector<int>> strands;
  JointRevision revision;
};

// layer_regions, join_strand_groups with its relations, revise_with_strands.
// Throws what layer_regions throws.
JointLayering layer_with_joins(const Image& image, const LabelMap& regions,
                               const layering::Options& layering_options = {},
                               const completion::Options& completion_options = {},
                               const JointOptions& options = {}, Progress* progress = nullptr);

}  // namespace hair25d::pipeline
