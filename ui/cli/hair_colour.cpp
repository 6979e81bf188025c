#include "hair_colour.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include "hair25d/core/error.h"

namespace hair25d::cli {

std::array<std::uint8_t, 3> parse_hair_colour(const std::string& text) {
  // Every digit checked: sscanf's %2x also takes signs and spaces ("#-1-1-1").
  const bool hex = text.size() == 7 && text[0] == '#' &&
                   std::all_of(text.begin() + 1, text.end(),
                               [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); });
  if (!hex) throw Error("--hair-colour \"" + text + "\": expected #RRGGBB, e.g. #8a5a3c");
  const auto channel = [&](int at) {
    return static_cast<std::uint8_t>(std::stoi(text.substr(at, 2), nullptr, 16));
  };
  return {channel(1), channel(3), channel(5)};
}

CLI::Option* add_colour_tolerance(CLI::App* cmd, double* tolerance, CLI::Option* colour) {
  // One check for NaN (CLI::Range lets it through: every comparison with it
  // is false) and the range, whose bounds CLI::Range would print as 442.000000.
  const CLI::Validator finite_in_range(
      [](std::string& text) {
        try {
          std::size_t used = 0;
          const double value = std::stod(text, &used);
          if (used != text.size()) return "must be a number from 0 to 442, not " + text;
          if (!std::isfinite(value)) return std::string("must be a finite number");
          if (value < 0.0 || value > 442.0) return "must be a number from 0 to 442, not " + text;
          return std::string();
        } catch (const std::out_of_range&) {
          return "must be a number from 0 to 442, not " + text;  // 1e999
        } catch (const std::exception&) {
          return "must be a number from 0 to 442, not " + text;
        }
      },
      "0-442");
  return cmd
      ->add_option("--colour-tolerance", *tolerance,
                   "RGB distance (0-255) a region's mean colour may be from --hair-colour")
      ->check(finite_in_range)
      ->needs(colour);
}

}  // namespace hair25d::cli
