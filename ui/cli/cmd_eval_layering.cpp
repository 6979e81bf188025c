// hair25d eval-layering CASES_DIR [--json REPORT.json] [--from-strokes] [--overlays DIR]
// [--with-joins] [--open-order-log-odds V]:
// layering accuracy over annotated cases, printed like the paper's Table 1.
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "commands.h"
#include "hair25d/core/annotation.h"
#include "hair25d/core/atomic_file.h"
#include "hair25d/core/error.h"
#include "hair25d/pipeline/layering_stage.h"

namespace hair25d::cli {
namespace {

struct EvalLayeringArgs {
  std::string cases_dir;
  std::string json_path;
  std::string overlays_dir;
  bool from_strokes = false;
  bool with_joins = false;
  double open_order_log_odds = layering::Options{}.open_order_log_odds;
};

// The mark write_folder_atomically leaves in the overlays folder.
constexpr const char* kOverlaysKind = "eval-layering overlays";

}  // namespace

void add_eval_layering_command(CLI::App& app, const CommonOptions& common) {
  auto args = std::make_shared<EvalLayeringArgs>();
  CLI::App* cmd = app.add_subcommand(
      "eval-layering",
      "Layering accuracy over annotated cases (FORMATS.md): one row per case and the total");
  cmd->add_option("CASES_DIR", args->cases_dir, "Folder whose sub-folders hold layering.json")
      ->required();
  CLI::Option* json = cmd->add_option(
      "--json", args->json_path,
      "Also write the report as JSON to this file ('-': standard output, instead of "
      "the table)");
  CLI::Option* overlays =
      cmd->add_option("--overlays", args->overlays_dir,
                      "Write an overlay per case here: arrows occludee -> occluder, '=' for equal, "
                      "wrong pairs ringed in red");
  cmd->add_flag("--from-strokes", args->from_strokes,
                "Layer regions segmented from each case's strokes.json instead of regions.png");
  cmd->add_flag("--with-joins", args->with_joins,
                "Score the relations revised by completion's strand joins (the pieces of one "
                "strand at one depth, weak relations to a strand's pieces made to agree)");
  cmd->add_option("--open-order-log-odds", args->open_order_log_odds,
                  "Order an open pair (equal only for want of a drawn line) whose open boundaries' "
                  "mean same-depth log-odds is below this (layering::Options::open_order_log_odds; "
                  "-inf: never)")
      ->capture_default_str();
  cmd->callback([args, json, overlays, &common] {
    // Given but empty (a script's unset variable) is not "not given": the
    // report or the overlays would silently go nowhere.
    if (json->count() > 0 && args->json_path.empty())
      throw Error("--json \"\": give the report a file name (or '-' for standard output)");
    if (overlays->count() > 0 && args->overlays_dir.empty())
      throw Error(
          "--overlays \"\": give the output folder a name of its own (not \"\", \".\" or "
          "\"..\")");
    {
      // find_annotated_cases says "not a folder of annotated cases" for both.
      std::error_code ec;
      const auto status = std::filesystem::status(args->cases_dir, ec);
      if (status.type() == std::filesystem::file_type::not_found)
        throw Error(args->cases_dir + ": no such folder (CASES_DIR: a folder of annotated cases)");
      if (!ec && status.type() != std::filesystem::file_type::directory)
        throw Error(args->cases_dir + ": is a file; CASES_DIR must be a folder of annotated cases");
    }
    pipeline::LayeringEvalOptions options;
    options.from_strokes = args->from_strokes;
    options.with_joins = args->with_joins;
    options.layering.open_order_log_odds = args->open_order_log_odds;
    // Checked once here: each case would otherwise fail alone with the same
    // message, and the table of zeros would exit 0.
    if (std::string why; !options.layering.is_valid(&why))
      throw Error("--open-order-log-odds: " + why);
    const std::vector<std::filesystem::path> cases = find_annotated_cases(args->cases_dir);
    const bool json_to_stdout = args->json_path == "-";
    if (!args->json_path.empty() && !json_to_stdout) {
      check_output_file(args->json_path, "--json");
      // The report would replace a case's own file (its layering.json, its drawing).
      for (const auto& c : cases) {
        if (lies_inside(args->json_path, c))
          throw Error("--json " + args->json_path + ": lies in the case folder " + c.string() +
                      "; the report would replace the case's own files (write it elsewhere)");
      }
    }
    if (!args->overlays_dir.empty()) {
      std::vector<std::string> names;
      for (const auto& c : cases) names.push_back(annotated_case_name(c) + ".png");
      check_output_folder(args->overlays_dir, "--overlays", names, kOverlaysKind);
      check_inputs_outside(args->overlays_dir, {args->cases_dir}, "--overlays");
    }
    TerminalProgress progress(stderr, TerminalProgress::pick_mode(stderr, common.quiet));
    pipeline::LayeringEvalReport report;
    if (args->overlays_dir.empty()) {
      report = pipeline::evaluate_layering(args->cases_dir, options, &progress);
    } else {
      // The overlays go to a temporary folder renamed into place only when
      // every case has been scored: a failure leaves no partial set.
      write_folder_atomically(
          args->overlays_dir,
          [&](const std::filesystem::path& tmp) {
            options.overlays_dir = tmp;
            report = pipeline::evaluate_layering(args->cases_dir, options, &progress);
          },
          kOverlaysKind);
    }
    progress.end_line();
    if (json_to_stdout) {
      // The table would make standard output unreadable as JSON.
      std::fputs(pipeline::layering_report_json(report).c_str(), stdout);
      return;
    }
    if (!args->json_path.empty()) {
      const std::filesystem::path json(args->json_path);
      std::error_code ec;
      if (json.has_parent_path()) std::filesystem::create_directories(json.parent_path(), ec);
      if (ec)
        throw Error("--json " + args->json_path + ": cannot create its folder: " + ec.message());
      write_text_atomically(json, pipeline::layering_report_json(report));
    }
    std::fputs(pipeline::format_layering_table(report).c_str(), stdout);
  });
}

}  // namespace hair25d::cli
