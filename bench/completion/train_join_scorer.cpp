// Trains the learned join scorer (completion/include/hair25d/completion/
// join_scorer.h, paper §5.1) and measures it against the hand cost.
//   collect: runs completion on generated drawings (or annotated cases) with
//            the candidates recorded (with the annotation's relations or,
//            --relations predicted, the layering's), labels each by the ground truth
//            (one strand or two) and appends them to a CSV;
//   train:   reads such CSVs, trains on the rows of the training files in
//            the cost window, prints how the scorer and the hand cost
//            separate right from wrong in the band on every file, and writes
//            the weights as join_scorer_weights.cpp;
//   probs:   prints every committed net's probability for each row of such a
//            CSV (session 32: how the nets judge one net's refusals).
// Training seeds must be disjoint from the evaluation seeds (101–116,
// 201–216, 301–316, 401–416) and the annotated cases; docs/completion-record.md gives the
// commands.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <exception>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "../../tests/completion/annotated_eval.h"
#include "case_relations.h"
#include "hair25d/completion/completion.h"
#include "hair25d/completion/join_scorer.h"
#include "hair25d/core/annotation.h"
#include "hair25d/generator/generator.h"

namespace {

using namespace hair25d;
using completion::JoinFeatures;
using completion::kJoinFeatures;
// The input saying a row is an angle refusal's second chance (session 35).
constexpr int kRetried = 44;
// The input saying a row is a cover refusal's second chance (session 36).
constexpr int kCoverRetried = 54;
// The input saying a row is a cut's second partner (session 37).
constexpr int kSecondCut = 64;

struct Row {
  std::string set;
  int label = 0;
  double hand_cost = 0;
  JoinFeatures f{};
};

// Session 28: with `crop_size` > 0, each candidate's crop (JoinCandidate::
// crop) is appended to `crops` and its row, with the committed net's
// probability after `chosen`, to `crop_rows`, in the same order.
struct CropFiles {
  int size = 0;
  std::FILE* rows = nullptr;
  std::FILE* crops = nullptr;
};

void collect_case(const AnnotatedCase& c, const std::string& set, bool predicted, double band_high,
                  double rescue_high, double max_angle, bool scorer_on, std::FILE* out, int* rows,
                  const CropFiles& crop_files = {}) {
  completion::Options o;
  o.inpaint_strands = false;
  o.inpaint_background = false;
  // Session 37: with `scorer_on`, the model's own matching (a cut's second
  // partners exist only there), the scorer at its defaults.
  o.join_scorer.enabled = scorer_on;
  o.join_scorer.record = true;
  if (!scorer_on) {
    o.join_scorer.band_high = band_high;
    // Candidates over band_high are recorded with `retrained` (the scorer
    // is off here, so it decides nothing).
    o.join_scorer.rescue_high = rescue_high;
    o.join_scorer.retrained = rescue_high > band_high;
    o.join_scorer.max_angle_deg = max_angle;
  }
  o.join_scorer.crop_size = crop_files.size;
  completion::Input in = completion::test::input_from_case(c);
  if (predicted) {
    std::string error;
    in.relations = completion::test::predicted_relations(c, &error);
    if (!error.empty())
      std::fprintf(stderr, "%s: layering failed (%s); no relations\n", c.name.c_str(),
                   error.c_str());
  }
  const completion::Result r = completion::complete_strands(in, o);
  std::map<int, int> truth;
  for (const AnnotatedRegion& reg : c.region_list) truth[reg.id] = reg.strand;
  for (const completion::JoinCandidate& j : r.join_candidates) {
    if (!truth.count(j.region_a) || !truth.count(j.region_b)) continue;
    std::fprintf(out, "%s,%s,%d,%d,%d,%.6f,%d", set.c_str(), c.name.c_str(), j.region_a, j.region_b,
                 truth[j.region_a] == truth[j.region_b] ? 1 : 0, j.hand_cost, j.chosen ? 1 : 0);
    for (float v : j.features) std::fprintf(out, ",%.9g", static_cast<double>(v));
    std::fprintf(out, "\n");
    ++*rows;
    if (crop_files.size == 0) continue;
    if (j.crop.size() !=
        static_cast<std::size_t>(completion::kJoinCropChannels) * crop_files.size * crop_files.size)
      throw std::runtime_error(c.name + ": a candidate without its crop");
    std::fprintf(crop_files.rows, "%s,%s,%d,%d,%d,%.6f,%d,%.6f", set.c_str(), c.name.c_str(),
                 j.region_a, j.region_b, truth[j.region_a] == truth[j.region_b] ? 1 : 0,
                 j.hand_cost, j.chosen ? 1 : 0,
                 completion::join_probability(completion::default_join_scorer(), j.features));
    for (float v : j.features) std::fprintf(crop_files.rows, ",%.9g", static_cast<double>(v));
    std::fprintf(crop_files.rows, "\n");
    if (std::fwrite(j.crop.data(), 1, j.crop.size(), crop_files.crops) != j.crop.size())
      throw std::runtime_error("cannot write the crops");
  }
}

std::vector<Row> read_rows(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::vector<Row> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    // A CSV collected with another number of inputs (another session's
    // scorer) says so rather than only "bad row".
    if (cells.size() != 7 + kJoinFeatures)
      throw std::runtime_error("bad row in " + path + ": " + std::to_string(cells.size()) +
                               " cells; must be " + std::to_string(7 + kJoinFeatures));
    Row r;
    r.set = cells[0];
    r.label = std::stoi(cells[4]);
    r.hand_cost = std::stod(cells[5]);
    for (int k = 0; k < kJoinFeatures; ++k) r.f[k] = std::stof(cells[7 + k]);
    rows.push_back(r);
  }
  return rows;
}

// Area under the ROC curve of `score` (higher = one strand), ties half.
double auc(const std::vector<double>& score, const std::vector<int>& label) {
  std::vector<int> idx(score.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<int>(i);
  std::sort(idx.begin(), idx.end(), [&](int a, int b) { return score[a] < score[b]; });
  double rank_sum = 0, pos = 0;
  for (std::size_t i = 0; i < idx.size();) {
    std::size_t j = i;
    while (j < idx.size() && score[idx[j]] == score[idx[i]]) ++j;
    const double rank = 0.5 * (i + j - 1) + 1;
    for (std::size_t k = i; k < j; ++k)
      if (label[idx[k]]) rank_sum += rank, ++pos;
    i = j;
  }
  const double neg = static_cast<double>(score.size()) - pos;
  if (pos == 0 || neg == 0) return 0.5;
  return (rank_sum - pos * (pos + 1) / 2) / (pos * neg);
}

void report(const std::string& name, const std::vector<Row>& rows,
            const std::vector<completion::JoinScorerNet>& nets, double low, double high,
            double limit, double threshold) {
  std::vector<double> hand, learned;
  std::vector<int> label;
  int hand_tp = 0, hand_fp = 0, net_tp = 0, net_fp = 0, pos = 0;
  for (const Row& r : rows) {
    if (r.hand_cost < low || r.hand_cost > high) continue;
    const double p = completion::join_probability(nets, r.f);
    hand.push_back(-r.hand_cost);
    learned.push_back(p);
    label.push_back(r.label);
    pos += r.label;
    const bool by_hand = r.hand_cost <= limit, by_net = p >= threshold;
    hand_tp += by_hand && r.label, hand_fp += by_hand && !r.label;
    net_tp += by_net && r.label, net_fp += by_net && !r.label;
  }
  std::printf(
      "%s: band [%.2f, %.2f] %zu candidates (%d one strand): AUC hand cost %.3f, scorer %.3f; "
      "accepted right / wrong: cost <= %.2f %d / %d, p >= %.2f %d / %d\n",
      name.c_str(), low, high, label.size(), pos, auc(hand, label), auc(learned, label), limit,
      hand_tp, hand_fp, threshold, net_tp, net_fp);
  // Above the limit, accepted by the scorer (rescued); below it, refused (vetoed).
  for (double t : {0.05, 0.1, 0.2, 0.5, 0.6, 0.7, 0.8, 0.85, 0.9, 0.95}) {
    int rescued[2] = {0, 0}, vetoed[2] = {0, 0};
    for (std::size_t i = 0; i < label.size(); ++i) {
      const bool by_hand = -hand[i] <= limit, by_net = learned[i] >= t;
      if (!by_hand && by_net) ++rescued[label[i]];
      if (by_hand && !by_net) ++vetoed[label[i]];
    }
    std::printf(
        "  p >= %.2f: rescued above the limit right / wrong %d / %d; vetoed below it %d / %d\n", t,
        rescued[1], rescued[0], vetoed[1], vetoed[0]);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Train and measure the learned join scorer"};
  app.require_subcommand(1);
  auto* collect = app.add_subcommand("collect", "Append recorded candidates to a CSV");
  std::string csv, set = "train", annotated, shadings = "all";
  int seed = 3000, count = 8, width = 800, height = 640, strands = 20;
  collect->add_option("--csv", csv, "CSV to append to")->required();
  collect->add_option("--set", set, "Name of the set in the first column");
  collect->add_option("--annotated", annotated, "Folder of annotated cases (else generated)");
  collect->add_option("--seed", seed, "First generator seed")->check(CLI::NonNegativeNumber);
  collect->add_option("--count", count, "Seeds")->check(CLI::Range(1, 10000));
  collect->add_option("--width", width)->check(CLI::Range(64, 8192));
  collect->add_option("--height", height)->check(CLI::Range(64, 8192));
  collect->add_option("--strands", strands)->check(CLI::Range(1, 400));
  double record_high = completion::JoinScorerOptions{}.band_high;
  collect->add_option("--band-high", record_high, "Record candidates up to this hand cost");
  // The wide net's recipe (session 18) records up to 120° although the
  // model leaves those candidates out by default (join_scorer.h).
  // Session 29: over band_high too, the rivals still counted up to it (as
  // JoinScorerOptions::rescue_high judges them).
  double rescue_high = 0.0;
  collect->add_option("--rescue-high", rescue_high,
                      "Also record candidates up to this hand cost (rivals counted to --band-high; "
                      "default none)");
  double record_angle = 120.0;
  collect->add_option("--max-angle", record_angle,
                      "Record candidates whose tangents turn up to this (degrees)");
  // Session 23 (joins42): `hair25d model` joins with the layering's
  // relations, whose wrong ones make candidates the annotation's never do.
  std::string relations = "annotated";
  collect
      ->add_option("--relations", relations,
                   "Relations completion is given: annotated (the case's pairs) or predicted "
                   "(the layering's, as eval_joins --relations predicted)")
      ->check(CLI::IsMember({"annotated", "predicted"}));
  collect
      ->add_option(
          "--shading", shadings,
          "flat, two-tone, gradient, screentone, all (each a seed) or mixed (seed % 4: "
          "flat, two-tone, gradient, screentone; eval_joins --shading mixed from a seed % 4 = 0)")
      ->check(CLI::IsMember({"flat", "two-tone", "gradient", "screentone", "all", "mixed"}));
  // Session 28: crops of the drawing around each candidate for an image
  // cue (bench/completion/train_join_cnn.py).
  std::string crops_dir;
  int crop_size = 48, seed_step = 1;
  collect->add_option("--crops", crops_dir,
                      "Folder to append rows.csv (the CSV's rows with the committed net's "
                      "probability after `chosen`) and crops.u8 (JoinCandidate::crop) to");
  collect->add_option("--crop-size", crop_size, "Crop side, pixels")->check(CLI::Range(8, 512));
  bool scorer_on = false;
  collect->add_flag("--scorer-on", scorer_on,
                    "Record with the scorer on at its defaults (the model's matching; "
                    "--band-high, --rescue-high and --max-angle ignored): a cut's second "
                    "partners are recorded only so");
  collect->add_option("--seed-step", seed_step, "Seeds seed, seed + step, ... (count of them)")
      ->check(CLI::Range(1, 1000));

  auto* train = app.add_subcommand("train", "Train on CSVs, report, write the weights");
  std::vector<std::string> train_csv, eval_csv;
  std::string out;
  double win_low = 1.0, win_high = 4.0, low = 1.4, high = 4.0, limit = 2.4, threshold = 0.5;
  completion::JoinTrainingOptions topt;
  train->add_option("--train", train_csv, "Training CSVs")->required();
  train->add_option("--eval", eval_csv, "Evaluation CSVs (reported per set)");
  train->add_option("--window-low", win_low, "Train on hand costs from");
  train->add_option("--window-high", win_high, "... up to");
  train->add_option("--band-low", low, "Band reported");
  train->add_option("--band-high", high, "Band reported");
  train->add_option("--threshold", threshold, "Probability accepted");
  train->add_option("--epochs", topt.epochs);
  train->add_option("--rate", topt.rate);
  train->add_option("--decay", topt.decay);
  train->add_option("--seed", topt.seed);
  train->add_option("--out", out, "join_scorer_weights.cpp to write");
  std::string function;
  train->add_option("--function", function,
                    "The function in --out (default_join_scorer, with --ensemble-seeds "
                    "ensemble_join_scorers; wide_join_scorer, paint_ensemble_join_scorers)");
  bool wide_only = false;
  train->add_flag(
      "--wide-only", wide_only,
      "Only candidates over the angle limit (worst_angle > 1, JoinScorerOptions::max_angle_deg)");
  // Session 35: the second chances of angle refusals (JoinScorerOptions::
  // angle_refusal_threshold) are rows of their own: only with this flag,
  // and never among the others' rows.
  bool angle_only = false;
  train->add_flag("--angle-only", angle_only,
                  "Only angle refusals' second chances (input `retried`; "
                  "JoinScorerOptions::angle_refusal_threshold); without it they are left out");
  // Session 36: the second chances of cover refusals (JoinScorerOptions::
  // cover_refusal_threshold) likewise.
  bool cover_only = false;
  train->add_flag("--cover-only", cover_only,
                  "Only cover refusals' second chances (input `cover_retried`; "
                  "JoinScorerOptions::cover_refusal_threshold); without it they are left out");
  // Session 37: a cut's second partners (JoinScorerOptions::
  // second_partner_threshold), recorded with --scorer-on, likewise.
  bool second_only = false;
  train->add_flag("--second-only", second_only,
                  "Only a cut's second partners (input `second_cut`; "
                  "JoinScorerOptions::second_partner_threshold); without it they are left out");
  bool baseline = false;
  // Session 23: the same report for the committed net, so a retrained one
  // is compared with it on the same rows.
  train->add_flag("--baseline", baseline,
                  "Also report the committed net (default_join_scorer, with --wide-only "
                  "wide_join_scorer) on the --eval files");
  // Session 25: nets of several training seeds, written as the ensemble.
  std::vector<std::uint64_t> ensemble_seeds;
  train->add_option("--ensemble-seeds", ensemble_seeds,
                    "Train one net per seed (--seed ignored) and write them to --out as "
                    "ensemble_join_scorers (join_scorer_ensemble_weights.cpp)");
  std::vector<std::string> drop;
  train->add_option("--drop", drop, "Inputs left out (set to 0 everywhere): feature names");
  // Session 32: every committed net's probability for each row, to compare
  // the nets' opinions on the candidates one of them refuses.
  auto* probs = app.add_subcommand("probs", "Print every committed net's probability per row");
  std::string probs_csv;
  probs->add_option("--csv", probs_csv, "CSV of collect")->required();
  CLI11_PARSE(app, argc, argv);

  try {
    // The committed net was trained on every input: zeroed ones would not be its rows.
    if (baseline && !drop.empty()) throw std::runtime_error("--baseline with --drop");
    if (std::string(completion::join_feature_name(kRetried)) != "retried")
      throw std::runtime_error("input 44 is not `retried`");
    if (std::string(completion::join_feature_name(kCoverRetried)) != "cover_retried")
      throw std::runtime_error("input 54 is not `cover_retried`");
    if (std::string(completion::join_feature_name(kSecondCut)) != "second_cut")
      throw std::runtime_error("input 64 is not `second_cut`");
    if (second_only && (wide_only || angle_only || cover_only))
      throw std::runtime_error("--second-only with --wide-only, --angle-only or --cover-only");
    if (cover_only && (wide_only || angle_only))
      throw std::runtime_error("--cover-only with --wide-only or --angle-only");
    if (wide_only && angle_only) throw std::runtime_error("--wide-only with --angle-only");
    std::vector<int> dropped;
    for (const std::string& name : drop) {
      int k = 0;
      while (k < kJoinFeatures && name != completion::join_feature_name(k)) ++k;
      if (k == kJoinFeatures) throw std::runtime_error("no feature " + name);
      dropped.push_back(k);
    }
    auto rows_of = [&](const std::string& path) {
      std::vector<Row> rows = read_rows(path);
      std::erase_if(rows, [&](const Row& r) { return (r.f[kSecondCut] > 0.5f) != second_only; });
      if (wide_only) std::erase_if(rows, [](const Row& r) { return !(r.f[1] > 1.0f); });
      if (!second_only)
        std::erase_if(rows,
                      [&](const Row& r) { return (r.f[kCoverRetried] > 0.5f) != cover_only; });
      if (!cover_only && !second_only)
        std::erase_if(rows, [&](const Row& r) { return (r.f[kRetried] > 0.5f) != angle_only; });
      for (Row& r : rows)
        for (int k : dropped) r.f[k] = 0;
      return rows;
    };
    if (*probs) {
      std::printf(
          "set,case,a,b,label,hand_cost,default,retrained,screentone,shaded,ensemble,paint,"
          "angle,cover,cover_plain,second\n");
      std::ifstream in(probs_csv);
      if (!in) throw std::runtime_error("cannot read " + probs_csv);
      for (std::string line; std::getline(in, line);) {
        std::vector<std::string> cells;
        std::stringstream s(line);
        for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
        if (cells.size() != 7 + kJoinFeatures)
          throw std::runtime_error("bad row in " + probs_csv + ": " + std::to_string(cells.size()) +
                                   " cells; must be " + std::to_string(7 + kJoinFeatures));
        JoinFeatures f{};
        for (int k = 0; k < kJoinFeatures; ++k) f[k] = std::stof(cells[7 + k]);
        std::printf("%s,%s,%s,%s,%s,%s,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f\n",
                    cells[0].c_str(), cells[1].c_str(), cells[2].c_str(), cells[3].c_str(),
                    cells[4].c_str(), cells[5].c_str(),
                    completion::join_probability(completion::default_join_scorer(), f),
                    completion::join_probability(completion::retrained_join_scorer(), f),
                    completion::join_probability(completion::screentone_join_scorer(), f),
                    completion::join_probability(completion::shaded_join_scorer(), f),
                    completion::join_probability(completion::ensemble_join_scorers(), f),
                    completion::join_probability(completion::paint_ensemble_join_scorers(), f),
                    completion::join_probability(completion::angle_join_scorer(), f),
                    completion::join_probability(completion::cover_join_scorer(), f),
                    completion::join_probability(completion::cover_plain_join_scorer(), f),
                    completion::join_probability(completion::second_partner_join_scorer(), f));
      }
      return 0;
    }
    if (*collect) {
      std::FILE* f = std::fopen(csv.c_str(), "a");
      if (!f) throw std::runtime_error("cannot write " + csv);
      int rows = 0;
      CropFiles crop_files;
      if (!crops_dir.empty()) {
        crop_files.size = crop_size;
        crop_files.rows = std::fopen((crops_dir + "/rows.csv").c_str(), "a");
        crop_files.crops = std::fopen((crops_dir + "/crops.u8").c_str(), "ab");
        if (!crop_files.rows || !crop_files.crops)
          throw std::runtime_error("cannot write rows.csv and crops.u8 in " + crops_dir);
      }
      if (!annotated.empty()) {
        for (const auto& folder : find_annotated_cases(annotated))
          collect_case(read_annotated_case(folder), set, relations == "predicted", record_high,
                       rescue_high, record_angle, scorer_on, f, &rows, crop_files);
      } else {
        const generator::Shading kinds[] = {generator::Shading::kFlat, generator::Shading::kTwoTone,
                                            generator::Shading::kGradient,
                                            generator::Shading::kScreentone};
        const char* names[] = {"flat", "two-tone", "gradient", "screentone"};
        for (int k = 0; k < count; ++k)
          for (int s = 0; s < 4; ++s) {
            const int case_seed = seed + k * seed_step;
            if (shadings == "mixed" ? case_seed % 4 != s
                                    : shadings != "all" && shadings != names[s])
              continue;
            generator::Options g;
            g.width = width;
            g.height = height;
            g.strand_count = strands;
            g.seed = static_cast<std::uint64_t>(case_seed);
            g.shading = kinds[s];
            AnnotatedCase c = generator::generate_case(g);
            c.name = std::string(names[s]) + "-" + std::to_string(case_seed);
            collect_case(c, set, relations == "predicted", record_high, rescue_high, record_angle,
                         scorer_on, f, &rows, crop_files);
          }
      }
      std::fclose(f);
      if (crop_files.rows) std::fclose(crop_files.rows);
      if (crop_files.crops) std::fclose(crop_files.crops);
      std::printf("%d candidates appended to %s\n", rows, csv.c_str());
      return 0;
    }
    std::vector<completion::JoinFeatures> x;
    std::vector<int> y;
    for (const std::string& path : train_csv)
      for (const Row& r : rows_of(path))
        if (r.hand_cost >= win_low && r.hand_cost <= win_high)
          x.push_back(r.f), y.push_back(r.label);
    std::printf("training on %zu candidates with hand cost in [%.2f, %.2f]\n", x.size(), win_low,
                win_high);
    if (!ensemble_seeds.empty()) {
      std::vector<completion::JoinScorerNet> nets;
      std::ostringstream comment;
      comment << "The learned join scorer's ensemble (join_scorer.h), trained by\n"
              << "bench/completion/train_join_scorer train on " << x.size()
              << " candidates (hand cost " << win_low << "-" << win_high << "), " << topt.epochs
              << " epochs, decay " << topt.decay << ", seeds";
      for (std::uint64_t s : ensemble_seeds) {
        completion::JoinTrainingOptions o = topt;
        o.seed = s;
        const completion::JoinTrainingResult t = completion::train_join_scorer(x, y, o);
        std::printf("seed %llu: trained %d epochs, final loss %.4f\n",
                    static_cast<unsigned long long>(s), t.epochs, t.final_loss);
        nets.push_back(t.net);
        comment << " " << s;
      }
      comment << ".";
      for (const std::string& path : eval_csv) {
        std::map<std::string, std::vector<Row>> by_set;
        for (const Row& r : rows_of(path)) by_set[r.set].push_back(r);
        for (const auto& [name, rows] : by_set) {
          report(path + " " + name, rows, nets, low, high, limit, threshold);
          if (baseline) {
            std::vector<completion::JoinScorerNet> with = nets;
            with.push_back(completion::default_join_scorer());
            report("  with the committed net: " + path + " " + name, rows, with, low, high, limit,
                   threshold);
            report("  committed net: " + path + " " + name, rows,
                   {completion::default_join_scorer()}, low, high, limit, threshold);
          }
        }
      }
      if (!out.empty()) {
        std::ofstream file(out);
        file << completion::join_scorer_ensemble_source(
            nets, comment.str(), function.empty() ? "ensemble_join_scorers" : function);
        if (!file) throw std::runtime_error("cannot write " + out);
        std::printf("wrote %s\n", out.c_str());
      }
      return 0;
    }
    const completion::JoinTrainingResult t = completion::train_join_scorer(x, y, topt);
    std::printf("trained %d epochs, final loss %.4f\n", t.epochs, t.final_loss);
    for (const std::string& path : train_csv)
      report(path, rows_of(path), {t.net}, low, high, limit, threshold);
    for (const std::string& path : eval_csv) {
      std::map<std::string, std::vector<Row>> by_set;
      for (const Row& r : rows_of(path)) by_set[r.set].push_back(r);
      for (const auto& [name, rows] : by_set) {
        report(path + " " + name, rows, {t.net}, low, high, limit, threshold);
        if (baseline)
          report("  committed net: " + path + " " + name, rows,
                 {wide_only     ? completion::wide_join_scorer()
                  : angle_only  ? completion::angle_join_scorer()
                  : cover_only  ? completion::cover_join_scorer()
                  : second_only ? completion::second_partner_join_scorer()
                                : completion::default_join_scorer()},
                 low, high, limit, threshold);
        if (baseline && !wide_only)
          report("  retrained net: " + path + " " + name, rows,
                 {completion::retrained_join_scorer()}, low, high, limit, threshold);
      }
    }
    if (!out.empty()) {
      std::ostringstream comment;
      comment << "The learned join scorer's weights (join_scorer.h), trained by\n"
              << "bench/completion/train_join_scorer train on " << x.size()
              << " candidates (hand cost " << win_low << "-" << win_high << "), seed " << topt.seed
              << ", " << t.epochs << " epochs, final loss " << t.final_loss << ".";
      if (!drop.empty()) comment << "\nInputs left out:";
      for (const std::string& name : drop) comment << " " << name;
      std::ofstream file(out);
      if (wide_only) comment << "\nOnly candidates over the angle limit (--wide-only).";
      if (angle_only) comment << "\nOnly angle refusals' second chances (--angle-only).";
      if (cover_only) comment << "\nOnly cover refusals' second chances (--cover-only).";
      if (second_only) comment << "\nOnly a cut's second partners (--second-only).";
      file << completion::join_scorer_source(t.net, comment.str(),
                                             function.empty() ? "default_join_scorer" : function);
      if (!file) throw std::runtime_error("cannot write " + out);
      std::printf("wrote %s\n", out.c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "train_join_scorer: %s\n", e.what());
    return 1;
  }
  return 0;
}
