// The layering stage and the eval-layering report (FORMATS.md) over the six
// annotated cases in tests/data.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/temp_dir.h"
#include "hair25d/core/atomic_file.h"
#include "hair25d/core/error.h"
#include "hair25d/pipeline/layering_stage.h"

namespace hair25d::pipeline {
namespace {

const std::filesystem::path kCases = std::filesystem::path(HAIR25D_TEST_DATA_DIR) / "annotated";

TEST(LayeringStage, RunGivesRelationsDepthsAndAnOverlay) {
  const AnnotatedCase c = read_annotated_case(kCases / "case5");
  const LayeringRun run = run_layering(c.image, c.regions);
  EXPECT_EQ(run.overlay.width(), c.image.width());
  EXPECT_EQ(run.overlay.height(), c.image.height());
  EXPECT_EQ(run.result.depth.size(), c.regions.labels().size());
  EXPECT_FALSE(run.result.relations.empty());
}

TEST(LayeringStage, EvaluationReportMatchesItsCases) {
  // A folder of its own: test runs in other trees share the temp directory.
  const hair25d::testing::TempDir tmp;
  const std::filesystem::path overlays = tmp / "overlays";
  LayeringEvalOptions options;
  options.overlays_dir = overlays;
  const LayeringEvalReport report = evaluate_layering(kCases, options);
  ASSERT_EQ(report.cases.size(), 6u);
  int pairs = 0, correct = 0;
  for (const LayeringCaseResult& c : report.cases) {
    EXPECT_TRUE(c.error.empty()) << c.error;
    pairs += c.score.pairs;
    correct += c.score.correct;
    EXPECT_TRUE(std::filesystem::exists(overlays / (c.score.name + ".png")));
  }
  EXPECT_EQ(report.pairs, pairs);
  EXPECT_EQ(report.correct, correct);
  EXPECT_EQ(report.pairs, 305);  // judged pairs over the six cases

  // The JSON has FORMATS.md's keys and the same numbers.
  const nlohmann::json doc = nlohmann::json::parse(layering_report_json(report));
  EXPECT_EQ(doc.at("pairs").get<int>(), report.pairs);
  EXPECT_EQ(doc.at("correct").get<int>(), report.correct);
  EXPECT_NEAR(doc.at("accuracy").get<double>(), report.accuracy(), 1e-12);
  ASSERT_EQ(doc.at("cases").size(), 6u);
  const nlohmann::json& first = doc.at("cases").at(0);
  EXPECT_EQ(first.at("name").get<std::string>(), "case0");
  for (const char* key : {"pairs", "correct", "accuracy", "seconds", "regions"})
    EXPECT_TRUE(first.contains(key)) << key;
  EXPECT_EQ(first.at("wrong").size(), static_cast<std::size_t>(first.at("pairs").get<int>() -
                                                               first.at("correct").get<int>()));

  const std::string table = format_layering_table(report);
  EXPECT_NE(table.find("case3"), std::string::npos);
  EXPECT_NE(table.find("total"), std::string::npos);
  std::filesystem::remove_all(overlays);
}

TEST(LayeringStage, ACaseTheLayeringRefusesCountsAsWrong) {
  AnnotatedCase c = read_annotated_case(kCases / "case2");
  c.regions = LabelMap(c.image.width(), c.image.height(), 1);  // one region only
  const LayeringEvalReport report = evaluate_layering(std::vector<AnnotatedCase>{c}, {});
  ASSERT_EQ(report.cases.size(), 1u);
  EXPECT_FALSE(report.cases[0].error.empty());
  EXPECT_EQ(report.correct, 0);
  EXPECT_EQ(report.pairs, static_cast<int>(c.pairs.size()));
}

// Records every progress report, to see whether scoring started.
class RecordingProgress final : public Progress {
 public:
  void report(std::string_view stage, double fraction, std::string_view message) override {
    reports.push_back(std::string(stage) + " " + std::to_string(fraction) + " " +
                      std::string(message));
  }
  std::vector<std::string> reports;
};

TEST(LayeringStage, ABadCaseAmongGoodOnesFailsBeforeAnyIsScored) {
  namespace fs = std::filesystem;
  testing::TempDir dir;
  fs::copy(kCases / "case0", dir / "a_good", fs::copy_options::recursive);
  fs::copy(kCases / "case1", dir / "b_bad", fs::copy_options::recursive);
  const std::string text = read_text_file(dir / "b_bad" / "layering.json");
  std::ofstream(dir / "b_bad" / "layering.json", std::ios::trunc)
      << text.substr(0, text.size() / 2);
  RecordingProgress progress;
  try {
    evaluate_layering(dir.path(), LayeringEvalOptions{}, &progress);
    FAIL() << "a truncated layering.json was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("b_bad"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("layering.json"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(progress.reports.empty()) << progress.reports.front();
}

TEST(LayeringStage, RejectsFoldersWithoutCases) {
  EXPECT_THROW(evaluate_layering(kCases / "no_such_folder", {}), Error);
  EXPECT_THROW(evaluate_layering(kCases / "case0" / "strands", {}), Error);
}

TEST(LayeringStage, FromStrokesNeedsStrokes) {
  AnnotatedCase c = read_annotated_case(kCases / "case5");
  c.strokes.reset();
  LayeringEvalOptions options;
  options.from_strokes = true;
  EXPECT_THROW(evaluate_layering(std::vector<AnnotatedCase>{c}, options), Error);
}

}  // namespace
}  // namespace hair25d::pipeline
