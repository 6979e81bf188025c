// --hair-colour #RRGGBB: the colour that tells hair regions from the rest when
// a drawing comes without strokes (segment and model share it).
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

namespace hair25d::cli {

// Parses "#RRGGBB"; throws hair25d::Error naming the value and the rule.
std::array<std::uint8_t, 3> parse_hair_colour(const std::string& text);

// --colour-tolerance T: finite, in [0, 442], and only with --hair-colour
// (`colour`), where it means something.
CLI::Option* add_colour_tolerance(CLI::App* cmd, double* tolerance, CLI::Option* colour);

}  // namespace hair25d::cli
