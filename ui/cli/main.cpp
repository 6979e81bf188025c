// hair25d: the command line. Exit status 0 done, 1 bad input (a file, or an
// option's value that breaks its rule) or failure (one line on stderr saying
// what and where), 2 wrong usage (an unknown or missing option or command).
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <string_view>

#include "commands.h"
#include "hair25d/core/error.h"

int main(int argc, char** argv) {
  using namespace hair25d::cli;
  CLI::App app{"hair25d: 2.5D cartoon hair modelling and animation from one drawing", "hair25d"};
  app.require_subcommand(1);
  // --help shows every option's default (set before the commands copy it).
  app.option_defaults()->always_capture_default();
  CommonOptions common;
  app.add_flag("-q,--quiet", common.quiet, "Print no progress");
  add_version_command(app, common);
  add_segment_command(app, common);
  add_eval_layering_command(app, common);
  add_model_command(app, common);
  // -q after the command too (hair25d model -q ...), and listed in its --help.
  for (CLI::App* command : app.get_subcommands({}))
    command->add_flag("-q,--quiet", common.quiet, "Print no progress");
  // A word where the command should be that names none: say so and list them
  // (CLI11 would take it for a stray argument and say a command is required).
  for (int i = 1; i < argc; ++i) {
    const std::string_view word = argv[i];
    if (word == "-q" || word == "--quiet") continue;
    if (word.empty() || word[0] == '-') break;  // --help, or an option CLI11 reports
    const auto commands = app.get_subcommands({});
    if (std::none_of(commands.begin(), commands.end(),
                     [&](const CLI::App* c) { return c->check_name(std::string(word)); })) {
      std::string names;
      for (const CLI::App* command : commands)
        names += (names.empty() ? "" : ", ") + command->get_name();
      std::fprintf(stderr, "hair25d: unknown command '%s'; the commands are: %s\n", argv[i],
                   names.c_str());
      return 2;
    }
    break;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ValidationError& e) {
    // A value that breaks its option's rule (--colour-tolerance 500) is bad
    // input like a bad file: one line, status 1 (as hair25d-generate).
    std::fprintf(stderr, "hair25d: %s\n", e.what());
    return 1;
  } catch (const CLI::ConversionError& e) {
    std::fprintf(stderr, "hair25d: %s\n", e.what());
    return 1;
  } catch (const CLI::ParseError& e) {
    // Wrong usage: an unknown or missing option or argument.
    std::fprintf(stderr, "hair25d: %s\nRun with --help for more information.\n", e.what());
    return 2;
  } catch (const hair25d::Error& e) {
    std::fprintf(stderr, "hair25d: %s\n", e.what());
    return 1;
  } catch (const std::filesystem::filesystem_error& e) {
    // A path the library did not check itself: still say which and why.
    std::fprintf(stderr, "hair25d: %s: %s\n", e.path1().string().c_str(),
                 e.code().message().c_str());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hair25d: internal error: %s\n", e.what());
    return 1;
  }
  return 0;
}
