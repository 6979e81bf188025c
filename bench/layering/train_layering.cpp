// Trains the learned boundary metric (layering/learned_metric.h): a logistic
// regression without intercept over boundary_features, on generated drawings
// only (samples/generator gives exact relations in many styles), fitted by
// Newton's method with a small ridge. Deterministic: the same seed gives the
// same weights, printed as the C++ initializer of learned_weights.cpp.
//
//   train_layering --cases 400 --seed 20000
//   train_layering --cases 150 --seed 7000 --check   (held-out sign of the weights built in)
#include <CLI/CLI.hpp>
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "hair25d/core/error.h"
#include "hair25d/generator/generator.h"
#include "hair25d/layering/layering.h"
#include "train_layering_style.h"

namespace {

using hair25d::Relation;
namespace layering = hair25d::layering;
namespace generator = hair25d::generator;

struct Sample {
  std::vector<double> x;
  double y = 0;  // +1 left above, -1 right above
  double weight = 1;
};

// Every occluding boundary between hair regions of a drawing, for the
// region context (which also reads boundaries of pairs nobody judged).
struct BoundaryRecord {
  layering::ContextBoundary context;
  layering::BoundaryFeatures features{};
  layering::EqualCues equal_cues;
  int y = 0;  // +1 left above, -1 below, 0 same depth or not judged
};
using Drawing = std::vector<BoundaryRecord>;

// A same-depth sample keeps its cues: its features read the order model's
// log-odds, which are those of the weights fitted in this run.
struct SameSample {
  layering::EqualCues cues;
  layering::BoundaryFeatures order_features{};
  double y = 0;  // +1 same depth
  double weight = 1;
};

// Minimises Σ log(1 + exp(−y w·x)) + ridge/2 ‖w‖² by Newton steps.
Eigen::VectorXd fit(const std::vector<Sample>& samples, double ridge) {
  const int d = samples.empty() ? 0 : static_cast<int>(samples.front().x.size());
  Eigen::VectorXd w = Eigen::VectorXd::Zero(d);
  for (int it = 0; it < 50; ++it) {
    Eigen::VectorXd grad = ridge * w;
    Eigen::MatrixXd hess = ridge * Eigen::MatrixXd::Identity(d, d);
    for (const Sample& s : samples) {
      const Eigen::Map<const Eigen::VectorXd> x(s.x.data(), d);
      const double m = s.y * w.dot(x);
      const double p = 1.0 / (1.0 + std::exp(m));  // σ(−m)
      grad -= s.weight * s.y * p * x;
      hess += s.weight * p * (1 - p) * x * x.transpose();
    }
    const Eigen::VectorXd step = hess.ldlt().solve(grad);
    w -= step;
    if (step.norm() < 1e-10) break;
  }
  return w;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Train the learned layering metric on generated drawings"};
  int cases = 400;
  std::uint64_t seed = 20000;
  double ridge = 1.0;
  bool length_weighted = false;
  double same_ridge = 1.0;
  int dark_from = -1;
  app.add_option("--cases", cases, "generated drawings")->check(CLI::PositiveNumber);
  app.add_option("--seed", seed, "seed of the first drawing");
  app.add_option("--ridge", ridge, "L2 penalty")->check(CLI::NonNegativeNumber);
  app.add_option("--same-ridge", same_ridge, "L2 penalty of the same-depth model")
      ->check(CLI::NonNegativeNumber);
  std::string write, dump;
  bool check = false;
  app.add_flag("--check", check,
               "only print how often the weights built in get the boundary sign right");
  app.add_option("--dump", dump, "write the order samples' features here and stop");
  app.add_option("--write", write, "write layering/src/learned_weights.cpp here");
  app.add_flag("--length-weighted", length_weighted, "weight boundaries by sqrt(length)");
  app.add_option("--dark-from", dark_from,
                 "drawings from this one on in dark_style (hair about as dark as the ink)");
  CLI11_PARSE(app, argc, argv);

  std::vector<Sample> samples, same_samples;
  int built_in_right = 0, built_in_total = 0;
  std::vector<SameSample> same_cases;
  std::vector<Drawing> drawings;
  layering::Options options;
  options.metric = layering::Metric::kPaper;
  for (int i = 0; i < cases; ++i) {
    hair25d::AnnotatedCase c;
    layering::Result r;
    try {
      c = generator::generate_case(dark_from >= 0 && i >= dark_from
                                       ? hair25d::layering_training::dark_style(i, seed)
                                       : hair25d::layering_training::training_style(i, seed));
      r = layering::layer_regions(c.image, c.regions, options);
    } catch (const hair25d::Error& e) {
      std::fprintf(stderr, "case %d skipped: %s\n", i, e.what());
      continue;
    }
    const std::map<std::pair<int, int>, Relation> truth = hair25d::layering_training::pair_truth(c);
    Drawing& drawing = drawings.emplace_back();
    for (const layering::BoundaryReport& b : r.boundaries) {
      if (!b.occluding || b.left <= 0 || b.right <= 0) continue;
      auto t = truth.find({b.left, b.right});
      BoundaryRecord& rec = drawing.emplace_back();
      rec.context = {b.left, b.right, b.length, 0.0, true};
      rec.features = b.features;
      rec.equal_cues = b.equal_cues;
      if (t == truth.end()) continue;
      rec.y = t->second == Relation::kAbove ? 1 : t->second == Relation::kBelow ? -1 : 0;
      // Same depth or ordered: every occluding boundary of a judged pair,
      // weighted by length as the pair's decision is.
      same_cases.push_back({b.equal_cues, b.features, t->second == Relation::kEqual ? 1.0 : -1.0,
                            std::sqrt(b.length / r.line_width)});
      if (t->second == Relation::kEqual) continue;
      ++built_in_total;
      built_in_right += (t->second == Relation::kAbove ? 1 : -1) * b.learned > 0;
      // A pair is decided by its boundaries' votes weighted by length; the
      // square root keeps short boundaries (most junction errors) in play.
      const layering::LearnedTerms terms = layering::learned_terms(b.features);
      samples.push_back({{terms.begin(), terms.end()},
                         t->second == Relation::kAbove ? 1.0 : -1.0,
                         length_weighted ? std::sqrt(b.length / r.line_width) : 1.0});
    }
  }
  if (check) {
    std::printf("%d boundaries; the weights built in get the sign of %.2f%% right\n",
                built_in_total, 100.0 * built_in_right / std::max(built_in_total, 1));
    return 0;
  }
  if (!dump.empty()) {
    // The order samples' features and truth, one line each, for trying other
    // learners outside this program.
    std::FILE* f = std::fopen(dump.c_str(), "w");
    if (f == nullptr) return 1;
    for (const Drawing& d : drawings)
      for (const BoundaryRecord& rec : d) {
        if (rec.y == 0) continue;
        std::fprintf(f, "%d", rec.y);
        for (double x : rec.features) std::fprintf(f, " %.6g", x);
        std::fprintf(f, "\n");
      }
    std::fclose(f);
    return 0;
  }
  const Eigen::VectorXd w = fit(samples, ridge);
  int right_paper = 0, right_learned = 0;
  for (const Sample& s : samples) {
    const Eigen::Map<const Eigen::VectorXd> x(s.x.data(), w.size());
    right_learned += s.y * w.dot(x) > 0;
    right_paper += s.y * (0.25 * s.x[0] + s.x[6]) > 0;
  }
  std::printf("%zu boundaries from %d drawings (seed %llu, ridge %g)\n", samples.size(), cases,
              static_cast<unsigned long long>(seed), ridge);
  std::printf("boundary sign right: paper Φ %.1f%%, learned %.1f%%\n",
              100.0 * right_paper / samples.size(), 100.0 * right_learned / samples.size());

  // The same-depth model. Its features use the order model's output: that
  // of the weights just fitted (what the layering computes once they are in
  // learned_weights.cpp), so one run gives both.
  for (const SameSample& c : same_cases) {
    const layering::LearnedTerms terms = layering::learned_terms(c.order_features);
    layering::EqualCues cues = c.cues;
    cues.order_log_odds = w.dot(Eigen::Map<const Eigen::VectorXd>(terms.data(), w.size()));
    const layering::EqualFeatures f = layering::equal_features(cues);
    same_samples.push_back({{f.begin(), f.end()}, c.y, c.weight});
  }
  const Eigen::VectorXd v = fit(same_samples, same_ridge);
  int positives = 0, right_same = 0, right_none = 0;
  for (const Sample& s : same_samples) {
    const Eigen::Map<const Eigen::VectorXd> x(s.x.data(), v.size());
    positives += s.y > 0;
    right_same += s.y * v.dot(x) > 0;
    right_none += s.y < 0;
  }
  std::printf("%zu boundaries (%d same depth); right: always ordered %.1f%%, model %.1f%%\n",
              same_samples.size(), positives, 100.0 * right_none / same_samples.size(),
              100.0 * right_same / same_samples.size());
  // The region context: with both models above, as the layering runs them.
  std::vector<Sample> context_samples;
  int right_before = 0, right_after = 0;
  for (Drawing& d : drawings) {
    std::vector<layering::ContextBoundary> boundaries;
    for (BoundaryRecord& rec : d) {
      const layering::LearnedTerms terms = layering::learned_terms(rec.features);
      rec.context.log_odds = w.dot(Eigen::Map<const Eigen::VectorXd>(terms.data(), w.size()));
      layering::EqualCues cues = rec.equal_cues;
      cues.order_log_odds = rec.context.log_odds;
      const layering::EqualFeatures f = layering::equal_features(cues);
      rec.context.used = v.dot(Eigen::Map<const Eigen::VectorXd>(f.data(), v.size())) <= 0;
      boundaries.push_back(rec.context);
    }
    const std::vector<double> diff = layering::context_differences(boundaries);
    for (std::size_t k = 0; k < d.size(); ++k) {
      if (d[k].y == 0) continue;
      const layering::ContextTerms t = layering::context_terms(d[k].context.log_odds, diff[k]);
      context_samples.push_back({{t.begin(), t.end()}, static_cast<double>(d[k].y), 1.0});
    }
  }
  const Eigen::VectorXd u = fit(context_samples, ridge);
  for (const Sample& s : context_samples) {
    right_before += s.y * s.x[0] > 0;
    right_after += s.y * u.dot(Eigen::Map<const Eigen::VectorXd>(s.x.data(), u.size())) > 0;
  }
  std::printf("region context: sign right %.1f%% -> %.1f%%; weights %g %g %g\n",
              100.0 * right_before / context_samples.size(),
              100.0 * right_after / context_samples.size(), u[0], u[1], u[2]);

  if (write.empty()) return 0;
  // The whole of learned_weights.cpp, so that the committed constants are
  // exactly what this program printed.
  const std::string dark_note =
      dark_from >= 0 ? " --dark-from " + std::to_string(dark_from) : std::string();
  std::FILE* f = std::fopen(write.c_str(), "w");
  if (f == nullptr) {
    std::fprintf(stderr, "cannot write %s\n", write.c_str());
    return 1;
  }
  std::fprintf(
      f,
      "#include \"hair25d/layering/learned_metric.h\"\n\n"
      "namespace hair25d::layering {\n\n"
      "// Written by bench/layering/train_layering.cpp on generated drawings only\n"
      "// (never the annotated cases), Release build:\n"
      "//   train_layering --cases %d --seed %llu --ridge %g --same-ridge %g%s --write ...\n"
      "// %zu occluding boundaries between hair regions of known order; sign right\n"
      "// on them: paper Φ %.1f%%, these %.1f%%. Order as in learned_terms.\n"
      "const LearnedTerms& learned_weights() {\n"
      "  static constexpr LearnedTerms kWeights = {",
      cases, static_cast<unsigned long long>(seed), ridge, same_ridge, dark_note.c_str(),
      samples.size(), 100.0 * right_paper / samples.size(), 100.0 * right_learned / samples.size());
  for (int k = 0; k < w.size(); ++k)
    std::fprintf(f, "%s%s%.6g", k ? "," : "", k % 6 ? " " : "\n      ", w[k]);
  std::fprintf(f,
               "};\n  return kWeights;\n}\n\n"
               "// Same program, same drawings: the %zu occluding boundaries between hair\n"
               "// regions of a judged pair, same depth (%d) against ordered, weighted by\n"
               "// √(length / line width), the order log-odds from the weights above; right\n"
               "// on %.1f%% of them (always \"ordered\": %.1f%%). Order as in equal_features.\n"
               "const EqualFeatures& equal_weights() {\n"
               "  static constexpr EqualFeatures kWeights = {",
               same_samples.size(), positives, 100.0 * right_same / same_samples.size(),
               100.0 * right_none / same_samples.size());
  for (int k = 0; k < v.size(); ++k) std::fprintf(f, "%s%.6g", k ? ", " : "", v[k]);
  std::fprintf(f,
               "};\n  return kWeights;\n}\n\n"
               "// Same program, same drawings: the second stage over the order log-odds\n"
               "// above and the region context (both models as the layering runs them);\n"
               "// boundary sign right %.1f%% before it, %.1f%% after. Order as in\n"
               "// context_terms.\n"
               "const ContextTerms& context_weights() {\n"
               "  static constexpr ContextTerms kWeights = {%.6g, %.6g, %.6g};\n"
               "  return kWeights;\n}\n\n}  // namespace hair25d::layering\n",
               100.0 * right_before / context_samples.size(),
               100.0 * right_after / context_samples.size(), u[0], u[1], u[2]);
  std::fclose(f);
  return 0;
}
