// hair25d-generate: writes synthetic annotated cartoon-hair cases (FORMATS.md)
// to a folder, one sub-folder a case, for tests, benchmarks and eval-layering.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include "hair25d/core/error.h"
#include "hair25d/generator/generator.h"

namespace {

namespace gen = hair25d::generator;

const std::map<std::string, int> kShadingNames = {
    {"flat", 0}, {"two-tone", 1}, {"gradient", 2}, {"screentone", 3}, {"mixed", -1}};

std::string case_name(int index) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "case%03d", index);
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Writes synthetic cartoon-hair drawings with exact layering ground truth"};
  app.option_defaults()->always_capture_default();  // --help shows the defaults
  std::filesystem::path out;
  int count = 1;
  std::uint64_t seed = 1;
  gen::Options opt;
  int shading = 0;
  bool coloured = false;
  app.add_option("-o,--output", out, "Folder to write case000, case001, ... into")->required();
  app.add_option("--count", count, "Number of cases")->check(CLI::Range(1, 100000));
  app.add_option("--seed", seed, "Seed of the first case; case i uses seed + i");
  app.add_option("--width", opt.width, "Image width, pixels");
  app.add_option("--height", opt.height, "Image height, pixels");
  app.add_option("--strands", opt.strand_count, "Hair strands a case");
  app.add_option("--line-width", opt.line_width, "Outline width, pixels");
  app.add_option("--shading", shading, "flat, two-tone, gradient, screentone, or mixed (cycles)")
      ->transform(CLI::CheckedTransformer(kShadingNames, CLI::ignore_case));
  app.add_option("--noise", opt.noise_sigma, "Gaussian noise sigma, 0..255 scale");
  app.add_option("--jpeg", opt.jpeg_quality, "JPEG round trip at this quality (0 = none)");
  app.add_flag("--coloured-lines", coloured, "Outlines in a dark hair colour, not black");
  bool fading = false;
  app.add_flag("--fading-forks", fading,
               "Fork lines stop inside the strand; the annotation still splits it");
  CLI11_PARSE(app, argc, argv);
  opt.coloured_lines = coloured;
  opt.fading_forks = fading;

  try {
    std::filesystem::create_directories(out);
    for (int i = 0; i < count; ++i) {
      gen::Options o = opt;
      o.seed = seed + static_cast<std::uint64_t>(i);
      o.shading = static_cast<gen::Shading>(shading >= 0 ? shading : i % 4);
      const auto t0 = std::chrono::steady_clock::now();
      hair25d::AnnotatedCase c = gen::generate_case(o);
      const auto t1 = std::chrono::steady_clock::now();
      c.name = case_name(i);
      hair25d::write_annotated_case(out / c.name, c);
      const auto t2 = std::chrono::steady_clock::now();
      std::printf("%s  seed %llu  %dx%d  %zu regions  %zu pairs  generate %.3f s  write %.3f s\n",
                  c.name.c_str(), static_cast<unsigned long long>(o.seed), o.width, o.height,
                  c.region_list.size(), c.pairs.size(),
                  std::chrono::duration<double>(t1 - t0).count(),
                  std::chrono::duration<double>(t2 - t1).count());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hair25d-generate: %s\n", e.what());
    return 1;
  }
  return 0;
}
