#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "commands.h"
#include "hair25d/core/atomic_file.h"
#include "hair25d/core/error.h"
#include "hair25d/core/image_io.h"
#include "hair25d/core/strokes.h"
#include "hair25d/pipeline/hair_check.h"
#include "hair25d/pipeline/head_center.h"
#include "hair25d/pipeline/model_stage.h"
#include "hair25d/pipeline/segment_stage.h"
#include "hair_colour.h"

namespace hair25d::cli {

void add_model_command(CLI::App& app, const CommonOptions& common) {
  struct Args {
    std::string image;
    std::string strokes;
    std::string regions;
    std::string out;
    std::vector<double> head;
    std::string hair_colour;
    double tolerance = 40.0;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "model",
      "Build the 2.5D hair model (paper §3–§6): segment, layer, complete and skeletonise "
      "every strand, and write the model folder with a contact sheet");
  cmd->add_option("image", args->image, "The drawing (PNG, JPEG, TIFF, PSD, ...)")
      ->required()
      ->check(not_empty("the drawing's file name"));
  auto* strokes = cmd->add_option("--strokes", args->strokes,
                                  "strokes.json: labelled hair strokes (and the head centre)")
                      ->check(not_empty("the strokes file's name"));
  auto* regions =
      cmd->add_option(
             "--regions", args->regions,
             "regions.png: hair region ids (0 = background and outlines) instead of segmenting")
          ->check(not_empty("the region map's file name"));
  auto* colour =
      cmd->add_option(
             "--hair-colour", args->hair_colour,
             "Without strokes or regions: the regions of this colour (#RRGGBB) are the hair, one "
             "strand each")
          ->check(not_empty("a colour #RRGGBB"));
  add_colour_tolerance(cmd, &args->tolerance, colour);
  strokes->excludes(regions)->excludes(colour);
  regions->excludes(strokes)->excludes(colour);
  colour->excludes(strokes)->excludes(regions);
  cmd->add_option("--head", args->head, "Head centre X Y in pixels (overrides strokes.json)")
      ->expected(2)
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            // "Could not convert: --head = a,b" named neither the rule nor which.
            try {
              std::size_t used = 0;
              (void)std::stod(text, &used);
              if (used == text.size()) return {};
            } catch (const std::exception&) {
            }
            return "X and Y must be numbers (pixels), not " + text;
          },
          "NUMBER"))
      ->default_str("");  // none by default ("[]" says nothing)
  cmd->add_option("-o,--output", args->out,
                  "The model folder to write (an earlier model there is replaced; a folder of "
                  "other files is refused)")
      ->required();
  cmd->callback([args, &common] {
    using Clock = std::chrono::steady_clock;
    const auto seconds_since = [](Clock::time_point t) {
      return std::chrono::duration<double>(Clock::now() - t).count();
    };
    if (args->strokes.empty() && args->regions.empty() && args->hair_colour.empty()) {
      // Automatic regions take every enclosed area for a strand: the paper,
      // the face and the clothes would be completed and animated as hair.
      // Wrong usage (status 2), as a missing -o is.
      throw CLI::RequiredError(
          "model: say which regions are hair: --strokes S.json, --regions R.png or "
          "--hair-colour #RRGGBB",
          CLI::ExitCodes::RequiredError);
    }
    pipeline::check_model_folder(args->out, "-o");
    check_inputs_outside(args->out, {args->image, args->strokes, args->regions}, "-o");
    std::optional<std::array<std::uint8_t, 3>> hair_colour;
    if (!args->hair_colour.empty()) hair_colour = parse_hair_colour(args->hair_colour);
    auto start = Clock::now();
    const Image image = load_image(args->image);
    const double load_seconds = seconds_since(start);
    TerminalProgress progress(stderr, TerminalProgress::pick_mode(stderr, common.quiet));
    std::optional<Vec2> head;
    if (args->head.size() == 2) head = Vec2(args->head[0], args->head[1]);
    if (head) pipeline::check_head_center(*head, image.width(), image.height(), "--head");
    pipeline::ModelRun run;
    if (!args->regions.empty()) {
      const LabelMap regions = load_label_map(args->regions);
      if (regions.width() != image.width() || regions.height() != image.height())
        throw Error(args->regions + ": regions are " + std::to_string(regions.width()) + "x" +
                    std::to_string(regions.height()) + ", the image " +
                    std::to_string(image.width()) + "x" + std::to_string(image.height()) +
                    "; they must be the same size");
      if (regions.labels().empty())
        throw Error(args->regions +
                    ": no hair region: every pixel is 0 (hair regions are 1, 2, ...)");
      run = pipeline::run_model(image, regions, head, {}, &progress);
    } else if (hair_colour) {
      start = Clock::now();
      const pipeline::SegmentRun seg =
          pipeline::run_segment_by_colour(image, *hair_colour, args->tolerance, &progress);
      const double segment_seconds = seconds_since(start);
      run = pipeline::run_model(image, seg.regions, head, {}, &progress);
      run.seconds["segment"] = segment_seconds;
    } else {
      Strokes s = read_strokes(args->strokes);
      if (head)
        s.head_center = head;
      else if (s.head_center)
        pipeline::check_head_center(*s.head_center, image.width(), image.height(),
                                    args->strokes + ": head_center");
      run = pipeline::run_model(image, &s, {}, &progress);
    }
    progress.end_line();
    const std::string source = !args->regions.empty() ? args->regions
                               : hair_colour          ? "--hair-colour " + args->hair_colour
                                                      : args->strokes;
    for (const std::string& w : pipeline::hair_region_warnings(run.regions, source))
      std::fprintf(stderr, "warning: %s\n", w.c_str());
    start = Clock::now();
    pipeline::write_model_run(args->out, run);
    run.seconds["write"] = seconds_since(start);
    run.seconds["load"] = load_seconds;
    if (!common.quiet) {
      std::printf("model: %s -> %s\n", run.summary.c_str(), args->out.c_str());
      std::printf("model: seconds");
      for (const auto& [stage, seconds] : run.seconds)
        std::printf(" %s %.3f", stage.c_str(), seconds);
      std::printf("\n");
    }
  });
}

}  // namespace hair25d::cli
