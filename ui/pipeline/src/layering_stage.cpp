#include "hair25d/pipeline/layering_stage.h"

#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <system_error>

#include "hair25d/core/error.h"
#include "hair25d/core/image_io.h"
#include "hair25d/layering/overlay.h"
#include "hair25d/pipeline/eval_overlay.h"
#include "hair25d/pipeline/segment_stage.h"

namespace hair25d::pipeline {
namespace {

LayeringCaseResult evaluate_one(const AnnotatedCase& c, const LayeringEvalOptions& options) {
  LayeringCaseResult out;
  if (options.from_strokes && !c.strokes)
    throw Error("eval-layering: case '" + c.name + "' (" + c.folder.string() +
                ") has no strokes.json; --from-strokes needs one per case");
  LabelMap regions = c.regions;
  std::optional<layering::Result> result;
  try {
    if (options.from_strokes) regions = run_segment(c.image, &*c.strokes, nullptr, false).regions;
    check_label_map(regions, c.folder.string() + ": the region map");
    const auto start = std::chrono::steady_clock::now();
    result = layering::layer_regions(c.image, regions, options.layering);
    if (options.with_joins) {
      // The joins grouped with the layering's relations, and the relations
      // revised to agree with them (joint_layering.h).
      const std::vector<std::vector<int>> strands =
          join_strand_groups(c.image, regions, result->relations);
      revise_with_strands(regions.labels(), strands, options.joint, &result->relations,
                          &result->depth);
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.score = layering::score_relations(c, result->relations);
    out.score.seconds = seconds;
  } catch (const Error& e) {
    // A case the layering refuses still counts: all its pairs are wrong.
    out.error = e.what();
    out.score = layering::score_relations(c, {});
  }
  out.score.regions = static_cast<int>(regions.labels().size());
  // Outside the try: an overlay that cannot be written is the user's problem
  // to hear about, not a case that scored zero.
  if (result && !options.overlays_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(options.overlays_dir, ec);
    if (ec) {
      throw Error(options.overlays_dir.string() +
                  ": cannot create the overlays folder: " + ec.message());
    }
    save_image(options.overlays_dir / (c.name + ".png"),
               render_eval_overlay(c.image, *result, out.score));
  }
  return out;
}

}  // namespace

LayeringRun run_layering(const Image& image, const LabelMap& regions,
                         const layering::Options& options, Progress* progress) {
  LayeringRun run;
  check_label_map(regions, "layering: the region map");
  run.result = layering::layer_regions(image, regions, options, progress);
  run.overlay = layering::render_overlay(image, run.result);
  return run;
}

LayeringEvalReport evaluate_layering(const std::vector<AnnotatedCase>& cases,
                                     const LayeringEvalOptions& options, Progress* progress) {
  LayeringEvalReport report;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    report.cases.push_back(evaluate_one(cases[i], options));
    const layering::CaseScore& s = report.cases.back().score;
    report.pairs += s.pairs;
    report.correct += s.correct;
    report.seconds += s.seconds;
    hair25d::report(progress, "eval-layering", static_cast<double>(i + 1) / cases.size(),
                    cases[i].name);
  }
  return report;
}

LayeringEvalReport evaluate_layering(const std::filesystem::path& cases_dir,
                                     const LayeringEvalOptions& options, Progress* progress) {
  if (!std::filesystem::is_directory(cases_dir))
    throw Error("eval-layering: '" + cases_dir.string() + "' is not a folder");
  const std::vector<std::filesystem::path> folders = find_annotated_cases(cases_dir);
  if (folders.empty())
    throw Error("eval-layering: '" + cases_dir.string() +
                "' has no case folder (a sub-folder with a layering.json)");
  // Every case read and checked before any is scored: a bad file in the last
  // case fails at once, not after the others' minutes of work. Read again
  // below so that only one case is in memory at a time (cases can be large
  // drawings); reading is a small part of scoring.
  for (const std::filesystem::path& folder : folders) (void)read_annotated_case(folder);
  LayeringEvalReport report;
  for (std::size_t i = 0; i < folders.size(); ++i) {
    const AnnotatedCase c = read_annotated_case(folders[i]);
    LayeringEvalReport one = evaluate_layering(std::vector<AnnotatedCase>{c}, options);
    report.cases.push_back(std::move(one.cases.front()));
    report.pairs += one.pairs;
    report.correct += one.correct;
    report.seconds += one.seconds;
    hair25d::report(progress, "eval-layering", static_cast<double>(i + 1) / folders.size(), c.name);
  }
  return report;
}

std::string format_layering_table(const LayeringEvalReport& report) {
  std::string out;
  char line[256];
  std::snprintf(line, sizeof line, "%-20s %8s %8s %8s %9s %9s\n", "case", "regions", "pairs",
                "correct", "accuracy", "seconds");
  out += line;
  for (const LayeringCaseResult& c : report.cases) {
    const layering::CaseScore& s = c.score;
    std::snprintf(line, sizeof line, "%-20s %8d %8d %8d %8.1f%% %9.4f%s\n", s.name.c_str(),
                  s.regions, s.pairs, s.correct, 100.0 * s.accuracy(), s.seconds,
                  c.error.empty() ? "" : "  (failed, see below)");
    out += line;
  }
  std::snprintf(line, sizeof line, "%-20s %8s %8d %8d %8.1f%% %9.4f\n", "total", "", report.pairs,
                report.correct, 100.0 * report.accuracy(), report.seconds);
  out += line;
  for (const LayeringCaseResult& c : report.cases)
    if (!c.error.empty()) out += c.score.name + ": " + c.error + "\n";
  return out;
}

std::string layering_report_json(const LayeringEvalReport& report) {
  using json = nlohmann::ordered_json;
  json cases = json::array();
  for (const LayeringCaseResult& c : report.cases) {
    const layering::CaseScore& s = c.score;
    json wrong = json::array();
    for (const layering::PairOutcome& o : s.outcomes) {
      if (o.correct) continue;
      wrong.push_back({{"a", o.a},
                       {"b", o.b},
                       {"relation", to_string(o.truth)},
                       {"predicted", o.predicted ? json(to_string(*o.predicted)) : json(nullptr)}});
    }
    json entry = {{"name", s.name},       {"regions", s.regions},     {"pairs", s.pairs},
                  {"correct", s.correct}, {"accuracy", s.accuracy()}, {"seconds", s.seconds},
                  {"wrong", wrong}};
    if (!c.error.empty()) entry["error"] = c.error;
    cases.push_back(entry);
  }
  const json doc = {{"cases", cases},
                    {"pairs", report.pairs},
                    {"correct", report.correct},
                    {"accuracy", report.accuracy()},
                    {"seconds", report.seconds}};
  return doc.dump(1) + "\n";
}

}  // namespace hair25d::pipeline
