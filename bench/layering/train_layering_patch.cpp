// Trains the junction patch model (layering/src/patch_model.h): OpenCV's
// ANN_MLP on label-map patches about the ends of occluding boundaries between
// hair regions of generated drawings (never the annotated cases), then a
// two-weight logistic second stage over (order model log-odds, patch score)
// on other drawings than the network's, so its weights see out-of-sample
// scores. Deterministic: the same seed gives the same weights.
//
//   train_layering_patch --cases 400 --seed 20000 --dump patches.bin
//   train_layering_patch --from patches.bin --write layering/src/patch_weights.cpp
#include <opencv2/core.hpp>
#include <opencv2/ml.hpp>

#include <CLI/CLI.hpp>
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "hair25d/core/error.h"
#include "hair25d/layering/layering.h"
#include "hair25d/layering/metrics.h"
#include "patch_model.h"
#include "train_layering_style.h"
#include "train_patch_mlp.h"

namespace {

using hair25d::Relation;
namespace layering = hair25d::layering;
namespace detail = hair25d::layering::detail;

struct Record {
  int drawing = 0;
  int y = 0;          // +1 left above, -1 below, 0 same depth
  float learned = 0;  // the order model's log-odds as the layering uses them
  float length_widths = 0;
  float equal = 0;  // the same-depth model's log-odds (files written with it only)
  std::vector<detail::Patch> ends;
};

// Drawings first .. cases − 1 (a dump can be collected in parts by several
// processes and the parts read together with --from), those from
// `extra_from` on in thin_fork_style, from `dark_from` on in dark_style.
std::vector<Record> collect(int cases, std::uint64_t seed, double radius_factor, int first,
                            int extra_from, int dark_from) {
  std::vector<Record> out;
  for (int i = first; i < cases; ++i) {
    hair25d::AnnotatedCase c;
    layering::Result r;
    try {
      c = hair25d::generator::generate_case(
          hair25d::layering_training::patch_style(i, seed, extra_from, dark_from));
      // Without the patch models, so the order and same-depth log-odds are
      // those the patch stages are joined with, whatever weights are built in.
      layering::Options options;
      options.junction_patches = false;
      r = layering::layer_regions(c.image, c.regions, options);
    } catch (const hair25d::Error& e) {
      std::fprintf(stderr, "case %d skipped: %s\n", i, e.what());
      continue;
    }
    const std::map<std::pair<int, int>, Relation> truth = hair25d::layering_training::pair_truth(c);
    const layering::Options defaults;
    const double reach = std::max(defaults.fit_reach_min, defaults.fit_reach_widths * r.line_width);
    for (std::size_t k = 0; k < r.boundaries.size(); ++k) {
      const layering::BoundaryReport& rep = r.boundaries[k];
      const layering::Boundary& b = r.graph.boundaries[k];
      if (!rep.occluding || b.left <= 0 || b.right <= 0 || b.closed()) continue;
      auto t = truth.find({b.left, b.right});
      if (t == truth.end()) continue;
      Record rec;
      rec.drawing = i;
      rec.y = t->second == Relation::kAbove ? 1 : t->second == Relation::kBelow ? -1 : 0;
      rec.learned = static_cast<float>(rep.learned);
      rec.length_widths = static_cast<float>(rep.length / r.line_width);
      rec.equal = static_cast<float>(rep.equal);
      const hair25d::Polyline back(b.points.rbegin(), b.points.rend());
      rec.ends = detail::boundary_patches(
          r.labels, detail::PatchImage{&c.image, detail::patch_contrast(r.line_threshold)}, r.graph,
          b, layering::leaving_direction(b.points, reach), layering::leaving_direction(back, reach),
          radius_factor * detail::patch_radius(reach));
      out.push_back(std::move(rec));
    }
    if (i % 50 == 49) std::fprintf(stderr, "%d drawings, %zu boundaries\n", i + 1, out.size());
  }
  return out;
}

void save(const std::string& path, const std::vector<Record>& records) {
  std::ofstream f(path, std::ios::binary);
  const int n = -static_cast<int>(records.size());  // negative: records hold `equal`
  f.write(reinterpret_cast<const char*>(&n), sizeof n);
  for (const Record& r : records) {
    const int ends = static_cast<int>(r.ends.size());
    f.write(reinterpret_cast<const char*>(&r.drawing), sizeof r.drawing);
    f.write(reinterpret_cast<const char*>(&r.y), sizeof r.y);
    f.write(reinterpret_cast<const char*>(&r.learned), sizeof r.learned);
    f.write(reinterpret_cast<const char*>(&r.length_widths), sizeof r.length_widths);
    f.write(reinterpret_cast<const char*>(&r.equal), sizeof r.equal);
    f.write(reinterpret_cast<const char*>(&ends), sizeof ends);
    for (const detail::Patch& p : r.ends)
      f.write(reinterpret_cast<const char*>(p.data()), sizeof(float) * p.size());
  }
}

std::vector<Record> load(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  int n = 0;
  f.read(reinterpret_cast<char*>(&n), sizeof n);
  const bool with_equal = n < 0;
  std::vector<Record> out(std::abs(n));
  for (Record& r : out) {
    int ends = 0;
    f.read(reinterpret_cast<char*>(&r.drawing), sizeof r.drawing);
    f.read(reinterpret_cast<char*>(&r.y), sizeof r.y);
    f.read(reinterpret_cast<char*>(&r.learned), sizeof r.learned);
    f.read(reinterpret_cast<char*>(&r.length_widths), sizeof r.length_widths);
    if (with_equal) f.read(reinterpret_cast<char*>(&r.equal), sizeof r.equal);
    f.read(reinterpret_cast<char*>(&ends), sizeof ends);
    r.ends.resize(std::clamp(ends, 0, 2));
    for (detail::Patch& p : r.ends)
      f.read(reinterpret_cast<char*>(p.data()), sizeof(float) * p.size());
  }
  if (!f) throw hair25d::Error("train_layering_patch: " + path + " is cut short");
  return out;
}

// Which drawings the networks learn from: the first `net_cases` and those
// from `extra_from` on; the second stages are fitted on the ones between.
// `thin_weight` weighs the networks' rows of drawings with lines of at most
// 1.5 px.
struct Split {
  int net_cases = 0;
  int extra_from = 0;
  std::uint64_t seed = 0;
  double thin_weight = 1.0;
  int dark_from = std::numeric_limits<int>::max();
  bool network(int drawing) const {
    return drawing < net_cases || drawing >= extra_from || drawing >= dark_from;
  }
  double line_width(int drawing) const {
    return hair25d::layering_training::patch_style(drawing, seed, extra_from, dark_from).line_width;
  }
  float weight(int drawing) const {
    return static_cast<float>(line_width(drawing) <= 1.5 ? thin_weight : 1.0);
  }
};

// Logistic regression by Newton's method (an intercept is a constant term),
// each sample weighted.
template <class V>
V fit_stage(const std::vector<V>& x, const std::vector<double>& y, double ridge,
            const std::vector<double>* weight = nullptr) {
  const int d = x.empty() ? 0 : static_cast<int>(x.front().size());
  V w = V::Zero(d);
  for (int it = 0; it < 50; ++it) {
    V grad = ridge * w;
    Eigen::MatrixXd hess = ridge * Eigen::MatrixXd::Identity(d, d);
    for (std::size_t k = 0; k < x.size(); ++k) {
      const double c = weight ? (*weight)[k] : 1.0;
      const double m = y[k] * w.dot(x[k]);
      const double p = 1.0 / (1.0 + std::exp(m));
      grad -= c * y[k] * p * x[k];
      hess += c * p * (1 - p) * x[k] * x[k].transpose();
    }
    const V step = hess.ldlt().solve(grad);
    w -= step;
    if (step.norm() < 1e-12) break;
  }
  return w;
}

cv::Ptr<cv::ml::ANN_MLP> train_network(const cv::Mat& x, const cv::Mat& t, const cv::Mat& weight,
                                       int hidden, int iterations, std::uint64_t seed) {
  cv::setNumThreads(1);  // the same sums in the same order: the same weights
  cv::theRNG().state = seed;
  cv::Ptr<cv::ml::ANN_MLP> mlp = cv::ml::ANN_MLP::create();
  const cv::Mat sizes = (cv::Mat_<int>(1, 3) << x.cols, hidden, 1);
  mlp->setLayerSizes(sizes);
  mlp->setActivationFunction(cv::ml::ANN_MLP::SIGMOID_SYM, 0, 0);
  // RPROP's default first step (0.1) saturates 1024 inputs at once.
  mlp->setTrainMethod(cv::ml::ANN_MLP::RPROP, 0.01);
  mlp->setTermCriteria(
      cv::TermCriteria(cv::TermCriteria::MAX_ITER + cv::TermCriteria::EPS, iterations, 1e-6));
  const cv::Ptr<cv::ml::TrainData> data =
      weight.empty() ? cv::ml::TrainData::create(x, cv::ml::ROW_SAMPLE, t)
                     : cv::ml::TrainData::create(x, cv::ml::ROW_SAMPLE, t, cv::noArray(),
                                                 cv::noArray(), weight);
  mlp->train(data, cv::ml::ANN_MLP::NO_INPUT_SCALE + cv::ml::ANN_MLP::NO_OUTPUT_SCALE);
  return mlp;
}

// A network trained on the first scales only weighs the others 0.
void copy_weights(const cv::ml::ANN_MLP& mlp, detail::PatchNet& net) {
  const cv::Mat l1 = mlp.getWeights(1), l2 = mlp.getWeights(2);  // (inputs + 1) × outputs
  const int inputs = l1.rows - 1;
  for (int h = 0; h < detail::kPatchHidden; ++h) {
    for (int k = 0; k < detail::kPatchInputs; ++k)
      net.w1[k][h] = k < inputs ? static_cast<float>(l1.at<double>(k, h)) : 0.0f;
    net.b1[h] = static_cast<float>(l1.at<double>(inputs, h));
    net.w2[h] = static_cast<float>(l2.at<double>(h, 0));
  }
  net.b2[0] = static_cast<float>(l2.at<double>(detail::kPatchHidden, 0));
}

void write_net(std::FILE* f, const detail::PatchNet& net) {
  std::fprintf(f, "{{{");
  for (int k = 0; k < detail::kPatchInputs; ++k) {
    std::fprintf(f, "%s{", k ? ",\n       " : "");
    for (int h = 0; h < detail::kPatchHidden; ++h)
      std::fprintf(f, "%s%#.7gf", h ? (h % 8 ? ", " : ",\n        ") : "", net.w1[k][h]);
    std::fprintf(f, "}");
  }
  std::fprintf(f, "}},\n      {");
  for (int h = 0; h < detail::kPatchHidden; ++h)
    std::fprintf(f, "%s%#.7gf", h ? ", " : "", net.b1[h]);
  std::fprintf(f, "},\n      {");
  for (int h = 0; h < detail::kPatchHidden; ++h)
    std::fprintf(f, "%s%#.7gf", h ? ", " : "", net.w2[h]);
  std::fprintf(f, "},\n      {");
  for (int m = 0; m < detail::kPatchMembers; ++m)
    std::fprintf(f, "%s%#.7gf", m ? ", " : "", net.b2[m]);
  std::fprintf(f, "},\n      %.17g,\n      %.17g,\n      %.17g,\n      %.17g}", net.alpha, net.beta,
               net.order_weight, net.patch_weight);
}

// Reads the networks back from a patch_weights.cpp this program wrote: the
// numbers of each kNet's initializer in order (float literals as the
// compiler reads them, by strtof).
void read_weights(const std::string& path, detail::PatchNet& order, detail::SameDepthNet& same) {
  std::ifstream f(path);
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  auto numbers = [&](const std::string& head) {
    std::vector<double> out;
    const std::size_t at = text.find(head);
    if (at == std::string::npos)
      throw hair25d::Error("train_layering_patch: no '" + head + "' in " + path);
    const char* c = text.c_str() + at + head.size();
    for (; *c != ';' && *c != 0; ++c) {
      if (!(std::isdigit(static_cast<unsigned char>(*c)) || *c == '-' || *c == '+' || *c == '.'))
        continue;
      char* end = nullptr;
      double v = std::strtod(c, &end);
      if (*end == 'f') v = std::strtof(c, &end), ++end;
      out.push_back(v);
      c = end - 1;
    }
    return out;
  };
  auto fill = [&](const std::vector<double>& v, std::size_t& k, detail::PatchNet& net) {
    for (auto& row : net.w1)
      for (float& x : row) x = static_cast<float>(v[k++]);
    for (float& x : net.b1) x = static_cast<float>(v[k++]);
    for (float& x : net.w2) x = static_cast<float>(v[k++]);
    for (float& x : net.b2) x = static_cast<float>(v[k++]);
    net.alpha = v[k++], net.beta = v[k++], net.order_weight = v[k++], net.patch_weight = v[k++];
  };
  const std::size_t size = detail::kPatchInputs * detail::kPatchHidden + 2 * detail::kPatchHidden +
                           detail::kPatchMembers + 4;
  const std::vector<double> a = numbers("static const PatchNet kNet =");
  const std::vector<double> b = numbers("static const SameDepthNet kNet =");
  if (a.size() != size || b.size() != size + 1)
    throw hair25d::Error("train_layering_patch: " + path + " holds " + std::to_string(a.size()) +
                         " and " + std::to_string(b.size()) + " numbers, not " +
                         std::to_string(size) + " and " + std::to_string(size + 1));
  std::size_t k = 0;
  fill(a, k, order);
  k = 0;
  fill(b, k, same.net);
  same.intercept = b[k];
}

// Distillation targets: for every end of the networks' drawings (records in
// order, each end), the probability of "A above" (order) and of "same depth"
// that the teachers' networks give it on average (ensemble_target).
struct SoftTargets {
  std::vector<float> order, same;  // one per end of the network's rows
};
SoftTargets teacher_targets(const std::vector<Record>& records, const Split& split,
                            const std::vector<std::string>& paths, double sharpness,
                            bool mean_logit) {
  const int k = static_cast<int>(paths.size());
  std::vector<std::vector<float>> order_scores, same_scores;  // [end][teacher]
  for (const Record& r : records)
    if (split.network(r.drawing))
      for (std::size_t e = 0; e < r.ends.size(); ++e)
        order_scores.emplace_back(k), same_scores.emplace_back(k);
  auto order = std::make_unique<detail::PatchNet>();
  auto same = std::make_unique<detail::SameDepthNet>();
  std::vector<double> mean_score(records.size(), 0.0);  // Σ over teachers, every boundary
  for (int t = 0; t < k; ++t) {
    read_weights(paths[t], *order, *same);
    const bool built_in = order->w1 == detail::patch_weights().w1 &&
                          same->net.w1 == detail::patch_same_weights().net.w1;
    const int inputs = detail::patch_inputs_used(*order);
    int end = 0, right = 0, total = 0;
    for (const Record& r : records) {
      double s = 0;
      for (const detail::Patch& p : r.ends) {
        const detail::PatchScores q = detail::patch_scores(*order, inputs, same->net, p);
        s += q.order;
        mean_score[&r - records.data()] += q.order / k;
        if (split.network(r.drawing)) {
          order_scores[end][t] = static_cast<float>(q.order);
          same_scores[end++][t] = static_cast<float>(q.same);
        }
      }
      if (r.y != 0 && !split.network(r.drawing)) ++total, right += s * r.y > 0;
    }
    std::printf("teacher %s%s: patch sign on the others %.1f%% of %d\n", paths[t].c_str(),
                built_in ? " (the built-in weights)" : "", 100.0 * right / std::max(total, 1),
                total);
    std::fflush(stdout);
  }
  {
    int right = 0, total = 0;
    for (const Record& r : records)
      if (r.y != 0 && !split.network(r.drawing))
        ++total, right += mean_score[&r - records.data()] * r.y > 0;
    std::printf("the teachers' mean score: patch sign on the others %.1f%% of %d\n",
                100.0 * right / std::max(total, 1), total);
  }
  SoftTargets out;
  int end = 0;
  double order_sum = 0, same_sum = 0;
  for (const Record& r : records) {
    if (!split.network(r.drawing)) continue;
    for (std::size_t e = 0; e < r.ends.size(); ++e, ++end) {
      if (r.y != 0) {
        out.order.push_back(hair25d::layering_training::ensemble_target(order_scores[end].data(), k,
                                                                        sharpness, mean_logit));
        order_sum += std::abs(out.order.back() - (r.y > 0 ? 1.0 : 0.0));
      }
      out.same.push_back(hair25d::layering_training::ensemble_target(same_scores[end].data(), k,
                                                                     sharpness, mean_logit));
      same_sum += std::abs(out.same.back() - (r.y == 0 ? 1.0 : 0.0));
    }
  }
  std::printf("teachers' targets: mean distance from the labels %.4f (order), %.4f (same depth)\n",
              order_sum / std::max<std::size_t>(out.order.size(), 1),
              same_sum / std::max<std::size_t>(out.same.size(), 1));
  return out;
}

// Same depth or ordered, from the same patches: a network whose score
// h(P) + h(swapped P) does not change when A and B swap, trained on every
// end of the first drawings' occluding boundaries (same-depth ones weighted
// up to half the total), joined with the same-depth model's log-odds by a
// logistic stage with intercept on the other drawings, weighted by
// √(length / line width) as that model is trained.
detail::SameDepthNet train_same_depth(const std::vector<Record>& records, const Split& split,
                                      int iterations, std::uint64_t seed,
                                      const hair25d::layering_training::MlpOptions* adam,
                                      int inputs, std::string* report,
                                      const std::vector<float>* soft = nullptr) {
  int n = 0, positives = 0, total = 0;
  for (const Record& r : records)
    if (split.network(r.drawing))
      n += static_cast<int>(r.ends.size()), ++total, positives += r.y == 0;
  cv::Mat x(2 * n, detail::kPatchInputs, CV_32F), t(2 * n, 1, CV_32F), w(2 * n, 1, CV_32F);
  int row = 0;
  for (const Record& r : records) {
    if (!split.network(r.drawing)) continue;
    const double share = r.y == 0 ? positives : total - positives;
    const float weight =
        static_cast<float>(total / (2.0 * std::max(share, 1.0))) * split.weight(r.drawing);
    for (const detail::Patch& p : r.ends)
      for (const detail::Patch& q : {p, detail::swapped(p)}) {
        std::copy(q.begin(), q.end(), x.ptr<float>(row));
        t.at<float>(row) = r.y == 0 ? 1.0f : -1.0f;
        w.at<float>(row++) = weight;
      }
  }
  std::printf("same depth: %d ends, %d of %d boundaries same depth ...\n", n, positives, total);
  std::fflush(stdout);
  detail::SameDepthNet out;
  if (adam != nullptr) {
    // One row per end and its exchanged patch side by side.
    hair25d::layering_training::RowMatrix px(n, detail::kPatchInputs), ps(n, detail::kPatchInputs);
    std::vector<float> py(n), pw(n);
    for (int k = 0; k < n; ++k) {
      px.row(k) = Eigen::Map<const Eigen::RowVectorXf>(x.ptr<float>(2 * k), detail::kPatchInputs);
      ps.row(k) =
          Eigen::Map<const Eigen::RowVectorXf>(x.ptr<float>(2 * k + 1), detail::kPatchInputs);
      py[k] = t.at<float>(2 * k);
      pw[k] = w.at<float>(2 * k);
    }
    hair25d::layering_training::MlpOptions o = *adam;
    o.symmetric = true;
    o.inputs = inputs;
    o.wide_dropout = 0.0;
    o.seed = seed + 1;
    const detail::PatchNet net =
        hair25d::layering_training::train_patch_mlp(px, ps, py, pw, o, soft);
    out.net = net;
  } else {
    const cv::Ptr<cv::ml::ANN_MLP> mlp =
        train_network(x.colRange(0, inputs).clone(), t, w, detail::kPatchHidden, iterations, seed);
    copy_weights(*mlp, out.net);
    {
      // Our forward pass against OpenCV's on the first ends.
      double worst = 0;
      for (int k = 0; k < std::min(n, 2000); ++k) {
        cv::Mat o;
        mlp->predict(x.row(k), o);
        const detail::Patch& p = *reinterpret_cast<const detail::Patch*>(x.ptr<float>(k));
        worst = std::max(worst, std::abs(o.at<float>(0) - detail::patch_net(out.net, p)));
      }
      std::printf("same-depth network against OpenCV's forward pass: largest difference %.3g\n",
                  worst);
    }
  }
  // The stage on the other drawings: (1, 6c log-odds, score) → same depth.
  std::vector<Eigen::VectorXd> sx[2];
  std::vector<double> sy[2], sw[2];
  int k = 0;
  for (const Record& r : records) {
    if (split.network(r.drawing)) continue;
    double q = 0;
    for (const detail::Patch& p : r.ends) q += detail::patch_same_score(out.net, p);
    Eigen::VectorXd v(3);
    v << 1.0, r.equal, q;
    const int half = k++ % 2;
    sx[half].push_back(v);
    sy[half].push_back(r.y == 0 ? 1.0 : -1.0);
    sw[half].push_back(std::sqrt(std::max(r.length_widths, 0.0f)));
  }
  auto rate = [&](const Eigen::VectorXd& h, int half, bool model_only) {
    double right = 0, sum = 0, found = 0, same = 0;
    for (std::size_t i = 0; i < sx[half].size(); ++i) {
      const double z = model_only ? sx[half][i][1] : h.dot(sx[half][i]);
      sum += sw[half][i];
      right += sw[half][i] * (z * sy[half][i] > 0);
      if (sy[half][i] > 0) ++same, found += z > 0;
    }
    char line[200];
    std::snprintf(line, sizeof line, "%.2f%% (same depth found %g of %g)", 100 * right / sum, found,
                  same);
    return std::string(line);
  };
  const Eigen::VectorXd h0 = fit_stage(sx[0], sy[0], 1.0, &sw[0]);
  std::vector<Eigen::VectorXd> all = sx[0];
  all.insert(all.end(), sx[1].begin(), sx[1].end());
  std::vector<double> ally = sy[0], allw = sw[0];
  ally.insert(ally.end(), sy[1].begin(), sy[1].end());
  allw.insert(allw.end(), sw[1].begin(), sw[1].end());
  const Eigen::VectorXd h = fit_stage(all, ally, 1.0, &allw);
  out.intercept = h[0];
  out.net.order_weight = h[1];
  out.net.patch_weight = h[2];
  *report = "same depth, weighted, other drawings' second half: model " + rate(h, 1, true) +
            ", with patches (stage fitted on the first half) " + rate(h0, 1, false);
  std::printf("%s\n", report->c_str());
  return out;
}
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Train the layering junction patch model on generated drawings"};
  int cases = 400, net_cases = 300, iterations = 200;
  std::uint64_t seed = 20000;
  std::string dump, write;
  std::vector<std::string> from;
  app.add_option("--cases", cases, "generated drawings")->check(CLI::PositiveNumber);
  app.add_option("--seed", seed, "seed of the first drawing");
  app.add_option("--net-cases", net_cases,
                 "the network learns from the first this many drawings, the second stage from "
                 "the rest");
  app.add_option("--iterations", iterations, "RPROP iterations")->check(CLI::PositiveNumber);
  int hidden = detail::kPatchHidden;
  double radius_factor = 1.0;
  std::vector<std::string> also;
  app.add_option("--hidden", hidden, "hidden units (only the built-in count can be written)");
  app.add_option("--radius-factor", radius_factor, "patch radius × the fit length (for --dump)");
  app.add_option("--also", also, "more patch files of the same ends, read side by side");
  int same_iterations = 400, order_scales = 1;
  app.add_option("--order-scales", order_scales, "scales the order network reads (1 or 2)")
      ->check(CLI::Range(1, detail::kPatchScales));
  app.add_option("--same-iterations", same_iterations, "RPROP iterations, same-depth network")
      ->check(CLI::PositiveNumber);
  hair25d::layering_training::MlpOptions adam;
  bool use_adam = false;
  app.add_flag("--adam", use_adam,
               "train by minibatch Adam on the pair scores (train_patch_mlp.h), not RPROP");
  app.add_option("--epochs", adam.epochs, "Adam: passes over the ends")->check(CLI::PositiveNumber);
  app.add_option("--rate", adam.rate, "Adam: step")->check(CLI::PositiveNumber);
  app.add_option("--batch", adam.batch, "Adam: ends per step")->check(CLI::PositiveNumber);
  app.add_option("--decay", adam.decay, "Adam: L2 on the weights")->check(CLI::NonNegativeNumber);
  app.add_option("--wide-dropout", adam.wide_dropout,
                 "Adam: share of order-network rows trained without the wide scale")
      ->check(CLI::Range(0.0, 1.0));
  app.add_flag("--anneal", adam.anneal, "Adam: the step falls linearly to 0");
  bool grey = false;
  double grey_dropout = 0.0;
  app.add_option("--grey-dropout", grey_dropout,
                 "with --grey: share of order-network rows trained with the grey channel zeroed "
                 "(instead of --wide-dropout)")
      ->check(CLI::Range(0.0, 1.0));
  app.add_flag("--grey", grey,
               "both networks also read the patches' grey channel (with --adam and "
               "--order-scales 2)");
  int extra_from = std::numeric_limits<int>::max();
  app.add_option("--extra-from", extra_from,
                 "drawings from this one on are drawn in thin_fork_style and train the networks "
                 "(the second stages keep the drawings from --net-cases to here)")
      ->check(CLI::NonNegativeNumber);
  int dark_from = std::numeric_limits<int>::max();
  app.add_option("--dark-from", dark_from,
                 "drawings from this one on are drawn in dark_style (hair as dark as the ink) "
                 "and train the networks")
      ->check(CLI::NonNegativeNumber);
  double thin_weight = 1.0;
  app.add_option("--thin-weight", thin_weight,
                 "weight of the networks' rows of drawings with lines of at most 1.5 px")
      ->check(CLI::PositiveNumber);
  int first = 0;
  app.add_option("--first", first, "with --dump: collect drawings from this one on")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--dump", dump, "write the patches here and stop");
  app.add_option("--from", from,
                 "read the patches from here instead of drawing (several files: parts of one "
                 "run, in order)");
  app.add_option("--write", write, "write layering/src/patch_weights.cpp here");
  std::vector<std::string> teachers;
  bool mean_logit = false;
  app.add_option("--teachers", teachers,
                 "with --adam: distil these patch_weights.cpp files' networks (both), their mean "
                 "probability per end as the target");
  app.add_option("--distil-share", adam.soft_share,
                 "with --teachers: share of the teachers' target (the rest the label's)")
      ->check(CLI::Range(0.0, 1.0));
  app.add_flag("--distil-logit", mean_logit,
               "with --teachers: the probability of the teachers' mean log-odds instead");
  std::string coarse = "none";
  app.add_option("--coarse", coarse,
                 "with --grey: which networks also read the coarse scale (patch_model.h, "
                 "kPatchCoarse × the radius)")
      ->check(CLI::IsMember({"none", "order", "same", "both"}));
  CLI11_PARSE(app, argc, argv);
  const bool coarse_order = coarse == "order" || coarse == "both";
  const bool coarse_same = coarse == "same" || coarse == "both";
  if (coarse != "none" && !grey) {
    std::fprintf(stderr, "--coarse needs --grey\n");
    return 1;
  }

  if (!use_adam && detail::kPatchMembers != 1) {
    std::fprintf(stderr,
                 "the layering's network is an ensemble of %d members: only --adam trains it\n",
                 detail::kPatchMembers);
    return 1;
  }
  if (!teachers.empty() && !use_adam) {
    std::fprintf(stderr, "--teachers needs --adam\n");
    return 1;
  }
  const Split split{net_cases, extra_from, seed, thin_weight, dark_from};
  std::vector<Record> records;
  if (from.empty()) {
    records = collect(cases, seed, radius_factor, first, extra_from, dark_from);
  } else {
    // Parts read one after the other, as one run's drawings in order.
    for (const std::string& path : from) {
      std::vector<Record> part = load(path);
      records.insert(records.end(), std::make_move_iterator(part.begin()),
                     std::make_move_iterator(part.end()));
    }
  }
  if (!dump.empty()) {
    save(dump, records);
    std::printf("%zu boundaries written to %s\n", records.size(), dump.c_str());
    return 0;
  }
  SoftTargets soft;
  if (!teachers.empty())
    soft = teacher_targets(records, split, teachers, adam.sharpness, mean_logit);
  // More patches of the same ends (other radii), side by side in one input.
  std::vector<std::vector<Record>> extra;
  for (const std::string& path : also) {
    extra.push_back(load(path));
    if (extra.back().size() != records.size())
      throw hair25d::Error("train_layering_patch: " + path + " has other boundaries");
  }
  const int parts = 1 + static_cast<int>(extra.size());
  const int d = parts * detail::kPatchInputs;
  // One row per end: the patches, then (swapped) the same with A and B exchanged.
  auto end_row = [&](std::size_t r, std::size_t e, bool swap, float* row) {
    for (int q = 0; q < parts; ++q) {
      const detail::Patch& p = q == 0 ? records[r].ends[e] : extra[q - 1][r].ends[e];
      const detail::Patch s = swap ? detail::swapped(p) : p;
      std::copy(s.begin(), s.end(), row + q * detail::kPatchInputs);
    }
  };
  // Network samples: every end of an ordered boundary, and the same end with
  // the regions exchanged and the answer negated.
  int n = 0;
  for (const Record& r : records)
    if (r.y != 0 && split.network(r.drawing)) n += static_cast<int>(r.ends.size());
  cv::Mat x(2 * n, d, CV_32F), t(2 * n, 1, CV_32F);
  int row = 0;
  for (std::size_t r = 0; r < records.size(); ++r) {
    if (records[r].y == 0 || !split.network(records[r].drawing)) continue;
    for (std::size_t e = 0; e < records[r].ends.size(); ++e) {
      end_row(r, e, false, x.ptr<float>(row));
      t.at<float>(row++) = static_cast<float>(records[r].y);
      end_row(r, e, true, x.ptr<float>(row));
      t.at<float>(row++) = -static_cast<float>(records[r].y);
    }
  }
  std::printf("training the network on %d ends (%d samples, %d inputs, %d hidden) ...\n", n, 2 * n,
              d, hidden);
  std::fflush(stdout);
  // The order network may read the fine scale only: the wide one carries the
  // generator's strand shapes, which real drawings need not share.
  if (grey && (!use_adam || order_scales != detail::kPatchScales || parts != 1))
    throw hair25d::Error(
        "train_layering_patch: --grey needs --adam, --order-scales 2 and one file");
  const int label_inputs = order_scales * detail::kPatchScaleInputs;
  const int used = parts == 1
                       ? (grey ? (coarse_order ? detail::kPatchInputs : detail::kPatchCoarseStart)
                               : label_inputs)
                       : d;
  auto net = std::make_unique<detail::PatchNet>();
  std::vector<double> score(records.size(), 0.0);
  cv::Ptr<cv::ml::ANN_MLP> mlp;
  if (use_adam) {
    if (parts != 1 || hidden != detail::kPatchHidden)
      throw hair25d::Error("train_layering_patch: --adam trains one patch file, " +
                           std::to_string(detail::kPatchHidden) + " hidden units");
    hair25d::layering_training::RowMatrix px(n, d), ps(n, d);
    std::vector<float> py(n), pw(n, 1.0f);
    {
      int k = 0;
      for (const Record& r : records)
        if (r.y != 0 && split.network(r.drawing))
          for (std::size_t e = 0; e < r.ends.size(); ++e) pw[k++] = split.weight(r.drawing);
    }
    for (int k = 0; k < n; ++k) {
      px.row(k) = Eigen::Map<const Eigen::RowVectorXf>(x.ptr<float>(2 * k), d);
      ps.row(k) = Eigen::Map<const Eigen::RowVectorXf>(x.ptr<float>(2 * k + 1), d);
      py[k] = t.at<float>(2 * k);
    }
    adam.inputs = used;
    if (grey && grey_dropout > 0) {
      if (adam.wide_dropout > 0)
        throw hair25d::Error(
            "train_layering_patch: --grey-dropout and --wide-dropout exclude "
            "each other");
      adam.fine_inputs = detail::kPatchLabelInputs;
      adam.dropout_end = detail::kPatchCoarseStart;  // the grey channel only
      adam.wide_dropout = grey_dropout;
    }
    adam.seed = seed;
    *net = hair25d::layering_training::train_patch_mlp(px, ps, py, pw, adam,
                                                       teachers.empty() ? nullptr : &soft.order);
  } else {
    mlp = train_network(x.colRange(0, used).clone(), t, cv::Mat(), hidden, iterations, seed);
  }

  // Scores of every boundary by OpenCV's forward pass: Σ over its ends of
  // net(P) − net(swapped P).
  if (mlp) {
    int m = 0;
    for (const Record& r : records) m += static_cast<int>(r.ends.size());
    cv::Mat all(2 * m, d, CV_32F), out;
    int k = 0;
    for (std::size_t r = 0; r < records.size(); ++r)
      for (std::size_t e = 0; e < records[r].ends.size(); ++e) {
        end_row(r, e, false, all.ptr<float>(k++));
        end_row(r, e, true, all.ptr<float>(k++));
      }
    mlp->predict(all.colRange(0, used).clone(), out);
    k = 0;
    for (std::size_t r = 0; r < records.size(); ++r)
      for (std::size_t e = 0; e < records[r].ends.size(); ++e, k += 2)
        score[r] += out.at<float>(k) - out.at<float>(k + 1);
  }
  const bool writable = parts == 1 && hidden == detail::kPatchHidden;
  if (use_adam) {
    for (std::size_t r = 0; r < records.size(); ++r)
      for (const detail::Patch& p : records[r].ends) score[r] += detail::patch_score(*net, p);
  } else if (writable) {
    copy_weights(*mlp, *net);
    // Our forward pass against OpenCV's.
    double worst = 0;
    for (std::size_t r = 0; r < records.size(); ++r) {
      double mine = 0;
      for (const detail::Patch& p : records[r].ends) mine += detail::patch_score(*net, p);
      worst = std::max(worst, std::abs(mine - score[r]));
    }
    std::printf("patch_score against OpenCV's forward pass: largest difference %.3g\n", worst);
    // The second stage sees the scores as the layering computes them.
    for (std::size_t r = 0; r < records.size(); ++r) {
      score[r] = 0;
      for (const detail::Patch& p : records[r].ends) score[r] += detail::patch_score(*net, p);
    }
  }

  // Sign of boundaries on the network's own drawings and on the others, and
  // the second stage on the others.
  int in_right = 0, in_total = 0, out_right_patch = 0, out_right_order = 0, out_total = 0;
  std::vector<Eigen::Vector2d> sx;
  std::vector<double> sy;
  for (const Record& r : records) {
    if (r.y == 0) continue;
    const double s = score[&r - records.data()];
    if (split.network(r.drawing)) {
      ++in_total;
      in_right += s * r.y > 0;
    } else {
      ++out_total;
      out_right_patch += s * r.y > 0;
      out_right_order += r.learned * r.y > 0;
      sx.emplace_back(r.learned, s);
      sy.push_back(r.y);
    }
  }
  {
    // The others by the line width they were drawn with.
    std::map<double, std::array<int, 3>> by_width;  // right (patch), right (order), boundaries
    for (const Record& r : records) {
      if (r.y == 0 || split.network(r.drawing)) continue;
      std::array<int, 3>& c = by_width[split.line_width(r.drawing)];
      c[0] += score[&r - records.data()] * r.y > 0;
      c[1] += r.learned * r.y > 0;
      ++c[2];
    }
    for (const auto& [width, c] : by_width)
      std::printf("  lines %.1f px: patch sign %.1f%%, order model %.1f%% of %d\n", width,
                  100.0 * c[0] / c[2], 100.0 * c[1] / c[2], c[2]);
  }
  std::printf(
      "patch sign: network's drawings %.1f%% of %d; others %.1f%% of %d (order model %.1f%%)\n",
      100.0 * in_right / std::max(in_total, 1), in_total,
      100.0 * out_right_patch / std::max(out_total, 1), out_total,
      100.0 * out_right_order / std::max(out_total, 1));
  // The second stage, fitted on half of the others and checked on the other
  // half, then fitted on all of them.
  std::vector<Eigen::Vector2d> ax, bx;
  std::vector<double> ay, by;
  for (std::size_t k = 0; k < sx.size(); ++k)
    ((k % 2) ? bx : ax).push_back(sx[k]), ((k % 2) ? by : ay).push_back(sy[k]);
  const Eigen::Vector2d half = fit_stage(ax, ay, 1.0);
  int half_right = 0;
  for (std::size_t k = 0; k < bx.size(); ++k) half_right += half.dot(bx[k]) * by[k] > 0;
  const Eigen::Vector2d w = fit_stage(sx, sy, 1.0);
  int all_right = 0;
  for (std::size_t k = 0; k < sx.size(); ++k) all_right += w.dot(sx[k]) * sy[k] > 0;
  std::printf(
      "second stage: fitted on half, the other half %.1f%%; on all %.1f%% (weights %g %g)\n",
      100.0 * half_right / std::max<std::size_t>(bx.size(), 1),
      100.0 * all_right / std::max<std::size_t>(sx.size(), 1), w[0], w[1]);
  {
    // Exploratory: with products, so one trusts the other where it is unsure.
    auto terms = [](const Eigen::Vector2d& v) {
      Eigen::VectorXd t(4);
      t << v[0], v[1], v[0] * std::abs(v[1]), v[1] * std::abs(v[0]);
      return t;
    };
    std::vector<Eigen::VectorXd> tx, ux;
    for (const auto& v : ax) tx.push_back(terms(v));
    for (const auto& v : bx) ux.push_back(terms(v));
    const Eigen::VectorXd h4 = fit_stage(tx, ay, 1.0);
    int r4 = 0;
    for (std::size_t k = 0; k < ux.size(); ++k) r4 += h4.dot(ux[k]) * by[k] > 0;
    std::printf("with products: the other half %.1f%%\n",
                100.0 * r4 / std::max<std::size_t>(ux.size(), 1));
  }
  net->order_weight = w[0];
  net->patch_weight = w[1];

  if (write.empty()) return 0;
  if (!writable) {
    std::fprintf(stderr, "only one patch file and %d hidden units can be written\n",
                 detail::kPatchHidden);
    return 1;
  }
  std::string same_report;
  const detail::SameDepthNet same =
      train_same_depth(records, split, same_iterations, seed, use_adam ? &adam : nullptr,
                       grey ? (coarse_same ? detail::kPatchInputs : detail::kPatchCoarseStart)
                            : detail::kPatchLabelInputs,
                       &same_report, teachers.empty() ? nullptr : &soft.same);
  char method_buffer[200];
  if (use_adam)
    std::snprintf(method_buffer, sizeof method_buffer,
                  "--adam --epochs %d --rate %g --batch %d --decay %g --wide-dropout %g%s%s",
                  adam.epochs, adam.rate, adam.batch, adam.decay,
                  grey && grey_dropout > 0 ? 0.0 : adam.wide_dropout,
                  adam.anneal ? " --anneal" : "", grey ? " --grey" : "");
  if (grey && grey_dropout > 0)
    std::snprintf(method_buffer + std::strlen(method_buffer),
                  sizeof method_buffer - std::strlen(method_buffer), " --grey-dropout %g",
                  grey_dropout);
  else if (!use_adam)
    std::snprintf(method_buffer, sizeof method_buffer, "--iterations %d --same-iterations %d",
                  iterations, same_iterations);
  std::string method = method_buffer;
  if (coarse != "none") method += " --coarse " + coarse;
  if (thin_weight != 1.0) {
    char text[40];
    std::snprintf(text, sizeof text, " --thin-weight %g", thin_weight);
    method += text;
  }
  if (!teachers.empty()) {
    char text[80];
    std::snprintf(text, sizeof text, " --distil-share %g%s --teachers", adam.soft_share,
                  mean_logit ? " --distil-logit" : "");
    method += text;
    for (const std::string& t : teachers) method += " " + t.substr(t.find_last_of('/') + 1);
  }
  std::string drawings = "the first " + std::to_string(net_cases) + " drawings";
  if (extra_from != std::numeric_limits<int>::max()) {
    method += " --extra-from " + std::to_string(extra_from);
    drawings += " and of drawings " + std::to_string(extra_from) + " on (thin_fork_style)";
  }
  if (dark_from != std::numeric_limits<int>::max()) {
    method += " --dark-from " + std::to_string(dark_from);
    drawings += " and of drawings " + std::to_string(dark_from) + " on (dark_style)";
  }
  std::FILE* f = std::fopen(write.c_str(), "w");
  if (f == nullptr) {
    std::fprintf(stderr, "cannot write %s\n", write.c_str());
    return 1;
  }
  std::fprintf(f,
               "#include \"patch_model.h\"\n\n"
               "namespace hair25d::layering::detail {\n\n"
               "// The trainer writes this file; it is kept as written so that a run\n"
               "// reproduces it byte for byte.\n"
               "// clang-format off\n"
               "// Written by bench/layering/train_layering_patch.cpp on generated drawings only\n"
               "// (never the annotated cases), Release build:\n"
               "//   train_layering_patch --cases %d --seed %llu --net-cases %d --order-scales %d\n"
               "//     %s\n"
               "// Weights input-major (w1[input][hidden]). The network learnt from the %d\n"
               "// ends of ordered boundaries of %s (and each exchanged);\n"
               "// boundary sign right there %.1f%%, on the other drawings %.1f%% (order\n"
               "// model %.1f%%), where the second stage was fitted.\n"
               "const PatchNet& patch_weights() {\n"
               "  static const PatchNet kNet = ",
               cases, static_cast<unsigned long long>(seed), net_cases, order_scales,
               method.c_str(), n, drawings.c_str(), 100.0 * in_right / std::max(in_total, 1),
               100.0 * out_right_patch / std::max(out_total, 1),
               100.0 * out_right_order / std::max(out_total, 1));
  write_net(f, *net);
  std::fprintf(f,
               ";\n  return kNet;\n}\n\n"
               "// Same program, same drawings: same depth or ordered, from every end of\n"
               "// the first drawings' occluding boundaries; its stage on the others.\n"
               "// %s.\n"
               "const SameDepthNet& patch_same_weights() {\n"
               "  static const SameDepthNet kNet = {",
               same_report.c_str());
  write_net(f, same.net);
  std::fprintf(f,
               ", %.17g};\n  return kNet;\n}\n// clang-format on\n\n"
               "}  // namespace hair25d::layering::detail\n",
               same.intercept);
  std::fclose(f);
  return 0;
}
