// The sub-commands of the hair25d command line (DESIGN.md "The command line").
// Each add_*_command registers its options and a callback on the CLI11 app.
#pragma once

#include <CLI/CLI.hpp>

#include "progress_bar.h"

namespace hair25d::cli {

// Options every command shares.
struct CommonOptions {
  bool quiet = false;  // --quiet: no progress output
};

// For an option or argument that names a file or a colour: an empty value
// (a script's unset variable) is refused rather than taken for "not given"
// (--strokes "" segmented automatically) or for a file named "".
inline CLI::Validator not_empty(const std::string& what) {
  return CLI::Validator(
      [what](std::string& text) -> std::string {
        return text.empty() ? "\"\": give " + what + " (the value is empty)" : std::string();
      },
      "");
}

void add_version_command(CLI::App& app, const CommonOptions& common);
void add_segment_command(CLI::App& app, const CommonOptions& common);
void add_eval_layering_command(CLI::App& app, const CommonOptions& common);
void add_model_command(CLI::App& app, const CommonOptions& common);

}  // namespace hair25d::cli
