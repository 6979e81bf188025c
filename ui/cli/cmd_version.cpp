#include <cstdio>

#include "commands.h"

namespace hair25d::cli {

void add_version_command(CLI::App& app, const CommonOptions&) {
  CLI::App* cmd = app.add_subcommand("version", "Print the version and licence");
  cmd->callback([] { std::printf("hair25d 0.1.0 — GPL-3.0-or-later\n"); });
}

}  // namespace hair25d::cli
