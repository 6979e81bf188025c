// The whole 2.5D hair model as the pipeline builds it (paper §3–§6, first
// part): segment → layering → completion (§5) → skeletons and meshes (§6),
// assembled into a core HairModel with a contact sheet for a person to check.
#pragma once

#include <array>
#include <chrono>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "hair25d/completion/completion.h"
#include "hair25d/core/hair_model.h"
#include "hair25d/core/image.h"
#include "hair25d/core/progress.h"
#include "hair25d/core/strokes.h"
#include "hair25d/layering/layering.h"
#include "hair25d/skeleton/strand_mesh.h"
#include "hair25d/skeleton/strand_skeleton.h"

namespace hair25d::pipeline {

struct ModelOptions {
  layering::Options layering;
  completion::Options completion;
  skeleton::Options skeleton;
  skeleton::MeshOptions mesh;
  // An outline vertex is covered (not a tip) when its own pixel, or more than
  // half of the disc of this radius round it, belongs to a strand drawn above.
  int cover_reach = 3;
  int threads = 2;  // skeletons and meshes built by up to this many threads (1 = serial)

  // False, naming the option, its value and the rule, if unusable.
  bool is_valid(std::string* error) const;
};

// Per-strand facts the model file does not keep (for the contact sheet and tests).
struct StrandReport {
  LabelMap mask;  // crop at the strand's texture origin: 1 visible, 2 completed
  Polyline body;  // the outline without the drawn rim: the skeleton's shape
  skeleton::SkeletonStatus skeleton = skeleton::SkeletonStatus::kTips;
  skeleton::MeshStatus mesh = skeleton::MeshStatus::kRefined;
  std::string problem;  // why the skeleton or mesh is missing, empty if none
};

struct ModelRun {
  HairModel model;
  std::vector<StrandReport> strands;  // parallel to model.strands
  LabelMap regions;                   // the regions used (outline pixels assigned)
  completion::Result completion;      // diagnostics (edges, joins); strands moved out
  Image contact_sheet;
  std::map<std::string, double> seconds;  // per stage
  std::string summary;
};

// Completion and skeletons from regions and relations already known (the
// annotation, or the layering stage). `depth`: region id → depth (0 = back);
// regions missing from it are ordered from `relations`.
ModelRun build_model(const Image& image, const LabelMap& regions,
                     const std::vector<RegionRelation>& relations, const std::map<int, int>& depth,
                     std::optional<Vec2> head_center, const ModelOptions& options = {},
                     Progress* progress = nullptr);

// Layering, completion and skeletons from a region label map (`--regions`).
ModelRun run_model(const Image& image, const LabelMap& regions, std::optional<Vec2> head_center,
                   const ModelOptions& options = {}, Progress* progress = nullptr);

// Everything from the drawing and optional strokes (segment first).
ModelRun run_model(const Image& image, const Strokes* strokes, const ModelOptions& options = {},
                   Progress* progress = nullptr);

// The contact sheet: the drawing; the completed areas in light blue (as the
// paper's Fig. 1d); strands coloured by depth, back blue to front red; the
// skeletons (red, tips green, roots blue) over the strands. Every panel shows
// the same part of the drawing, contact_sheet_box(run), shrunk by one whole
// factor so that its longer side is at most `panel_max_side`.
Image render_contact_sheet(const ModelRun& run, int panel_max_side = 640);

// The part of the drawing a contact sheet shows: the box of every strand's
// texture and skeleton, grown by a margin (an eighth of its longer side, at
// least 16 px) and clipped to the drawing; the whole drawing when there are
// no strands. {x, y, width, height}.
std::array<int, 4> contact_sheet_box(const ModelRun& run);

// Writes the model folder (core write_model_into) with contact_sheet.png inside
// it, atomically: the folder appears only once every file is in it.
void write_model_run(const std::filesystem::path& folder, const ModelRun& run);

// Throws hair25d::Error before any work when write_model_run would refuse
// `folder` (a file there, or a folder of somebody else's files).
void check_model_folder(const std::filesystem::path& folder, const std::string& what);

}  // namespace hair25d::pipeline
