// hair25d: the command line. Exit status 0 done, 1 bad input or failure (one
// line on stderr saying what and where), 2 wrong usage.
#include <cstdio>
#include <exception>
#include <filesystem>

#include "commands.h"
#include "hair25d/core/error.h"

int main(int argc, char** argv) {
  using namespace hair25d::cli;
  CLI::App app{"hair25d: 2.5D cartoon hair modelling and animation from one drawing", "hair25d"};
  app.require_subcommand(1);
  CommonOptions common;
  app.add_flag("-q,--quiet", common.quiet, "Print no progress");
  add_version_command(app, common);
  add_segment_command(app, common);
  add_eval_layering_command(app, common);
  add_model_command(app, common);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
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
