// Looks at the pairs layering gets wrong on annotated cases, for choosing
// what to train and change (never part of a result): per wrong pair, what
// was measured on each of its boundaries, and a close-up PNG of the drawing
// with the two regions tinted (a red, b blue) and their boundaries marked.
//
//   train_layering_diag CASES_DIR OUT_DIR
//
// --widths prints each case's line width and threshold; --couplings tallies
// the couplings of Eq. (2) against the truth (--couplings-verbose lists the
// states they moved off their unary, with the couplings of each).
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
#include "hair25d/layering/metrics.h"

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

// Truth of a boundary's state (+1 left above, -1 right above, 0 unknown):
// from the judged pair for two hair regions, hair above the background
// (which is wrong for back hair behind a face or body: label 0 too).
int true_state(const std::map<std::pair<int, int>, Relation>& truth, int left, int right) {
  if (left < 0 || right < 0) return 0;
  if (left == 0) return right > 0 ? -1 : 0;
  if (right == 0) return 1;
  auto it = truth.find({left, right});
  if (it == truth.end() || it->second == Relation::kEqual) return 0;
  return it->second == Relation::kAbove ? 1 : -1;
}

// Tallies, over a set, of the smoothest-pair couplings of Eq. (2) against
// the truth (recomputed from the Result as layer_regions builds them).
struct CouplingTally {
  int coupled = 0, known = 0, violated = 0, violated_changed = 0;
  int states = 0, states_known = 0, unary_right = 0, state_right = 0, overturned = 0, rescued = 0;
  std::map<int, std::pair<int, int>> by_angle;  // degrees / 5 → (known, violated)
  // The shorter boundary's length / fit reach, in quarters → (known, violated).
  std::map<int, std::pair<int, int>> by_short;
};

void tally_couplings(const hair25d::AnnotatedCase& c, const layering::Result& r,
                     const layering::Options& o, CouplingTally* t, bool verbose, bool hair_only) {
  std::map<std::pair<int, int>, Relation> truth;
  for (const auto& p : c.pairs) {
    truth[{p.a, p.b}] = p.relation;
    truth[{p.b, p.a}] = hair25d::reversed(p.relation);
  }
  const auto& bs = r.graph.boundaries;
  const double reach = std::max(o.fit_reach_min, o.fit_reach_widths * r.line_width);
  struct Ray {
    int b;
    hair25d::Vec2 dir;
  };
  std::vector<std::vector<Ray>> rays(r.graph.junctions.size());
  for (std::size_t i = 0; i < bs.size(); ++i) {
    if (bs[i].closed()) continue;
    rays[bs[i].start].push_back(
        {static_cast<int>(i), layering::leaving_direction(bs[i].points, reach)});
    const hair25d::Polyline back(bs[i].points.rbegin(), bs[i].points.rend());
    rays[bs[i].end].push_back({static_cast<int>(i), layering::leaving_direction(back, reach)});
  }
  std::vector<double> unary(bs.size(), 0.0);
  for (std::size_t i = 0; i < bs.size(); ++i) {
    const layering::BoundaryReport& b = r.boundaries[i];
    unary[i] = o.learned_scale * (o.junction_patches ? b.patch_log_odds : b.learned);
    if (b.state == 0) continue;
    const int ts = true_state(truth, b.left, b.right);
    ++t->states;
    if (ts == 0) continue;
    ++t->states_known;
    const bool ur = unary[i] * ts > 0, sr = b.state == ts;
    t->unary_right += ur;
    t->state_right += sr;
    t->overturned += ur && !sr;
    t->rescued += !ur && sr;
  }
  struct Coupled {
    int j, bi, bj;
    double theta;
    bool same;
  };
  std::vector<Coupled> coupled;
  for (std::size_t j = 0; j < rays.size(); ++j) {
    const auto& rs = rays[j];
    double best = -1;
    int bi = -1, bj = -1;
    bool same = false;
    for (std::size_t p = 0; p < rs.size(); ++p)
      for (std::size_t q = p + 1; q < rs.size(); ++q) {
        const int u = rs[p].b, v = rs[q].b;
        if (u == v || r.boundaries[u].state == 0 || r.boundaries[v].state == 0) continue;
        int shared = 0, count = 0;
        for (int l : {bs[u].left, bs[u].right})
          if (l == bs[v].left || l == bs[v].right) shared = l, ++count;
        if (count != 1) continue;
        const double theta = std::acos(std::clamp(rs[p].dir.dot(rs[q].dir), -1.0, 1.0));
        if (theta > best)
          best = theta, bi = u, bj = v, same = (shared == bs[u].left) == (shared == bs[v].left);
      }
    if (bi < 0 || best < o.smooth_angle || o.coupling == layering::Coupling::kNone) continue;
    coupled.push_back({static_cast<int>(j), bi, bj, best, same});
    ++t->coupled;
    const int ti = true_state(truth, bs[bi].left, bs[bi].right);
    const int tj = true_state(truth, bs[bj].left, bs[bj].right);
    if (ti == 0 || tj == 0) continue;
    if (hair_only &&
        (bs[bi].left == 0 || bs[bi].right == 0 || bs[bj].left == 0 || bs[bj].right == 0))
      continue;
    ++t->known;
    const bool bad = ti * tj * (same ? 1 : -1) < 0;
    auto& a = t->by_angle[static_cast<int>(best * 57.2958 / 5)];
    ++a.first;
    a.second += bad;
    const double shorter = std::min(r.boundaries[bi].length, r.boundaries[bj].length) / reach;
    auto& sh = t->by_short[std::min(8, static_cast<int>(shorter * 4))];
    ++sh.first;
    sh.second += bad;
    if (!bad) continue;
    ++t->violated;
    // Did it change a state away from its unary?
    const bool changed =
        r.boundaries[bi].state * unary[bi] < 0 || r.boundaries[bj].state * unary[bj] < 0;
    t->violated_changed += changed;
  }
  if (!verbose) return;
  for (std::size_t i = 0; i < bs.size(); ++i) {
    const layering::BoundaryReport& b = r.boundaries[i];
    if (b.state == 0 || b.state * unary[i] > 0) continue;
    const int ts = true_state(truth, b.left, b.right);
    std::printf("%s %s %d/%d len %.0f unary %+.2f state %+d truth %+d lw %.2f reach %.0f\n",
                ts == 0         ? "FLIP?"
                : ts == b.state ? "RESCUED"
                                : "OVERTURNED",
                c.name.c_str(), b.left, b.right, b.length, unary[i], b.state, ts, r.line_width,
                reach);
    for (const Coupled& k : coupled) {
      if (k.bi != static_cast<int>(i) && k.bj != static_cast<int>(i)) continue;
      const int o2 = k.bi == static_cast<int>(i) ? k.bj : k.bi;
      const layering::BoundaryReport& p = r.boundaries[o2];
      const int tp = true_state(truth, p.left, p.right);
      const bool pull = p.state * b.state * (k.same ? 1 : -1) > 0;
      std::printf(
          "    via junction %d (%.0f,%.0f) theta %.0f rays %zu: %d/%d len %.0f unary %+.2f state "
          "%+d truth %+d%s\n",
          k.j, r.graph.junctions[k.j].position.x(), r.graph.junctions[k.j].position.y(),
          k.theta * 57.2958, rays[k.j].size(), p.left, p.right, p.length, unary[o2], p.state, tp,
          pull ? "" : " (against)");
    }
  }
}

// For choosing the rules that make a pair "equal": per judged pair with an
// open (non-occluding) boundary or predicted equal, length-weighted means
// over its open and its occluding boundaries.
void print_equal_pairs(const hair25d::AnnotatedCase& c, const layering::Result& r,
                       const layering::CaseScore& s, const layering::Options& o) {
  for (const layering::PairOutcome& out : s.outcomes) {
    double total = 0, open = 0, open_same = 0, open_order = 0, occ = 0, occ_same = 0, occ_order = 0;
    for (const layering::BoundaryReport& b : r.boundaries) {
      if (!((b.left == out.a && b.right == out.b) || (b.left == out.b && b.right == out.a)))
        continue;
      const double sgn = b.left == out.a ? 1 : -1;  // toward a above
      total += b.length;
      if (b.occluding) {
        occ += b.length;
        occ_same += b.equal * b.length;
        occ_order += sgn * (o.junction_patches ? b.patch_log_odds : b.learned) * b.length;
      } else {
        open += b.length;
        open_same += b.equal * b.length;
        open_order += sgn * b.learned * b.length;
      }
    }
    const bool equal = out.predicted && *out.predicted == Relation::kEqual;
    if (open == 0 && !equal) continue;
    std::printf(
        "EQ %s %d %d truth %s predicted %s total %.0f open %.0f open_same %+.2f open_order %+.2f "
        "occ %.0f occ_same %+.2f occ_order %+.2f\n",
        c.name.c_str(), out.a, out.b, hair25d::to_string(out.truth),
        out.predicted ? hair25d::to_string(*out.predicted) : "none", total, open,
        open > 0 ? open_same / open : 0.0, open > 0 ? open_order / open : 0.0, occ,
        occ > 0 ? occ_same / occ : 0.0, occ > 0 ? occ_order / occ : 0.0);
  }
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
  app.add_option("--line-width", options.line_width, "fixed line width (default: estimated)");
  app.add_option("--fit-min", options.fit_reach_min, "fit_reach_min, pixels");
  app.add_option("--fit-widths", options.fit_reach_widths, "fit_reach_widths");
  app.add_option("--smooth-angle", options.smooth_angle);
  app.add_flag("--no-equal", no_equal);
  app.add_option("--equal-log-odds", options.equal_log_odds);
  app.add_flag("--context", options.region_context);
  app.add_flag("--paper", paper);
  bool no_patches = false;
  app.add_flag("--no-patches", no_patches, "without the junction patch model");
  app.add_flag("--quiet", quiet, "totals only");
  bool widths = false;
  app.add_flag("--widths", widths, "line width and threshold per case");
  bool couplings = false, couplings_verbose = false, hair_only = false;
  app.add_flag("--hair-only", hair_only, "tally only couplings of two hair-hair boundaries");
  app.add_flag("--couplings", couplings, "tally Eq. (2)'s couplings against the truth");
  app.add_flag("--couplings-verbose", couplings_verbose,
               "... and list the states they moved off their unary");
  bool equal_pairs = false;
  app.add_flag("--equal-pairs", equal_pairs,
               "a line per judged pair with an open boundary or predicted equal: its open and "
               "occluding boundaries' mean same-depth and order log-odds (a above b), the truth");
  app.add_option("--open-order-log-odds", options.open_order_log_odds,
                 "layering::Options::open_order_log_odds (-inf: open pairs stay equal)");
  CLI11_PARSE(app, argc, argv);
  options.coupling = coupling == "all"    ? layering::Coupling::kAllPairs
                     : coupling == "none" ? layering::Coupling::kNone
                                          : layering::Coupling::kSmoothestPair;
  options.learned_equal = !no_equal;
  options.junction_patches = !no_patches;
  if (paper) options.metric = layering::Metric::kPaper;
  int total = 0, right = 0;
  CouplingTally tally;
  std::filesystem::create_directories(out_dir);
  for (const auto& folder : hair25d::find_annotated_cases(cases_dir)) {
    const hair25d::AnnotatedCase c = hair25d::read_annotated_case(folder);
    layering::Result r;
    const layering::CaseScore s = layering::evaluate_case(c, options, &r);
    total += s.pairs;
    right += s.correct;
    if (widths)
      std::printf("%s line width %.2f threshold %.1f: %d / %d\n", c.name.c_str(), r.line_width,
                  r.line_threshold, s.correct, s.pairs);
    if (couplings || couplings_verbose)
      tally_couplings(c, r, options, &tally, couplings_verbose, hair_only);
    if (equal_pairs) print_equal_pairs(c, r, s, options);
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
  if (couplings || couplings_verbose) {
    std::printf(
        "couplings %d, truth known %d, violated by the truth %d (%.1f%%), of those moving a state "
        "off its unary %d\n",
        tally.coupled, tally.known, tally.violated,
        100.0 * tally.violated / std::max(tally.known, 1), tally.violated_changed);
    std::printf("states %d, known %d: unary right %d, state right %d, overturned %d, rescued %d\n",
                tally.states, tally.states_known, tally.unary_right, tally.state_right,
                tally.overturned, tally.rescued);
    for (const auto& [q, kv] : tally.by_short)
      std::printf("  shorter / reach %.2f-%.2f: %d known, %d violated (%.0f%%)\n", q / 4.0,
                  (q + 1) / 4.0, kv.first, kv.second, 100.0 * kv.second / std::max(kv.first, 1));
    for (const auto& [deg, kv] : tally.by_angle)
      std::printf("  theta %3d-%3d: %d known, %d violated\n", deg * 5, deg * 5 + 5, kv.first,
                  kv.second);
  }
  std::printf("total %d / %d = %.1f%%\n", right, total, 100.0 * right / std::max(total, 1));
  return 0;
}
