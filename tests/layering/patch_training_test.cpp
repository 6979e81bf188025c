// The patch networks' trainer (bench/layering/train_patch_mlp.h): it learns
// a rule a patch shows, keeps the layering's symmetries, and repeats itself.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "patch_model.h"
#include "train_patch_mlp.h"

namespace {

using hair25d::layering::detail::kPatchInputs;
using hair25d::layering::detail::Patch;
using hair25d::layering::detail::patch_same_score;
using hair25d::layering::detail::patch_score;
using hair25d::layering::detail::PatchNet;
using hair25d::layering::detail::swapped;
using hair25d::layering_training::ensemble_target;
using hair25d::layering_training::MlpOptions;
using hair25d::layering_training::RowMatrix;
using hair25d::layering_training::soft_target_loss;
using hair25d::layering_training::train_patch_mlp;

// Random values in the fine scale's first two rows (the far v < 0 edge),
// "A above" when the A − B channel of the first row sums above 0: a rule
// the network must learn from the patch and, exchanged, its opposite.
struct Toy {
  RowMatrix x, xs;
  std::vector<float> y, w;
  std::vector<Patch> patches;
};

Toy toy(int n, unsigned seed, int inputs) {
  Toy t;
  t.x.resize(n, inputs);
  t.xs.resize(n, inputs);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1, 1);
  for (int k = 0; k < n; ++k) {
    Patch p{};
    for (int i = 0; i < 64; ++i) p[i] = u(rng);  // rows 0 and 1, both channels
    double upper = 0;
    for (int i = 0; i < 16 * 2; i += 2) upper += p[i];  // row 0, channel A − B
    t.y.push_back(upper > 0 ? 1.0f : -1.0f);
    t.w.push_back(1.0f);
    const Patch s = swapped(p);
    for (int i = 0; i < inputs; ++i) t.x(k, i) = p[i], t.xs(k, i) = s[i];
    t.patches.push_back(p);
  }
  return t;
}

// How many of the toy's patches the net scores with the right sign; every
// score must flip exactly when A and B are exchanged.
int right_and_antisymmetric(const PatchNet& net, const Toy& test) {
  int right = 0;
  for (std::size_t k = 0; k < test.patches.size(); ++k) {
    const double s = patch_score(net, test.patches[k]);
    right += s * test.y[k] > 0;
    EXPECT_EQ(patch_score(net, swapped(test.patches[k])), -s);
  }
  return right;
}

TEST(PatchTraining, LearnsARuleAndKeepsTheSignFlip) {
  const int inputs = 512;
  const Toy train = toy(2000, 3, inputs), test = toy(300, 4, inputs);
  MlpOptions o;
  o.epochs = 15;
  o.inputs = inputs;
  o.seed = 7;
  const PatchNet net = train_patch_mlp(train.x, train.xs, train.y, train.w, o);
  const int right = right_and_antisymmetric(net, test);
  EXPECT_GT(right, 270) << "of 300";  // chance is 150
  // Inputs past `inputs` are weighed 0, so the layering reads only those.
  for (int k = inputs; k < kPatchInputs; ++k)
    for (float v : net.w1[k]) ASSERT_EQ(v, 0.0f);
}

// "A above" when the grey channel's first row (toward B, v < 0) is darker
// than its last: exchanging A and B mirrors the rows and flips the answer,
// so the rule keeps the layering's symmetry; the label channels are noise.
Toy grey_toy(int n, unsigned seed) {
  using hair25d::layering::detail::kPatchCells;
  using hair25d::layering::detail::kPatchLabelInputs;
  Toy t;
  t.x.resize(n, kPatchInputs);
  t.xs.resize(n, kPatchInputs);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1, 1), g(0, 2);
  for (int k = 0; k < n; ++k) {
    Patch p{};
    for (int i = 0; i < 64; ++i) p[i] = u(rng);
    double first = 0, last = 0;
    for (int i = 0; i < kPatchCells; ++i) {
      p[kPatchLabelInputs + i] = g(rng);
      p[kPatchLabelInputs + (kPatchCells - 1) * kPatchCells + i] = g(rng);
      first += p[kPatchLabelInputs + i];
      last += p[kPatchLabelInputs + (kPatchCells - 1) * kPatchCells + i];
    }
    t.y.push_back(first > last ? 1.0f : -1.0f);
    t.w.push_back(1.0f);
    const Patch s = swapped(p);
    for (int i = 0; i < kPatchInputs; ++i) t.x(k, i) = p[i], t.xs(k, i) = s[i];
    t.patches.push_back(p);
  }
  return t;
}

TEST(PatchTraining, LearnsARuleOfTheGreyChannel) {
  const Toy train = grey_toy(2000, 13), test = grey_toy(300, 14);
  MlpOptions o;
  o.epochs = 15;
  o.inputs = kPatchInputs;
  o.seed = 9;
  const PatchNet net = train_patch_mlp(train.x, train.xs, train.y, train.w, o);
  const int right = right_and_antisymmetric(net, test);
  EXPECT_GT(right, 270) << "of 300";
  // Trained on the label channels only, the same rule is chance.
  o.inputs = hair25d::layering::detail::kPatchLabelInputs;
  const PatchNet blind = train_patch_mlp(train.x, train.xs, train.y, train.w, o);
  EXPECT_LT(right_and_antisymmetric(blind, test), 200) << "of 300";
}

TEST(PatchTraining, TheSameSeedGivesTheSameWeights) {
  const Toy train = toy(300, 5, kPatchInputs);
  MlpOptions o;
  o.epochs = 2;
  o.symmetric = true;
  o.anneal = true;
  o.seed = 11;
  const PatchNet a = train_patch_mlp(train.x, train.xs, train.y, train.w, o);
  const PatchNet b = train_patch_mlp(train.x, train.xs, train.y, train.w, o);
  EXPECT_EQ(a.w1, b.w1);
  EXPECT_EQ(a.w2, b.w2);
  EXPECT_EQ(a.b2, b.b2);
  o.seed = 12;
  const PatchNet c = train_patch_mlp(train.x, train.xs, train.y, train.w, o);
  EXPECT_NE(a.w1, c.w1);
  // A symmetric network's score does not change when A and B swap.
  for (const Patch& p : train.patches)
    EXPECT_EQ(patch_same_score(a, swapped(p)), patch_same_score(a, p));
}

// The soft-target loss: its derivative is the finite difference of the
// loss, and a target of 1 or 0 gives the hard label's loss softplus(∓z).
TEST(PatchTraining, SoftTargetLossGradientAndHardLimit) {
  for (double t : {0.0, 0.1, 0.5, 0.83, 1.0})
    for (double z : {-30.0, -3.0, -0.4, 0.0, 0.7, 2.5, 25.0}) {
      double dz = 0;
      soft_target_loss(z, t, &dz);
      const double h = 1e-5;
      const double numeric =
          (soft_target_loss(z + h, t, nullptr) - soft_target_loss(z - h, t, nullptr)) / (2 * h);
      EXPECT_NEAR(dz, numeric, 1e-6) << "t " << t << ", z " << z;
    }
  for (double z : {-4.0, -0.5, 0.0, 1.5, 40.0}) {
    EXPECT_NEAR(soft_target_loss(z, 1.0, nullptr), std::log1p(std::exp(-z)), 1e-12);
    EXPECT_NEAR(soft_target_loss(z, 0.0, nullptr), std::log1p(std::exp(z)), 1e-12);
  }
  // The loss is least where σ(z) is the target.
  const double z0 = std::log(0.3 / 0.7);
  EXPECT_LT(soft_target_loss(z0, 0.3, nullptr), soft_target_loss(z0 + 0.2, 0.3, nullptr));
  EXPECT_LT(soft_target_loss(z0, 0.3, nullptr), soft_target_loss(z0 - 0.2, 0.3, nullptr));
}

TEST(PatchTraining, EnsembleTargetIsTheTeachersMean) {
  const float scores[3] = {1.0f, -0.5f, 2.0f};
  auto sigma = [](double v) { return 1.0 / (1.0 + std::exp(-v)); };
  EXPECT_NEAR(ensemble_target(scores, 3, 2.0, false), (sigma(2.0) + sigma(-1.0) + sigma(4.0)) / 3,
              1e-6);
  EXPECT_NEAR(ensemble_target(scores, 3, 2.0, true), sigma((2.0 - 1.0 + 4.0) / 3), 1e-6);
}

// A planted soft rule: P(A above) = σ(f / 2), f the A − B sum of the first
// row (as in `toy`), labels drawn from it. A network distilled from that
// probability (the teachers' mean standing in) must give it back as
// σ(2 × score) on other patches; one trained on the drawn labels alone is
// far from it, and one distilled with the targets' share 0 is that one.
TEST(PatchTraining, DistilledNetworkMatchesTheTeachersProbability) {
  const int inputs = 512;
  Toy train = toy(3000, 21, inputs);
  const Toy test = toy(300, 22, inputs);
  auto planted = [](const Patch& p) {
    double f = 0;
    for (int i = 0; i < 16 * 2; i += 2) f += p[i];
    return 1.0 / (1.0 + std::exp(-f / 2));
  };
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<float> soft;
  for (std::size_t k = 0; k < train.patches.size(); ++k) {
    soft.push_back(static_cast<float>(planted(train.patches[k])));
    train.y[k] = u(rng) < soft.back() ? 1.0f : -1.0f;
  }
  MlpOptions o;
  o.epochs = 30;
  o.inputs = inputs;
  o.seed = 25;
  o.anneal = true;
  auto distance = [&](const PatchNet& net) {
    double sum = 0;
    for (const Patch& p : test.patches)
      sum += std::abs(1.0 / (1.0 + std::exp(-2.0 * patch_score(net, p))) - planted(p));
    return sum / static_cast<double>(test.patches.size());
  };
  const PatchNet distilled = train_patch_mlp(train.x, train.xs, train.y, train.w, o, &soft);
  const PatchNet hard = train_patch_mlp(train.x, train.xs, train.y, train.w, o);
  o.soft_share = 0.0;
  const PatchNet none = train_patch_mlp(train.x, train.xs, train.y, train.w, o, &soft);
  const double d_distilled = distance(distilled), d_hard = distance(hard), d_none = distance(none);
  std::printf("mean |p − planted|: distilled %.4f, labels %.4f, share 0 %.4f\n", d_distilled,
              d_hard, d_none);
  EXPECT_LT(d_distilled, 0.02);
  EXPECT_GT(d_hard, 3 * d_distilled);
  EXPECT_NEAR(d_none, d_hard, 0.01);
  right_and_antisymmetric(distilled, test);  // the sign still flips exactly
}

}  // namespace
