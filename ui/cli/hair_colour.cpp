#include "hair_colour.h"

#include <cstdio>

#include "hair25d/core/error.h"

namespace hair25d::cli {

std::array<std::uint8_t, 3> parse_hair_colour(const std::string& text) {
  unsigned r = 0, g = 0, b = 0;
  char tail = 0;
  if (text.size() != 7 || std::sscanf(text.c_str(), "#%2x%2x%2x%c", &r, &g, &b, &tail) != 3)
    throw Error("--hair-colour \"" + text + "\": expected #RRGGBB, e.g. #8a5a3c");
  return {static_cast<std::uint8_t>(r), static_cast<std::uint8_t>(g), static_cast<std::uint8_t>(b)};
}

}  // namespace hair25d::cli
