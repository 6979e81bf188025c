// Looks at the pairs layering gets wrong on annotated cases, for choosing
// what to train and change (never part of a result): per wrong pair, what
// was measured on each of its boundaries, and a close-up PNG of the drawing
// with the two regions tinted (a red, b blue) and their boundaries marked.
//
//   train_layering_diag CASES_DIR OUT_DIR
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>

#include "hair25d/core/annotation.h"
#include "hair25d/core/error.h"
#include "hair25d/core/image_io.h"
#include "hair25d/layering/evaluation.h"
#include "hair25d/layering/layering.h"

namespace {
namespace layering = hair25d::layering;
using hair25d::Image;
using hair25d::Relation;

Image close_up(const hair25d::AnnotatedCase& c, const layering::Result& r, int a, int b,
               int scale) {
  const hair25d::LabelMap& lab = r.labels;
  int x0 = lab.width(), y0 = lab.height(), x1 = 0, y1 = 0;
  for (const layering::Boundary& bd : r.graph.boundaries) {
    if (!((bd.left == a && bd.right == b) || (bd.left == b && bd.right == a))) continue;
    for (const hair25d::Vec2& p : bd.points) {
      x0 = std::min(x0, static_cast<int>(p.x()));
      y0 = std::min(y0, static_cast<int>(p.y()));
      x1 = std::max(x1, static_cast<int>(p.x()));
      y1 = std::max(y1, static_cast<int>(p.y()));
    }
  }
  if (x1 < x0) x0 = y0 = 0, x1 = lab.width() - 1, y1 = lab.height() - 1;
  const int pad = 40;
  x0 = std::max(0, x0 - pad);
  y0 = std::max(0, y0 - pad);
  x1 = std::min(lab.width() - 1, x1 + pad);
  y1 = std::min(lab.height() - 1, y1 + pad);
  const int w = x1 - x0 + 1, h = y1 - y0 + 1;
  Image out(2 * w * scale + scale, h * scale, {255, 255, 255, 255});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const hair25d::Rgba p = c.image.at(x0 + x, y0 + y);
      hair25d::Rgba q = p;
      const int l = lab.at(x0 + x, y0 + y);
      if (l == a)
        q = {static_cast<std::uint8_t>((p.r + 255) / 2), static_cast<std::uint8_t>(p.g / 2),
             static_cast<std::uint8_t>(p.b / 2), 255};
      if (l == b)
        q = {static_cast<std::uint8_t>(p.r / 2), static_cast<std::uint8_t>(p.g / 2),
             static_cast<std::uint8_t>((p.b + 255) / 2), 255};
      q.a = 255;
      for (int dy = 0; dy < scale; ++dy)
        for (int dx = 0; dx < scale; ++dx) {
          out.at(x * scale + dx, y * scale + dy) = {p.r, p.g, p.b, 255};
          out.at((w + 1) * scale + x * scale + dx, y * scale + dy) = q;
        }
    }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Wrong layering pairs, close up"};
  std::string cases_dir, out_dir;
  int scale = 3;
  app.add_option("cases", cases_dir)->required();
  app.add_option("out", out_dir)->required();
  app.add_option("--scale", scale);
  layering::Options options;
  std::string coupling = "smooth";
  bool quiet = false, no_equal = false, paper = false;
  app.add_option("--coupling", coupling, "smooth, all or none");
  app.add_option("--learned-scale", options.learned_scale);
  app.add_option("--cap", options.coupling_cap);
  app.add_option("--smooth-angle", options.smooth_angle);
  app.add_flag("--no-equal", no_equal);
  app.add_option("--equal-log-odds", options.equal_log_odds);
  app.add_flag("--context", options.region_context);
  app.add_flag("--paper", paper);
  bool no_patches = false;
  app.add_flag("--no-patches", no_patches, "without the junction patch model");
  app.add_flag("--quiet", quiet, "totals only");
  CLI11_PARSE(app, argc, argv);
  options.coupling = coupling == "all"    ? layering::Coupling::kAllPairs
                     : coupling == "none" ? layering::Coupling::kNone
                                          : layering::Coupling::kSmoothestPair;
  options.learned_equal = !no_equal;
  options.junction_patches = !no_patches;
  if (paper) options.metric = layering::Metric::kPaper;
  int total = 0, right = 0;
  std::filesystem::create_directories(out_dir);
  for (const auto& folder : hair25d::find_annotated_cases(cases_dir)) {
    const hair25d::AnnotatedCase c = hair25d::read_annotated_case(folder);
    layering::Result r;
    const layering::CaseScore s = layering::evaluate_case(c, options, &r);
    total += s.pairs;
    right += s.correct;
    if (quiet) continue;
    std::map<int, int> strand;
    for (const auto& reg : c.region_list) strand[reg.id] = reg.strand;
    for (const layering::PairOutcome& o : s.outcomes) {
      if (o.correct) continue;
      bool over = false;
      for (auto [p, q] : r.overridden) over |= (p == o.a && q == o.b) || (p == o.b && q == o.a);
      double score = 0;
      for (const auto& rel : r.relations)
        if ((rel.a == o.a && rel.b == o.b) || (rel.a == o.b && rel.b == o.a)) score = rel.score;
      std::printf("%s %d/%d (strands %d/%d) truth %s predicted %s%s score %.3f\n", c.name.c_str(),
                  o.a, o.b, strand[o.a], strand[o.b], hair25d::to_string(o.truth),
                  o.predicted ? hair25d::to_string(*o.predicted) : "none",
                  over ? " OVERRIDDEN" : "", score);
      for (std::size_t i = 0; i < r.boundaries.size(); ++i) {
        const layering::BoundaryReport& b = r.boundaries[i];
        if (!((b.left == o.a && b.right == o.b) || (b.left == o.b && b.right == o.a))) continue;
        const double sgn = b.left == o.a ? 1 : -1;  // toward a above
        std::printf(
            "   len %.0f occ %d contrast %.0f low %.0f col %.1f | learned(a up) %+.2f phiJ %+.2f "
            "phiR %+.2f patch %+.2f -> %+.2f | equal %+.2f state(a up) %+d | start %s %.0f/%.0f "
            "n%d end %s %.0f/%.0f "
            "n%d\n",
            b.length, b.occluding, b.line_contrast, b.line_contrast_low, b.colour_difference,
            sgn * b.learned, sgn * b.phi_j, sgn * b.phi_r, sgn * b.patch, sgn * b.patch_log_odds,
            b.equal, static_cast<int>(sgn) * b.state, b.cues.start.used ? "T" : "-",
            b.cues.start.left * 57.3, b.cues.start.right * 57.3, b.cues.start.rays,
            b.cues.end.used ? "T" : "-", b.cues.end.left * 57.3, b.cues.end.right * 57.3,
            b.cues.end.rays);
      }
      hair25d::save_image(std::filesystem::path(out_dir) / (c.name + "_" + std::to_string(o.a) +
                                                            "_" + std::to_string(o.b) + ".png"),
                          close_up(c, r, o.a, o.b, scale));
    }
  }
  std::printf("total %d / %d = %.1f%%\n", right, total, 100.0 * right / std::max(total, 1));
  return 0;
}
