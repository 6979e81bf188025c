#include "hair25d/pipeline/hair_check.h"

#include <cmath>
#include <cstdio>
#include <map>

namespace hair25d::pipeline {

std::vector<std::string> hair_region_warnings(const LabelMap& regions, const std::string& source) {
  struct Reach {
    long long area = 0;
    bool left = false, right = false, top = false, bottom = false;
  };
  std::map<int, Reach> reach;
  const int w = regions.width(), h = regions.height();
  Reach* entry = nullptr;  // a run of one label looks its entry up once
  int last = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int l = regions.at(x, y);
      if (l <= 0) continue;
      if (entry == nullptr || l != last) entry = &reach[l], last = l;
      Reach& r = *entry;
      ++r.area;
      r.left |= x == 0, r.right |= x == w - 1, r.top |= y == 0, r.bottom |= y == h - 1;
    }
  std::vector<std::string> out;
  const double pixels = static_cast<double>(w) * h;
  for (const auto& [label, r] : reach) {
    const double share = r.area / pixels;
    const bool four_sides = r.left && r.right && r.top && r.bottom;
    if (share <= kMostOfTheDrawing && !four_sides) continue;
    char text[256];
    std::snprintf(text, sizeof text,
                  "hair region %d covers %.0f%% of the drawing%s: is it the paper? Check %s "
                  "(hair is expected to cover at most %.0f%% and to leave a side of the "
                  "drawing free; the model is built anyway)",
                  label, std::round(100 * share),
                  four_sides ? " and touches all four of its sides" : "", source.c_str(),
                  100 * kMostOfTheDrawing);
    out.emplace_back(text);
  }
  return out;
}

}  // namespace hair25d::pipeline
