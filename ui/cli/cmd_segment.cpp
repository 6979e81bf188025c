#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "commands.h"
#include "hair25d/core/atomic_file.h"
#include "hair25d/core/error.h"
#include "hair25d/core/image_io.h"
#include "hair25d/core/strokes.h"
#include "hair25d/pipeline/hair_check.h"
#include "hair25d/pipeline/segment_stage.h"
#include "hair_colour.h"

namespace hair25d::cli {

void add_segment_command(CLI::App& app, const CommonOptions& common) {
  struct Args {
    std::string image;
    std::string strokes;
    std::string out;
    std::string hair_colour;
    double tolerance = 40.0;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "segment", "Split a drawing into hair regions (paper §3): from strokes, or automatic");
  cmd->add_option("image", args->image, "The drawing (PNG, JPEG, TIFF, PSD, ...)")
      ->required()
      ->check(not_empty("the drawing's file name"));
  cmd->add_option("--strokes", args->strokes,
                  "strokes.json: labelled hair strokes; without it every face enclosed by "
                  "lines becomes a region")
      ->check(not_empty("the strokes file's name"));
  CLI::Option* colour =
      cmd->add_option("--hair-colour", args->hair_colour,
                      "Without strokes: take the regions of this colour (#RRGGBB) as the hair, "
                      "one region each")
          ->check(not_empty("a colour #RRGGBB"))
          ->excludes(cmd->get_option("--strokes"));
  add_colour_tolerance(cmd, &args->tolerance, colour);
  cmd->add_option("-o,--output", args->out,
                  "Folder to write regions.png, segmentation.json and overlay.png into")
      ->required();
  cmd->callback([args, &common] {
    pipeline::check_segment_folder(args->out, "-o");
    check_inputs_outside(args->out, {args->image, args->strokes}, "-o");
    const Image image = load_image(args->image);
    std::optional<Strokes> strokes;
    if (!args->strokes.empty()) strokes = read_strokes(args->strokes);
    TerminalProgress progress(stderr, TerminalProgress::pick_mode(stderr, common.quiet));
    pipeline::SegmentRun run;
    if (!args->hair_colour.empty()) {
      run = pipeline::run_segment_by_colour(image, parse_hair_colour(args->hair_colour),
                                            args->tolerance, &progress);
    } else {
      run = pipeline::run_segment(image, strokes ? &*strokes : nullptr, &progress);
    }
    pipeline::write_segment_run(args->out, run);
    progress.end_line();
    // Automatic regions include the paper on purpose; marked hair should not.
    if (strokes || !args->hair_colour.empty())
      for (const std::string& w : pipeline::hair_region_warnings(
               run.regions, strokes ? args->strokes : "--hair-colour " + args->hair_colour))
        std::fprintf(stderr, "warning: %s\n", w.c_str());
    std::set<int> regions(run.segmentation.triangle_region.begin(),
                          run.segmentation.triangle_region.end());
    regions.erase(0);
    if (!common.quiet)
      std::printf("segment: %zu regions, %d triangles, %zu curves -> %s\n", regions.size(),
                  run.segmentation.mesh.triangle_count(), run.segmentation.curves.size(),
                  args->out.c_str());
  });
}

}  // namespace hair25d::cli
