// The layering stage as the pipeline runs it (paper §4), and the layering
// accuracy evaluation over annotated cases (paper §7, Table 1; FORMATS.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "hair25d/core/annotation.h"
#include "hair25d/core/image.h"
#include "hair25d/core/progress.h"
#include "hair25d/layering/evaluation.h"
#include "hair25d/layering/layering.h"
#include "hair25d/pipeline/joint_layering.h"

namespace hair25d::pipeline {

struct LayeringRun {
  layering::Result result;
  Image overlay;  // relations as arrows (occludee → occluder, "=" for equal) over the drawing
};

// Layers the hair regions of `regions` (0 = background and outlines) drawn in
// `image`. Throws hair25d::Error as layering::layer_regions does.
LayeringRun run_layering(const Image& image, const LabelMap& regions,
                         const layering::Options& options = {}, Progress* progress = nullptr);

struct LayeringEvalOptions {
  // Layer regions segmented from each case's strokes.json (pipeline::run_segment)
  // instead of its regions.png; a case without strokes is an error.
  bool from_strokes = false;
  // When not empty: one overlay per case, <dir>/<case>.png, wrong pairs ringed.
  std::filesystem::path overlays_dir;
  layering::Options layering;
  // Score the relations revised by completion's strand joins
  // (joint_layering.h) instead of the layering's own.
  bool with_joins = false;
  JointOptions joint;
};

struct LayeringCaseResult {
  layering::CaseScore score;  // every judged pair counts; a failed case has 0 correct
  std::string error;          // why layering failed on this case, empty if it ran
};

struct LayeringEvalReport {
  std::vector<LayeringCaseResult> cases;
  int pairs = 0;
  int correct = 0;
  double seconds = 0.0;  // layering time summed over cases
  double accuracy() const { return pairs > 0 ? static_cast<double>(correct) / pairs : 0.0; }
};

// Evaluates cases already in memory (generated ones, for tests).
LayeringEvalReport evaluate_layering(const std::vector<AnnotatedCase>& cases,
                                     const LayeringEvalOptions& options,
                                     Progress* progress = nullptr);

// Reads and evaluates every case folder under `cases_dir` (find_annotated_cases).
// Throws hair25d::Error when the folder holds no case or a case cannot be read.
LayeringEvalReport evaluate_layering(const std::filesystem::path& cases_dir,
                                     const LayeringEvalOptions& options,
                                     Progress* progress = nullptr);

// The report as a Table-1-like text table: one row per case (regions, judged
// pairs, correct, accuracy, seconds) and the total.
std::string format_layering_table(const LayeringEvalReport& report);

// The report in the JSON of FORMATS.md ("cases", "pairs", "correct",
// "accuracy"), with per-case "regions", "seconds", "error" and "wrong" pairs.
std::string layering_report_json(const LayeringEvalReport& report);

}  // namespace hair25d::pipeline
