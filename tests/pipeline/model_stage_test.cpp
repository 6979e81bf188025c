#include "hair25d/pipeline/model_stage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <set>
#include <thread>

#include "../completion/annotated_eval.h"
#include "hair25d/core/annotation.h"
#include "hair25d/core/error.h"
#include "hair25d/core/image_io.h"
#include "hair25d/core/model_io.h"
#ifdef HAIR25D_HAVE_GENERATOR
#include "hair25d/generator/generator.h"
#endif

namespace hair25d::pipeline {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path p =
      fs::temp_directory_path() / ("hair25d_model_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(p);
  return p;
}

// The annotation's relations, certain (user-fixed) as in RestPose.
std::vector<RegionRelation> relations_of(const AnnotatedCase& c) {
  std::vector<RegionRelation> out;
  for (const AnnotatedPair& p : c.pairs) out.push_back({p.a, p.b, p.relation, 1.0, true, false});
  return out;
}

// Checks that hold for every model.
void expect_consistent(const ModelRun& run, const LabelMap& regions) {
  const HairModel& m = run.model;
  ASSERT_EQ(run.strands.size(), m.strands.size());
  std::set<int> seen;
  for (const Strand& s : m.strands) {
    for (int r : s.regions) EXPECT_TRUE(seen.insert(r).second) << "region " << r << " twice";
    EXPECT_GE(s.outline.size(), 3u);
    ASSERT_FALSE(s.skeleton.nodes.empty());
    EXPECT_EQ(s.skeleton.parent[0], -1);
    for (std::size_t i = 1; i < s.skeleton.nodes.size(); ++i) {
      EXPECT_LT(s.skeleton.parent[i], static_cast<int>(i));
      const Vec2 mid = 0.5 * (s.skeleton.nodes[i] + s.skeleton.nodes[s.skeleton.parent[i]]);
      // Inside the completed shape, up to a pixel on its outline.
      bool near = point_in_polygon(s.outline, mid);
      for (std::size_t k = 0; k < s.outline.size() && !near; ++k)
        near = (s.outline[k] - mid).norm() < 2.0;
      EXPECT_TRUE(near) << "strand " << s.id << " skeleton leaves its outline at "
                        << mid.transpose();
    }
    EXPECT_NO_THROW(s.mesh.validate("strand mesh"));
  }
  for (int id : regions.labels()) EXPECT_TRUE(seen.count(id)) << "region " << id << " lost";
  EXPECT_EQ(m.background.width(), m.width);
  EXPECT_FALSE(run.contact_sheet.empty());
}

TEST(ModelStage, AnnotatedCaseBuildsWritesAndReadsBack) {
  const AnnotatedCase c = read_annotated_case(HAIR25D_TEST_DATA_DIR "/annotated/case1");
  const ModelRun run = build_model(c.image, c.regions, relations_of(c), {}, c.head_center);
  expect_consistent(run, c.regions);
  // Depth follows the relations between different strands.
  std::map<int, int> depth_of_region;
  for (const Strand& s : run.model.strands)
    for (int r : s.regions) depth_of_region[r] = s.depth;
  int agree = 0, judged = 0;
  for (const AnnotatedPair& p : c.pairs) {
    if (p.relation == Relation::kEqual || depth_of_region[p.a] == depth_of_region[p.b]) continue;
    ++judged;
    agree += (p.relation == Relation::kBelow) == (depth_of_region[p.a] < depth_of_region[p.b]);
  }
  EXPECT_GE(agree, 0.9 * judged);

  const fs::path dir = scratch("case1");
  write_model_run(dir, run);
  EXPECT_TRUE(fs::exists(dir / "contact_sheet.png"));
  const HairModel back = read_model(dir);
  ASSERT_EQ(back.strands.size(), run.model.strands.size());
  for (std::size_t i = 0; i < back.strands.size(); ++i) {
    EXPECT_EQ(back.strands[i].regions, run.model.strands[i].regions);
    EXPECT_EQ(back.strands[i].depth, run.model.strands[i].depth);
    EXPECT_EQ(back.strands[i].skeleton.parent, run.model.strands[i].skeleton.parent);
    EXPECT_EQ(back.strands[i].mesh.triangle_count(), run.model.strands[i].mesh.triangle_count());
  }
  EXPECT_EQ(back.background, run.model.background);
  fs::remove_all(dir);
}

#ifdef HAIR25D_HAVE_GENERATOR
// A generated 560 x 400 drawing of ten strands.
AnnotatedCase generated_non_square_case() {
  generator::Options g;
  g.width = 560;
  g.height = 400;
  g.strand_count = 10;
  g.seed = 3;
  return generator::generate_case(g);
}

// Slow to take a skeleton report, as a terminal can be: the silent worker then
// finishes the last strands while the reporting one waits here.
class SlowSkeletonProgress final : public Progress {
 public:
  void report(std::string_view stage, double fraction, std::string_view) override {
    if (stage != "skeleton") return;
    fractions.push_back(fraction);
    if (fraction < 1.0) std::this_thread::sleep_for(std::chrono::milliseconds(700));
  }
  std::vector<double> fractions;
};

TEST(ModelStage, SkeletonProgressEndsAtOneWhicheverWorkerFinishesLast) {
  // Strands of like sizes: the reporting worker's first (the longest) is not
  // the last to finish.
  const AnnotatedCase c = generated_non_square_case();
  ModelOptions options;
  options.threads = 2;
  SlowSkeletonProgress progress;
  const ModelRun run =
      build_model(c.image, c.regions, relations_of(c), {}, c.head_center, options, &progress);
  ASSERT_GT(run.model.strands.size(), 2u);
  ASSERT_FALSE(progress.fractions.empty());
  EXPECT_EQ(progress.fractions.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(progress.fractions.begin(), progress.fractions.end()));
}
#endif

// Every region is in one strand: regions made one by "equal" relations and by
// joins account for the difference, and the summary says both.
TEST(ModelStage, SummaryCountsSameDepthMergesAndJoins) {
  const AnnotatedCase c = read_annotated_case(HAIR25D_TEST_DATA_DIR "/annotated/case1");
  const std::vector<RegionRelation> relations = relations_of(c);
  ASSERT_TRUE(std::any_of(relations.begin(), relations.end(),
                          [](const RegionRelation& r) { return r.relation == Relation::kEqual; }));
  const ModelRun run = build_model(c.image, c.regions, relations, {}, c.head_center);
  std::set<int> regions;
  for (int y = 0; y < c.regions.height(); ++y)
    for (int x = 0; x < c.regions.width(); ++x)
      if (c.regions.at(x, y) > 0) regions.insert(c.regions.at(x, y));
  EXPECT_GT(run.completion.equal_merges, 0);
  EXPECT_EQ(run.completion.equal_merges + run.completion.joins,
            static_cast<int>(regions.size() - run.model.strands.size()));
  EXPECT_NE(run.summary.find(std::to_string(run.completion.equal_merges) + " same-depth merges"),
            std::string::npos)
      << run.summary;
}

// The contact sheet's panels: the drawing as it is (top left), completed
// areas tinted light blue (top right), depth colours (bottom left), skeletons
// (bottom right); panels are the hair's box shrunk by a whole factor.
TEST(ModelStage, ContactSheetShowsTheCompletedAreasInLightBlue) {
  const AnnotatedCase c = read_annotated_case(HAIR25D_TEST_DATA_DIR "/annotated/case1");
  const ModelRun run = build_model(c.image, c.regions, relations_of(c), {}, c.head_center);
  const int side = 200;
  const Image sheet = render_contact_sheet(run, side);
  const auto [bx, by, bw, bh] = contact_sheet_box(run);
  const int factor = (std::max(bw, bh) + side - 1) / side;
  const int pw = (bw + factor - 1) / factor;
  const int ph = (bh + factor - 1) / factor;
  ASSERT_EQ(sheet.width(), 2 * pw + 24);
  ASSERT_EQ(sheet.height(), 2 * ph + 24);
  // Panel pixels whose every source pixel is completed (a hidden part) are
  // bluer in the completion panel than in the drawing panel; pixels with no
  // strand at all are the same in both.
  LabelMap completed(c.image.width(), c.image.height()), any(c.image.width(), c.image.height());
  for (std::size_t i = 0; i < run.strands.size(); ++i) {
    const LabelMap& mask = run.strands[i].mask;
    const Eigen::Vector2i o = run.model.strands[i].texture_origin;
    for (int y = 0; y < mask.height(); ++y)
      for (int x = 0; x < mask.width(); ++x) {
        if (mask.at(x, y) == 2) completed.at(x + o.x(), y + o.y()) = 1;
        if (mask.at(x, y) != 0) any.at(x + o.x(), y + o.y()) = 1;
      }
  }
  int tinted = 0, all_completed = 0, untouched = 0, empty = 0;
  for (int py = 0; py < ph - 1; ++py)
    for (int px = 0; px < pw - 1; ++px) {
      int n_completed = 0, n_any = 0;
      bool background_is_drawing = true;
      for (int y = by + py * factor; y < by + (py + 1) * factor; ++y)
        for (int x = bx + px * factor; x < bx + (px + 1) * factor; ++x) {
          n_completed += completed.at(x, y), n_any += any.at(x, y);
          background_is_drawing &= run.model.background.at(x, y) == c.image.at(x, y);
        }
      const Rgba drawn = sheet.at(8 + px, 8 + py);
      const Rgba shown = sheet.at(16 + pw + px, 8 + py);
      if (n_completed == factor * factor) {
        ++all_completed;
        tinted += shown.b > shown.r && shown.b >= 150;
      } else if (n_any == 0 && background_is_drawing) {
        ++empty;
        untouched += shown == drawn;
      }
    }
  ASSERT_GT(all_completed, 20);
  EXPECT_GE(tinted, 0.95 * all_completed);
  ASSERT_GT(empty, 100);
  EXPECT_EQ(untouched, empty);
}

// The sheet shows the hair, not the whole drawing: the box of the strands'
// textures and skeletons with a margin, clipped to the drawing.
TEST(ModelStage, ContactSheetBoxIsTheHairWithAMargin) {
  ModelRun run;
  run.model.width = 400;
  run.model.height = 300;
  run.model.image = Image(400, 300, Rgba{255, 255, 255, 255});
  EXPECT_EQ(contact_sheet_box(run), (std::array<int, 4>{0, 0, 400, 300}));
  Strand s;
  s.texture = Image(20, 10, Rgba{10, 20, 30, 255});
  s.texture_origin = {100, 50};
  s.skeleton.nodes = {Vec2(105, 55), Vec2(130, 58)};
  s.skeleton.parent = {-1, 0};
  run.model.strands.push_back(s);
  // Texture 100..120 × 50..60 and a node at x = 130: longer side 30, margin 16.
  EXPECT_EQ(contact_sheet_box(run), (std::array<int, 4>{84, 34, 62, 42}));
  // Near the corner the margin is clipped to the drawing.
  run.model.strands[0].texture_origin = {0, 290};
  run.model.strands[0].skeleton.nodes = {Vec2(5, 295), Vec2(15, 299)};
  EXPECT_EQ(contact_sheet_box(run), (std::array<int, 4>{0, 274, 36, 26}));
  const Image sheet = render_contact_sheet(run, 9);
  // 36 × 26 shrunk by 4: 9 × 7 panels, four of them with 8 px gaps.
  EXPECT_EQ(sheet.width(), 2 * 9 + 24);
  EXPECT_EQ(sheet.height(), 2 * 7 + 24);
  EXPECT_THROW(render_contact_sheet(run, 0), Error);
}

TEST(ModelStage, WriteModelRunPutsTheContactSheetInsideTheAtomicFolder) {
  const fs::path dir = scratch("atomic");
  // A 40 x 30 model of one background colour, with a contact sheet.
  const auto bare_run = [](Rgba background, Image sheet) {
    ModelRun r;
    r.model.width = 40;
    r.model.height = 30;
    r.model.background = Image(40, 30, background);
    r.contact_sheet = std::move(sheet);
    return r;
  };
  write_model_run(dir, bare_run({1, 2, 3, 255}, Image(3, 2, Rgba{1, 2, 3, 255})));
  // A file of the earlier output that the new one does not write.
  { std::ofstream(dir / "stale.txt") << "old run"; }
  const ModelRun run = bare_run({9, 8, 7, 255}, Image(50, 20, Rgba{200, 100, 50, 255}));
  write_model_run(dir, run);
  // The whole folder was replaced in one step: nothing of the old one is left.
  EXPECT_FALSE(fs::exists(dir / "stale.txt"));
  EXPECT_EQ(load_image(dir / "contact_sheet.png"), run.contact_sheet);
  EXPECT_EQ(read_model(dir).background, run.model.background);
  for (const auto& e : fs::directory_iterator(dir.parent_path()))
    EXPECT_EQ(e.path().filename().string().find("." + dir.filename().string()), std::string::npos)
        << "temporary left behind: " << e.path();
  // A model that cannot be written leaves the previous folder as it was.
  ModelRun bad = run;
  bad.model.width = 0;
  bad.contact_sheet = Image(5, 5, Rgba{0, 0, 0, 255});
  EXPECT_THROW(write_model_run(dir, bad), Error);
  EXPECT_EQ(load_image(dir / "contact_sheet.png"), run.contact_sheet);
  EXPECT_THROW(write_model_into(dir / "missing", run.model), Error);
  fs::remove_all(dir);
}

TEST(ModelStage, EndToEndWithPredictedRelationsOnAnnotatedCases) {
  // Layering predicts the relations; joins are scored against the annotation.
  completion::test::PairScore total;
  ModelOptions options;
  options.completion.inpaint_strands = false;
  options.completion.inpaint_background = false;
  for (const fs::path& folder : find_annotated_cases(HAIR25D_TEST_DATA_DIR "/annotated")) {
    const AnnotatedCase c = read_annotated_case(folder);
    const ModelRun run = run_model(c.image, c.regions, c.head_center, options);
    expect_consistent(run, c.regions);
    completion::Result scored;
    for (const Strand& s : run.model.strands) {
      completion::CompletedStrand cs;
      cs.regions = s.regions;
      scored.strands.push_back(cs);
    }
    const completion::test::PairScore s = completion::test::score_pairs(c, scored);
    std::printf("%s (predicted relations): precision %.3f recall %.3f\n", c.name.c_str(),
                s.precision(), s.recall());
    total.predicted += s.predicted;
    total.truth += s.truth;
    total.correct += s.correct;
  }
  std::printf("all (predicted relations): precision %.3f recall %.3f\n", total.precision(),
              total.recall());
  EXPECT_GE(total.precision(), 0.6);
  EXPECT_GE(total.recall(), 0.4);
}

#ifdef HAIR25D_HAVE_GENERATOR
TEST(ModelStage, GeneratedNonSquareDrawing) {
  const AnnotatedCase c = generated_non_square_case();
  const ModelRun run = build_model(c.image, c.regions, relations_of(c), {}, c.head_center);
  expect_consistent(run, c.regions);
  EXPECT_EQ(run.model.width, 560);
  EXPECT_EQ(run.model.height, 400);
}

// A batch run must give the same clip for the same drawing: the model folder
// is the same byte for byte, whatever the worker threads and the heap did.
TEST(ModelStage, SameDrawingGivesTheSameModelFolder) {
  // 40 strands on 1024 x 1024: one completed strand folds over itself, whose
  // mesh came out different from run to run (CGAL's simplification order).
  generator::Options g;
  g.width = 1024;
  g.height = 1024;
  g.strand_count = 40;
  g.seed = 7;
  const AnnotatedCase c = generator::generate_case(g);
  std::vector<fs::path> dirs;
  std::vector<std::unique_ptr<char[]>> clutter;
  for (int run = 0; run < 2; ++run) {
    for (int k = 0; k < 50 * run; ++k)
      clutter.push_back(std::make_unique<char[]>(16 + (k * 7919) % 200000));
    for (std::size_t k = run % 2; k < clutter.size(); k += 3) clutter[k].reset();
    dirs.push_back(scratch("same" + std::to_string(run)));
    write_model_run(dirs.back(), run_model(c.image, c.regions, c.head_center));
  }
  auto bytes = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  int files = 0;
  for (const auto& e : fs::recursive_directory_iterator(dirs[0])) {
    if (!e.is_regular_file()) continue;
    ++files;
    const fs::path rel = fs::relative(e.path(), dirs[0]);
    for (int run = 1; run < 2; ++run)
      EXPECT_TRUE(bytes(e.path()) == bytes(dirs[run] / rel)) << rel << " differs in run " << run;
  }
  EXPECT_GT(files, 3);
  for (const fs::path& d : dirs) fs::remove_all(d);
}
#endif

TEST(ModelStage, SingleRegionAndBadInput) {
  Image img(120, 80, Rgba{240, 240, 240, 255});
  LabelMap regions(120, 80);
  for (int y = 20; y < 40; ++y)
    for (int x = 10; x < 100; ++x) regions.at(x, y) = 5, img.at(x, y) = {200, 150, 90, 255};
  // One region: layering has nothing to order, the model still has its strand.
  const ModelRun run = run_model(img, regions, std::nullopt);
  ASSERT_EQ(run.model.strands.size(), 1u);
  expect_consistent(run, regions);
  EXPECT_THROW(run_model(img, LabelMap(10, 10), std::nullopt), Error);
  EXPECT_THROW(run_model(img, LabelMap(120, 80), std::nullopt), Error);  // no hair at all
  ModelOptions bad;
  bad.cover_reach = -1;
  EXPECT_THROW(run_model(img, regions, std::nullopt, bad), Error);
}

#ifdef HAIR25D_CLI
TEST(ModelCommand, WritesAModelFolderThatReadsBack) {
  const fs::path dir = scratch("cli");
  const std::string data = HAIR25D_TEST_DATA_DIR "/annotated/case5/";
  const std::string cmd = std::string("\"") + HAIR25D_CLI + "\" --quiet model \"" + data +
                          "image.png\" --regions \"" + data +
                          "regions.png\" --head 461.5 614.8 -o \"" + dir.string() + "\"";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  const HairModel m = read_model(dir);
  EXPECT_EQ(m.width, 896);
  EXPECT_EQ(m.height, 1162);
  EXPECT_GE(m.strands.size(), 5u);
  EXPECT_TRUE(fs::exists(dir / "contact_sheet.png"));
  EXPECT_FALSE(load_image(dir / "contact_sheet.png").empty());
  // Bad input: a missing image is exit status 1, not a crash.
  const std::string bad = std::string("\"") + HAIR25D_CLI +
                          "\" --quiet model /nonexistent.png --regions \"" + data +
                          "regions.png\" -o \"" + dir.string() + "\" 2>/dev/null";
  const int status = std::system(bad.c_str());
  EXPECT_EQ(WEXITSTATUS(status), 1);
  fs::remove_all(dir);
}
#endif

}  // namespace
}  // namespace hair25d::pipeline
