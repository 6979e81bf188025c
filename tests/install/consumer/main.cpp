// Uses the installed core library: a strokes file parsed and a label map made.
#include <hair25d/core/strokes.h>

#include <cstdio>

int main() {
  const hair25d::Strokes s = hair25d::parse_strokes(
      R"({"format": "hair25d-strokes/1", "strokes": [{"label": 2, "width": 3, "points": [[1, 1]]}]})",
      "inline");
  const hair25d::LabelMap m = hair25d::rasterize_strokes(s, 4, 3);
  std::printf("%d\n", m.at(1, 1));
  return m.at(1, 1) == 2 ? 0 : 1;
}
