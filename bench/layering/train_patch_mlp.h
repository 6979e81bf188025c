// Minibatch training of the junction patch networks (layering/src/patch_model.h)
// for train_layering_patch.cpp: the same one-hidden-layer form as OpenCV's
// ANN_MLP, but trained on what the layering reads — the pair score
// g(P) ∓ g(swapped P) of each end — by Adam on a logistic loss. OpenCV's
// full-batch RPROP needs hundreds of passes over the data, which limits the
// number of drawings it can learn from; a few dozen minibatch passes do.
// Deterministic: the same seed gives the same weights (one thread, a fixed
// shuffle from std::mt19937_64).
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <numeric>
#include <random>
#include <vector>

#include "hair25d/core/adam.h"
#include "patch_model.h"

namespace hair25d::layering_training {

struct MlpOptions {
  int epochs = 30;
  int batch = 128;
  double rate = 1e-3;      // Adam's step
  double decay = 1e-5;     // L2 on the weights (not the biases)
  double sharpness = 2.0;  // the logistic loss reads sharpness × score
  bool symmetric = false;  // score g(P) + g(P̄) instead of g(P) − g(P̄)
  int inputs = hair25d::layering::detail::kPatchInputs;  // the first this many
  // Share of training rows whose inputs past `fine_inputs` (the wide scale)
  // are zeroed, so the network cannot lean on the wide scale alone.
  double wide_dropout = 0.0;
  bool anneal = false;  // the step falls linearly to 0 over the epochs
  // Distillation (train_patch_mlp's `soft`): each row's target probability
  // is (1 − soft_share) × its label's + soft_share × the teachers'.
  double soft_share = 1.0;

  int fine_inputs = hair25d::layering::detail::kPatchScaleInputs;
  // ... up to this input (exclusive; -1: to the last one), so that a grey
  // channel dropout leaves the coarse scale after it (session 17).
  int dropout_end = -1;
  std::uint64_t seed = 1;
};

using RowMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The logistic loss of z = sharpness × score against a target probability t
// of "+1" (a soft label): t · softplus(−z) + (1 − t) · softplus(z), whose
// derivative in z is σ(z) − t. For t = 1 or 0 it is the loss of a hard ±1
// label, softplus(∓z).
inline double soft_target_loss(double z, double t, double* dz) {
  auto softplus = [](double v) {
    return v > 0 ? v + std::log1p(std::exp(-v)) : std::log1p(std::exp(v));
  };
  if (dz != nullptr) *dz = 1.0 / (1.0 + std::exp(-z)) - t;
  return t * softplus(-z) + (1.0 - t) * softplus(z);
}

// The target an ensemble of `k` teachers gives one row from their scores
// (each as the layering reads it: g(P) ∓ g(swapped P)): the mean of their
// probabilities σ(sharpness × score), or with `mean_logit` the probability
// of their mean log-odds.
inline float ensemble_target(const float* scores, int k, double sharpness, bool mean_logit) {
  double sum = 0;
  for (int i = 0; i < k; ++i)
    sum += mean_logit ? sharpness * scores[i] : 1.0 / (1.0 + std::exp(-sharpness * scores[i]));
  const double mean = sum / std::max(k, 1);
  return static_cast<float>(mean_logit ? 1.0 / (1.0 + std::exp(-mean)) : mean);
}

// One member of the ensemble (patch_model.h), trained on its own score from
// initial weights and a shuffle drawn from `seed`, written into hidden units
// [member · kPatchMemberHidden, ...) and b2[member] of `net`. With `soft`
// (one probability of "+1" per row, e.g. ensemble_target of teachers) the
// rows' targets mix it with the labels by o.soft_share (distillation).
inline void train_patch_member(const RowMatrix& x, const RowMatrix& xs, const std::vector<float>& y,
                               const std::vector<float>& w, const MlpOptions& o, std::uint64_t seed,
                               int member, hair25d::layering::detail::PatchNet& net,
                               const std::vector<float>* soft = nullptr) {
  namespace detail = hair25d::layering::detail;
  constexpr int H = detail::kPatchMemberHidden;
  const int d = o.inputs;
  const int n = static_cast<int>(x.rows());
  std::mt19937_64 rng(seed);
  auto uniform = [&rng] { return static_cast<float>((rng() >> 11) * 0x1.0p-53 * 2.0 - 1.0); };
  Eigen::MatrixXf w1(d, H);
  for (int k = 0; k < d; ++k)
    for (int h = 0; h < H; ++h) w1(k, h) = uniform() * 1.0f / std::sqrt(static_cast<float>(d) / 8);
  Eigen::RowVectorXf b1 = Eigen::RowVectorXf::Zero(H);
  Eigen::VectorXf w2(H);
  for (int h = 0; h < H; ++h) w2(h) = uniform() / std::sqrt(static_cast<float>(H));
  float b2 = 0;
  const float alpha = 2.0f / 3.0f, beta = 1.7159f, half = 0.5f * alpha;
  // Adam's moments.
  Eigen::MatrixXf m1 = Eigen::MatrixXf::Zero(d, H), v1 = m1;
  Eigen::RowVectorXf mb1 = Eigen::RowVectorXf::Zero(H), vb1 = mb1;
  Eigen::VectorXf m2 = Eigen::VectorXf::Zero(H), v2 = m2;
  float mb2 = 0, vb2 = 0;
  long step = 0;
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  RowMatrix bx(o.batch, d), bs(o.batch, d);
  for (int epoch = 0; epoch < o.epochs; ++epoch) {
    for (int i = n - 1; i > 0; --i) std::swap(order[i], order[rng() % (i + 1)]);
    double loss_sum = 0, weight_sum = 0;
    for (int start = 0; start < n; start += o.batch) {
      const int m = std::min(o.batch, n - start);
      for (int r = 0; r < m; ++r) {
        bx.row(r) = x.row(order[start + r]).head(d);
        bs.row(r) = xs.row(order[start + r]).head(d);
        if (o.wide_dropout > 0 && d > o.fine_inputs && (rng() >> 11) * 0x1.0p-53 < o.wide_dropout) {
          const int end = o.dropout_end < 0 ? d : std::min(o.dropout_end, d);
          bx.row(r).segment(o.fine_inputs, end - o.fine_inputs).setZero();
          bs.row(r).segment(o.fine_inputs, end - o.fine_inputs).setZero();
        }
      }
      // Forward both patches.
      auto forward = [&](const RowMatrix& in, Eigen::MatrixXf& t, Eigen::VectorXf& g,
                         Eigen::VectorXf& tg) {
        Eigen::MatrixXf pre = in.topRows(m) * w1;
        pre.rowwise() += b1;
        t = (pre * half).array().tanh().matrix();
        const Eigen::VectorXf out = (beta * t) * w2 + Eigen::VectorXf::Constant(m, b2);
        tg = (out * half).array().tanh().matrix();
        g = beta * tg;
      };
      Eigen::MatrixXf t1, t2;
      Eigen::VectorXf g1, g2, tg1, tg2;
      forward(bx, t1, g1, tg1);
      forward(bs, t2, g2, tg2);
      // Loss softplus(−y κ s), s = g1 ± g2; dL/ds.
      Eigen::VectorXf ds(m);
      float batch_weight = 0;
      for (int r = 0; r < m; ++r) {
        const float yy = y[order[start + r]], ww = w[order[start + r]];
        const float s = o.symmetric ? g1(r) + g2(r) : g1(r) - g2(r);
        if (soft != nullptr) {
          const double t = (1.0 - o.soft_share) * (yy > 0 ? 1.0 : 0.0) +
                           o.soft_share * (*soft)[order[start + r]];
          double dz = 0;
          loss_sum += ww * soft_target_loss(o.sharpness * s, t, &dz);
          weight_sum += ww;
          batch_weight += ww;
          ds(r) = static_cast<float>(ww * o.sharpness * dz);
          continue;
        }
        const float z = -yy * static_cast<float>(o.sharpness) * s;
        loss_sum += ww * (z > 0 ? z + std::log1p(std::exp(-z)) : std::log1p(std::exp(z)));
        weight_sum += ww;
        batch_weight += ww;
        ds(r) = ww * -yy * static_cast<float>(o.sharpness) / (1.0f + std::exp(-z));
      }
      ds /= std::max(batch_weight, 1e-12f);
      Eigen::MatrixXf gw1 = o.decay * w1;
      Eigen::RowVectorXf gb1 = Eigen::RowVectorXf::Zero(H);
      Eigen::VectorXf gw2 = o.decay * w2;
      float gb2 = 0;
      auto backward = [&](const RowMatrix& in, const Eigen::MatrixXf& t, const Eigen::VectorXf& tg,
                          const Eigen::VectorXf& dg) {
        const Eigen::VectorXf dout =
            (dg.array() * beta * half * (1.0f - tg.array().square())).matrix();
        gw2 += (beta * t).transpose() * dout;
        gb2 += dout.sum();
        const Eigen::MatrixXf dpre =
            ((dout * w2.transpose()).array() * beta * half * (1.0f - t.array().square())).matrix();
        gw1.noalias() += in.topRows(m).transpose() * dpre;
        gb1 += dpre.colwise().sum();
      };
      backward(bx, t1, tg1, ds);
      backward(bs, t2, tg2, o.symmetric ? Eigen::VectorXf(ds) : Eigen::VectorXf(-ds));
      const double progress = (epoch + static_cast<double>(start) / n) / o.epochs;
      const float lr =
          adam_rate(static_cast<float>(o.rate * (o.anneal ? 1.0 - progress : 1.0)), ++step);
      adam_step(w1, m1, v1, gw1, lr);
      adam_step(b1, mb1, vb1, gb1, lr);
      adam_step(w2, m2, v2, gw2, lr);
      adam_step(b2, mb2, vb2, gb2, lr);
    }
    std::printf("  epoch %d: loss %.4f\n", epoch + 1, loss_sum / std::max(weight_sum, 1e-12));
    std::fflush(stdout);
  }
  const int first = member * H;
  for (int k = 0; k < detail::kPatchInputs; ++k)
    for (int h = 0; h < H; ++h) net.w1[k][first + h] = k < d ? w1(k, h) : 0.0f;
  for (int h = 0; h < H; ++h) net.b1[first + h] = b1(h), net.w2[first + h] = w2(h);
  net.b2[member] = b2;
}

// `x` holds one end's patch per row, `xs` the same patch exchanged, `y` ±1
// (antisymmetric: +1 when A is above; symmetric: +1 when same depth), `w`
// each row's weight. Returns the network in the layering's layout: its
// kPatchMembers members trained one after the other, member m from seed
// o.seed + m (so a one-member network is the member of o.seed). `soft`: see
// train_patch_member.
inline hair25d::layering::detail::PatchNet train_patch_mlp(
    const RowMatrix& x, const RowMatrix& xs, const std::vector<float>& y,
    const std::vector<float>& w, const MlpOptions& o, const std::vector<float>* soft = nullptr) {
  namespace detail = hair25d::layering::detail;
  auto net = std::make_unique<detail::PatchNet>();
  for (int m = 0; m < detail::kPatchMembers; ++m) {
    if (detail::kPatchMembers > 1) std::printf("  member %d of %d\n", m + 1, detail::kPatchMembers);
    train_patch_member(x, xs, y, w, o, o.seed + static_cast<std::uint64_t>(m), m, *net, soft);
  }
  return *net;
}

}  // namespace hair25d::layering_training
