#include "hair25d/completion/join_scorer.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <sstream>

#include "hair25d/core/adam.h"
#include "hair25d/core/error.h"

namespace hair25d::completion {
namespace {

constexpr const char* kNames[kJoinFeatures] = {"mean_angle",
                                               "worst_angle",
                                               "colour",
                                               "colour_step",
                                               "width_change",
                                               "gap_per_width",
                                               "bulge",
                                               "no_common_occluder",
                                               "uncovered",
                                               "hand_cost",
                                               "log_width",
                                               "log_gap",
                                               "profile_luma",
                                               "profile_rgb",
                                               "profile_corr",
                                               "profile_spread",
                                               "texture",
                                               "mid_above_both",
                                               "mid_unlabelled",
                                               "mid_above_one",
                                               "mid_occluders",
                                               "back_pieces",
                                               "edges_min",
                                               "edges_max",
                                               "radial",
                                               "elongation_min",
                                               "elongation_max",
                                               "rival_margin_min",
                                               "rival_margin_max",
                                               "rivals_min",
                                               "rivals_max",
                                               "region_colour",
                                               "paint_step",
                                               "flat_paint",
                                               "shading_continues",
                                               "rare_paint",
                                               "tone_cost",
                                               "one_sided",
                                               "tone_same",
                                               "tone_other",
                                               "mass_step",
                                               "dark_step",
                                               "top_occluder",
                                               "patch_occluders",
                                               "retried",
                                               "own_worst_angle",
                                               "arm_min",
                                               "arm_mean",
                                               "ends_part",
                                               "retried_either_end",
                                               "retried_reversed",
                                               "retried_side",
                                               "retried_turned",
                                               "sliver",
                                               "cover_retried",
                                               "miss_paper",
                                               "miss_face",
                                               "miss_ink",
                                               "miss_below",
                                               "miss_sibling",
                                               "miss_other",
                                               "shape_cover",
                                               "miss_per_width",
                                               "miss_at_cuts",
                                               "second_cut",
                                               "second_p",
                                               "first_p",
                                               "first_cost_step",
                                               "faced_gap",
                                               "faced_overlap",
                                               "cut_width_share",
                                               "partner_widths",
                                               "partners_gap",
                                               "partners_side",
                                               "first_partners",
                                               "field_cross_max",
                                               "field_cross_larger"};

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// The ranges most of JoinScorerOptions' fields lie in: a probability bar
// (0, 1), a bar where 1 turns a second chance off (0, 1], a probability
// floor [0, 1) or [0, 1], a hand cost [0, 100), and an RGB distance
// [0, 60] where 0 turns a rule off.
enum class Range { kOpenUnit, kBarOrOff, kLowUnit, kUnit, kCost, kRgb };

bool in_range(double v, Range r) {
  switch (r) {
    case Range::kOpenUnit:
      return v > 0 && v < 1;
    case Range::kBarOrOff:
      return v > 0 && v <= 1;
    case Range::kLowUnit:
      return v >= 0 && v < 1;
    case Range::kUnit:
      return v >= 0 && v <= 1;
    case Range::kCost:
      return v >= 0 && v < 100;
    case Range::kRgb:
      return v >= 0 && v <= 60;
  }
  return false;
}

const char* range_text(Range r) {
  switch (r) {
    case Range::kOpenUnit:
      return "(0, 1)";
    case Range::kBarOrOff:
      return "(0, 1]";
    case Range::kLowUnit:
      return "[0, 1)";
    case Range::kUnit:
      return "[0, 1]";
    case Range::kCost:
      return "[0, 100)";
    case Range::kRgb:
      return "[0, 60]";
  }
  return "";
}

void check_finite(const JoinFeatures& f, const char* what) {
  for (int i = 0; i < kJoinFeatures; ++i)
    if (!std::isfinite(f[i]))
      throw Error(std::string(what) + ": feature " + kNames[i] + " = " + num(f[i]) +
                  "; must be finite");
}

}  // namespace

const char* join_feature_name(int index) {
  if (index < 0 || index >= kJoinFeatures)
    throw Error("join_feature_name: index " + std::to_string(index) + "; must be in [0, " +
                std::to_string(kJoinFeatures) + ")");
  return kNames[index];
}

double join_probability(const JoinScorerNet& net, const JoinFeatures& features) {
  check_finite(features, "join_probability");
  std::array<float, kJoinFeatures> x{};
  for (int k = 0; k < kJoinFeatures; ++k) x[k] = (features[k] - net.mean[k]) * net.inv_std[k];
  float out = net.b2;
  for (int h = 0; h < kJoinHidden; ++h) {
    float pre = net.b1[h];
    for (int k = 0; k < kJoinFeatures; ++k) pre += x[k] * net.w1[k][h];
    out += net.w2[h] * std::tanh(pre);
  }
  return 1.0 / (1.0 + std::exp(-static_cast<double>(out)));
}

double join_probability(std::span<const JoinScorerNet> nets, const JoinFeatures& features) {
  if (nets.empty()) throw Error("join_probability: no nets");
  double sum = 0;
  for (const JoinScorerNet& net : nets) sum += join_probability(net, features);
  return sum / static_cast<double>(nets.size());
}

bool JoinScorerOptions::is_valid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error != nullptr) *error = "JoinScorerOptions::" + m;
    return false;
  };
  auto check = [&](const char* name, double v, Range r) {
    return in_range(v, r) ||
           fail(std::string(name) + " = " + num(v) + "; must be in " + range_text(r));
  };
  if (!(band_low >= 0)) return fail("band_low = " + num(band_low) + "; must be >= 0");
  if (!(band_high > band_low))
    return fail("band_high = " + num(band_high) + "; must be > band_low (" + num(band_low) + ")");
  if (!(band_high < 100)) return fail("band_high = " + num(band_high) + "; must be < 100");
  if (!check("threshold", threshold, Range::kOpenUnit)) return false;
  if (!check("screentone_threshold", screentone_threshold, Range::kOpenUnit)) return false;
  if (!check("ensemble_threshold", ensemble_threshold, Range::kOpenUnit)) return false;
  if (!check("paint_ensemble_threshold", paint_ensemble_threshold, Range::kOpenUnit)) return false;
  if (!check("cel_ensemble_threshold", cel_ensemble_threshold, Range::kOpenUnit)) return false;
  if (!check("retrained_threshold", retrained_threshold, Range::kOpenUnit)) return false;
  if (!check("retrained_shaded_threshold", retrained_shaded_threshold, Range::kOpenUnit))
    return false;
  if (!(refuse_below >= 0 && refuse_below <= threshold))
    return fail("refuse_below = " + num(refuse_below) + "; must be in [0, threshold (" +
                num(threshold) + ")]");
  if (!check("veto_low", veto_low, Range::kCost)) return false;
  if (!check("screentone_veto_low", screentone_veto_low, Range::kCost)) return false;
  if (!check("veto_below", veto_below, Range::kLowUnit)) return false;
  if (!check("rescue_high", rescue_high, Range::kCost)) return false;
  if (!check("rescue_threshold", rescue_threshold, Range::kOpenUnit)) return false;
  if (!check("screentone_veto_below", screentone_veto_below, Range::kLowUnit)) return false;
  if (!check("screentone_rescue_threshold", screentone_rescue_threshold, Range::kBarOrOff))
    return false;
  if (!check("shaded_threshold", shaded_threshold, Range::kOpenUnit)) return false;
  if (!check("shaded_veto_below", shaded_veto_below, Range::kLowUnit)) return false;
  if (!check("shaded_rescue_threshold", shaded_rescue_threshold, Range::kBarOrOff)) return false;
  if (!(max_angle_deg >= 0 && max_angle_deg <= 180))
    return fail("max_angle_deg = " + num(max_angle_deg) + "; must be in [0, 180]");
  if (!check("wide_band_high", wide_band_high, Range::kCost)) return false;
  if (!check("wide_threshold", wide_threshold, Range::kOpenUnit)) return false;
  if (!check("side_threshold", side_threshold, Range::kBarOrOff)) return false;
  if (!check("second_low", second_low, Range::kUnit)) return false;
  if (!check("second_threshold", second_threshold, Range::kBarOrOff)) return false;
  if (!check("angle_refusal_threshold", angle_refusal_threshold, Range::kBarOrOff)) return false;
  if (!check("cover_refusal_threshold", cover_refusal_threshold, Range::kBarOrOff)) return false;
  if (!check("cover_flat_threshold", cover_flat_threshold, Range::kBarOrOff)) return false;
  if (!check("cover_screentone_threshold", cover_screentone_threshold, Range::kBarOrOff))
    return false;
  if (!check("second_partner_threshold", second_partner_threshold, Range::kBarOrOff)) return false;
  if (!check("field_cross_max", field_cross_max, Range::kRgb)) return false;
  if (!check("field_cross_larger_max", field_cross_larger_max, Range::kRgb)) return false;
  if (!check("field_cross_low", field_cross_low, Range::kUnit)) return false;
  if (!(crop_size >= 0 && crop_size <= 512))
    return fail("crop_size = " + std::to_string(crop_size) + "; must be in [0, 512]");
  return true;
}

bool JoinTrainingOptions::is_valid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error != nullptr) *error = "JoinTrainingOptions::" + m;
    return false;
  };
  if (epochs < 1 || epochs > 100000)
    return fail("epochs = " + std::to_string(epochs) + "; must be in [1, 100000]");
  if (batch < 1 || batch > 1 << 20)
    return fail("batch = " + std::to_string(batch) + "; must be in [1, 2^20]");
  if (!(rate > 0 && rate < 1)) return fail("rate = " + num(rate) + "; must be in (0, 1)");
  if (!(decay >= 0 && decay < 1)) return fail("decay = " + num(decay) + "; must be in [0, 1)");
  return true;
}

JoinTrainingResult train_join_scorer(const std::vector<JoinFeatures>& rows,
                                     const std::vector<int>& labels,
                                     const JoinTrainingOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw Error("train_join_scorer: " + why);
  if (rows.size() != labels.size())
    throw Error("train_join_scorer: " + std::to_string(rows.size()) + " rows but " +
                std::to_string(labels.size()) + " labels; must be as many");
  int positives = 0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] != 0 && labels[i] != 1)
      throw Error("train_join_scorer: label " + std::to_string(i) + " = " +
                  std::to_string(labels[i]) + "; must be 0 or 1");
    positives += labels[i];
    check_finite(rows[i], "train_join_scorer");
  }
  const int n = static_cast<int>(rows.size());
  if (positives < 2 || n - positives < 2)
    throw Error("train_join_scorer: " + std::to_string(positives) + " rows of one strand and " +
                std::to_string(n - positives) + " of two; must be at least 2 of each");
  constexpr int D = kJoinFeatures, H = kJoinHidden;
  JoinTrainingResult result;
  JoinScorerNet& net = result.net;
  // Standardise (in double, so the sums do not depend on float rounding order).
  for (int k = 0; k < D; ++k) {
    double s = 0, s2 = 0;
    for (const JoinFeatures& r : rows) s += r[k], s2 += static_cast<double>(r[k]) * r[k];
    const double mean = s / n, var = std::max(0.0, s2 / n - mean * mean);
    net.mean[k] = static_cast<float>(mean);
    // A constant input carries nothing; zero keeps it out.
    net.inv_std[k] = var > 1e-12 ? static_cast<float>(1.0 / std::sqrt(var)) : 0.0f;
  }
  Eigen::MatrixXf x(n, D);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < D; ++k) x(i, k) = (rows[i][k] - net.mean[k]) * net.inv_std[k];
  // Both classes weigh the same in all (wrong candidates outnumber right ones).
  std::vector<float> weight(n);
  for (int i = 0; i < n; ++i)
    weight[i] = labels[i] ? 0.5f * n / positives : 0.5f * n / (n - positives);

  std::mt19937_64 rng(options.seed);
  auto uniform = [&rng] { return static_cast<float>((rng() >> 11) * 0x1.0p-53 * 2.0 - 1.0); };
  Eigen::MatrixXf w1(D, H);
  for (int k = 0; k < D; ++k)
    for (int h = 0; h < H; ++h) w1(k, h) = uniform() * std::sqrt(3.0f / D);
  Eigen::RowVectorXf b1 = Eigen::RowVectorXf::Zero(H);
  Eigen::VectorXf w2(H);
  for (int h = 0; h < H; ++h) w2(h) = uniform() * std::sqrt(3.0f / H);
  float b2 = 0;
  Eigen::MatrixXf m1 = Eigen::MatrixXf::Zero(D, H), v1 = m1;
  Eigen::RowVectorXf mb1 = Eigen::RowVectorXf::Zero(H), vb1 = mb1;
  Eigen::VectorXf m2 = Eigen::VectorXf::Zero(H), v2 = m2;
  float mb2 = 0, vb2 = 0;
  long step = 0;
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  for (int epoch = 0; epoch < options.epochs; ++epoch) {
    for (int i = n - 1; i > 0; --i) std::swap(order[i], order[rng() % (i + 1)]);
    double loss = 0, total = 0;
    for (int start = 0; start < n; start += options.batch) {
      const int m = std::min(options.batch, n - start);
      Eigen::MatrixXf bx(m, D);
      for (int r = 0; r < m; ++r) bx.row(r) = x.row(order[start + r]);
      Eigen::MatrixXf pre = bx * w1;
      pre.rowwise() += b1;
      const Eigen::MatrixXf t = pre.array().tanh().matrix();
      const Eigen::VectorXf out = t * w2 + Eigen::VectorXf::Constant(m, b2);
      Eigen::VectorXf dout(m);
      float batch_weight = 0;
      for (int r = 0; r < m; ++r) {
        const int i = order[start + r];
        const float p = 1.0f / (1.0f + std::exp(-out(r)));
        const float y = static_cast<float>(labels[i]);
        // Softplus form of the logistic loss, stable for large |out|.
        const float z = y > 0 ? -out(r) : out(r);
        loss += weight[i] * (z > 0 ? z + std::log1p(std::exp(-z)) : std::log1p(std::exp(z)));
        total += weight[i];
        batch_weight += weight[i];
        dout(r) = weight[i] * (p - y);
      }
      dout /= std::max(batch_weight, 1e-12f);
      const Eigen::VectorXf gw2 = t.transpose() * dout + static_cast<float>(options.decay) * w2;
      const float gb2 = dout.sum();
      const Eigen::MatrixXf dpre =
          ((dout * w2.transpose()).array() * (1.0f - t.array().square())).matrix();
      const Eigen::MatrixXf gw1 = bx.transpose() * dpre + static_cast<float>(options.decay) * w1;
      const Eigen::RowVectorXf gb1 = dpre.colwise().sum();
      const float lr = adam_rate(static_cast<float>(options.rate), ++step);
      adam_step(w1, m1, v1, gw1, lr);
      adam_step(b1, mb1, vb1, gb1, lr);
      adam_step(w2, m2, v2, gw2, lr);
      adam_step(b2, mb2, vb2, gb2, lr);
    }
    result.final_loss = loss / std::max(total, 1e-12);
    result.epochs = epoch + 1;
  }
  for (int k = 0; k < D; ++k)
    for (int h = 0; h < H; ++h) net.w1[k][h] = w1(k, h);
  for (int h = 0; h < H; ++h) net.b1[h] = b1(h), net.w2[h] = w2(h);
  net.b2 = b2;
  return result;
}

namespace {

// %.9g round-trips every float exactly, so the file is the net bit for bit.
std::string float_literal(float v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(v));
  std::string out(buf);
  // "0" or "3" would not be a float literal with the suffix.
  if (out.find_first_of(".en") == std::string::npos) out += ".0";
  return out + "f";
}

// The first `count` values (all of them by default).
template <class Values>
std::string float_row(const Values& values, std::size_t count = static_cast<std::size_t>(-1)) {
  std::string out = "{";
  for (std::size_t i = 0; i < std::min(count, values.size()); ++i)
    out += (i ? ", " : "") + float_literal(values[i]);
  return out + "}";
}

// How many inputs the net reads: past the last one with a mean, a scale or
// a weight, the initialiser leaves them out and they are zero-filled, so a
// net trained before inputs were added (session 35's 44-53) is printed as
// it was written then.
int inputs_used(const JoinScorerNet& net) {
  int used = kJoinFeatures;
  auto zero = [](float v) { return v == 0.0f; };
  while (used > 0 && zero(net.mean[used - 1]) && zero(net.inv_std[used - 1]) &&
         std::all_of(net.w1[used - 1].begin(), net.w1[used - 1].end(), zero))
    --used;
  return used;
}

// The braced initialiser of one net, its lines led by `indent`.
std::string net_initialiser(const JoinScorerNet& net, const std::string& indent) {
  const int used = inputs_used(net);
  std::ostringstream s;
  s << "{\n"
    << indent << float_row(net.mean, used) << ",\n"
    << indent << float_row(net.inv_std, used) << ",\n"
    << indent << "{{\n";
  for (int k = 0; k < used; ++k) s << indent << "    " << float_row(net.w1[k]) << ",\n";
  s << indent << "}},\n"
    << indent << float_row(net.b1) << ",\n"
    << indent << float_row(net.w2) << ",\n"
    << indent << float_literal(net.b2) << "}";
  return s.str();
}

// Kept as written (long rows, the comment's own lines): clang-format would
// reflow it and the file would no longer be what the trainer wrote.
std::string generated_head(const std::string& comment) {
  std::ostringstream s;
  s << "// clang-format off\n";
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) s << "// " << line << "\n";
  s << "// Generated file: do not edit (bench/completion/train_join_scorer writes it).\n"
    << "#include \"hair25d/completion/join_scorer.h\"\n\n"
    << "namespace hair25d::completion {\n\n";
  return s.str();
}

}  // namespace

std::string join_scorer_source(const JoinScorerNet& net, const std::string& comment,
                               const std::string& function) {
  std::ostringstream s;
  s << generated_head(comment) << "const JoinScorerNet& " << function << "() {\n"
    << "  static const JoinScorerNet net" << net_initialiser(net, "      ") << ";\n"
    << "  return net;\n"
    << "}\n\n"
    << "}  // namespace hair25d::completion\n";
  return s.str();
}

std::string join_scorer_ensemble_source(std::span<const JoinScorerNet> nets,
                                        const std::string& comment, const std::string& function) {
  std::ostringstream s;
  s << generated_head(comment) << "std::span<const JoinScorerNet> " << function << "() {\n";
  if (nets.empty()) {
    s << "  return {};\n";
  } else {
    s << "  static const JoinScorerNet nets[] = {\n";
    for (const JoinScorerNet& net : nets)
      s << "      " << net_initialiser(net, "          ") << ",\n";
    s << "  };\n"
      << "  return nets;\n";
  }
  s << "}\n\n"
    << "}  // namespace hair25d::completion\n";
  return s.str();
}

}  // namespace hair25d::completion
