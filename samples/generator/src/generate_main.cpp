// hair25d-generate: writes synthetic annotated cartoon-hair cases (FORMATS.md)
// to a folder, one sub-folder a case, for tests, benchmarks and eval-layering.
// Exit status as hair25d's (docs/cli.md): 0 done; 1 a bad option value, bad
// input or a failure, one line on stderr naming the option, value and rule;
// 2 wrong usage (an unknown or missing option).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "hair25d/core/atomic_file.h"
#include "hair25d/core/error.h"
#include "hair25d/generator/generator.h"

namespace {

namespace gen = hair25d::generator;

// The numbers too, as scripts and docs written before the names use them.
const std::map<std::string, int> kShadingNames = {
    {"flat", 0}, {"two-tone", 1}, {"gradient", 2}, {"screentone", 3}, {"mixed", -1},
    {"0", 0},    {"1", 1},        {"2", 2},        {"3", 3},          {"-1", -1}};

// The mark write_folder_atomically leaves in the -o folder: a second run
// replaces the whole set (no stale case005 from a run of --count 6 after one
// of --count 2), and a folder of other files is refused.
constexpr const char* kCasesKind = "generated cases";

// A whole number in [lo, hi]; CLI::Range says "Value abc not in range" for
// text and lets 1.5 through as 1.
CLI::Validator whole_number(int lo, int hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        const bool digits =
            !text.empty() && text.size() <= 9 && std::all_of(text.begin(), text.end(), [](char c) {
              return std::isdigit(static_cast<unsigned char>(c));
            });
        const int value = digits ? std::stoi(text) : lo - 1;
        if (value < lo || value > hi)
          return "must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                 ", not " + text;
        return {};
      },
      std::to_string(lo) + "-" + std::to_string(hi));
}

// Before conversion: "Could not convert: --width = 1e11" named no rule. The
// ranges themselves are generator::Options::is_valid's, checked after.
CLI::Validator a_number(bool whole) {
  return CLI::Validator(
      [whole](std::string& text) -> std::string {
        try {
          std::size_t used = 0;
          if (whole) {
            (void)std::stoi(text, &used);
          } else {
            (void)std::stod(text, &used);
          }
          if (used == text.size()) return {};
        } catch (const std::exception&) {
        }
        return whole ? "must be a whole number (of at most 9 digits), not " + text
                     : "must be a number, not " + text;
      },
      "");
}

// The generator's own check names its fields (generator::Options::width):
// say the option the user typed instead.
std::string with_option_names(std::string why) {
  static const std::pair<const char*, const char*> kOptions[] = {
      {"width", "--width"},           {"height", "--height"},     {"strand_count", "--strands"},
      {"line_width", "--line-width"}, {"noise_sigma", "--noise"}, {"jpeg_quality", "--jpeg"},
      {"shading", "--shading"}};
  for (const auto& [field, option] : kOptions) {
    const std::string prefix = std::string("generator::Options::") + field + " = ";
    if (why.rfind(prefix, 0) == 0) {
      why = std::string(option) + " " + why.substr(prefix.size());
      if (const auto semi = why.find("; "); semi != std::string::npos) why.replace(semi, 2, ": ");
      break;
    }
  }
  return why;
}

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
  app.add_option("--count", count, "Number of cases")->check(whole_number(1, 100000));
  app.add_option("--seed", seed, "Seed of the first case; case i uses seed + i")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            // CLI11 would take -1 for 2^64 - 1.
            const bool digits = !text.empty() && text.size() <= 19 &&
                                std::all_of(text.begin(), text.end(), [](char c) {
                                  return std::isdigit(static_cast<unsigned char>(c));
                                });
            return digits ? std::string()
                          : "must be a whole number from 0 to 10^19 - 1, not " + text;
          },
          "0-9999999999999999999"));
  app.add_option("--width", opt.width, "Image width, pixels")->check(a_number(true));
  app.add_option("--height", opt.height, "Image height, pixels")->check(a_number(true));
  app.add_option("--strands", opt.strand_count, "Hair strands a case")->check(a_number(true));
  app.add_option("--line-width", opt.line_width, "Outline width, pixels")->check(a_number(false));
  app.add_option("--shading", shading, "flat, two-tone, gradient, screentone, or mixed (cycles)")
      ->transform(CLI::Validator(
          [](std::string& text) -> std::string {
            std::string lower;
            for (char c : text)
              lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            const auto it = kShadingNames.find(lower);
            if (it == kShadingNames.end())
              return "must be flat, two-tone, gradient, screentone or mixed, not " + text;
            text = std::to_string(it->second);
            return {};
          },
          "flat|two-tone|gradient|screentone|mixed"));
  app.add_option("--noise", opt.noise_sigma, "Gaussian noise sigma, 0..255 scale")
      ->check(a_number(false));
  app.add_option("--jpeg", opt.jpeg_quality, "JPEG round trip at this quality (0 = none)")
      ->check(a_number(true));
  app.add_flag("--coloured-lines", coloured, "Outlines in a dark hair colour, not black");
  bool fading = false;
  app.add_flag("--fading-forks", fading,
               "Fork lines stop inside the strand; the annotation still splits it");
  bool dark = false;
  app.add_flag("--dark-hair", dark,
               "Hair painted about as dark as the ink (black-haired manga), a third on a dark "
               "backdrop");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ValidationError& e) {
    // A value that breaks its option's rule is bad input: one line, status 1.
    std::fprintf(stderr, "hair25d-generate: %s\n", e.what());
    return 1;
  } catch (const CLI::ConversionError& e) {
    std::fprintf(stderr, "hair25d-generate: %s\n", e.what());
    return 1;
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "hair25d-generate: %s\nRun with --help for more information.\n", e.what());
    return 2;
  }
  opt.coloured_lines = coloured;
  opt.fading_forks = fading;
  opt.dark_hair = dark;
  // Every case's options checked before the folder is made: a bad --width
  // leaves nothing behind.
  {
    gen::Options o = opt;
    o.shading = static_cast<gen::Shading>(std::max(shading, 0));  // mixed: each is valid
    std::string why;
    if (!o.is_valid(&why)) {
      std::fprintf(stderr, "hair25d-generate: %s\n", with_option_names(why).c_str());
      return 1;
    }
  }

  try {
    std::vector<std::string> names;
    for (int i = 0; i < count; ++i) names.push_back(case_name(i));
    hair25d::check_output_folder(out, "-o", names, kCasesKind);
    // Written under a temporary name and swapped in when every case is there:
    // a run stopped half-way leaves no half set that looks whole.
    hair25d::write_folder_atomically(
        out,
        [&](const std::filesystem::path& tmp) {
          for (int i = 0; i < count; ++i) {
            gen::Options o = opt;
            o.seed = seed + static_cast<std::uint64_t>(i);
            o.shading = static_cast<gen::Shading>(shading >= 0 ? shading : i % 4);
            const auto t0 = std::chrono::steady_clock::now();
            hair25d::AnnotatedCase c = gen::generate_case(o);
            const auto t1 = std::chrono::steady_clock::now();
            c.name = case_name(i);
            hair25d::write_annotated_case(tmp / c.name, c);
            const auto t2 = std::chrono::steady_clock::now();
            std::printf(
                "%s  seed %llu  %dx%d  %zu regions  %zu pairs  generate %.3f s  write %.3f s\n",
                c.name.c_str(), static_cast<unsigned long long>(o.seed), o.width, o.height,
                c.region_list.size(), c.pairs.size(),
                std::chrono::duration<double>(t1 - t0).count(),
                std::chrono::duration<double>(t2 - t1).count());
          }
        },
        kCasesKind);
  } catch (const std::filesystem::filesystem_error& e) {
    std::fprintf(stderr, "hair25d-generate: %s: %s\n", e.path1().string().c_str(),
                 e.code().message().c_str());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hair25d-generate: %s\n", e.what());
    return 1;
  }
  return 0;
}
