#include "hair25d/pipeline/model_stage.h"

#include <algorithm>
#include <atomic>
#include <future>
#include <set>
#include <sstream>

#include "hair25d/core/atomic_file.h"
#include "hair25d/core/error.h"
#include "hair25d/core/image_io.h"
#include "hair25d/core/model_io.h"
#include "hair25d/layering/depth_order.h"
#include "hair25d/pipeline/segment_stage.h"
#include "strand_order.h"

namespace hair25d::pipeline {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Region depths for every region: the given ones, the rest from the relations.
std::map<int, int> complete_depths(const LabelMap& regions,
                                   const std::vector<RegionRelation>& relations,
                                   const std::map<int, int>& given) {
  const std::vector<int> ids = regions.labels();
  bool all = true;
  for (int id : ids) all = all && given.count(id);
  if (all) return given;
  std::vector<RegionRelation> known;
  const std::set<int> present(ids.begin(), ids.end());
  for (const RegionRelation& r : relations)
    if (present.count(r.a) && present.count(r.b)) known.push_back(r);
  return layering::order_regions(ids, known).depth;
}

}  // namespace

bool ModelOptions::is_valid(std::string* error) const {
  if (!layering.is_valid(error) || !completion.is_valid(error) || !skeleton.is_valid(error) ||
      !mesh.is_valid(error))
    return false;
  if (threads < 1 || threads > 64) {
    if (error != nullptr)
      *error =
          "pipeline::ModelOptions::threads = " + std::to_string(threads) + "; must be in [1, 64]";
    return false;
  }
  if (cover_reach < 0 || cover_reach > 32) {
    if (error != nullptr)
      *error = "pipeline::ModelOptions::cover_reach = " + std::to_string(cover_reach) +
               "; must be in [0, 32]";
    return false;
  }
  return true;
}

ModelRun build_model(const Image& image, const LabelMap& regions,
                     const std::vector<RegionRelation>& relations, const std::map<int, int>& depth,
                     std::optional<Vec2> head_center, const ModelOptions& options,
                     Progress* progress) {
  std::string why;
  if (!options.is_valid(&why)) throw Error(why);
  ModelRun run;
  auto start = Clock::now();
  completion::Input in;
  in.image = &image;
  in.regions = &regions;
  in.relations = relations;
  in.head_center = head_center;
  run.completion = completion::complete_strands(in, options.completion, progress);
  run.seconds["completion"] = since(start);

  start = Clock::now();
  const std::map<int, int> region_depth = complete_depths(regions, relations, depth);
  std::vector<completion::CompletedStrand> done = std::move(run.completion.strands);
  run.completion.strands.clear();
  // Strand depths come from the relations between strands, not from their
  // pieces' region depths: a strand joined from pieces may lie above another
  // strand through one piece and below it through another (strand_order.h).
  std::vector<std::vector<int>> strand_regions;
  for (const completion::CompletedStrand& c : done) strand_regions.push_back(c.regions);
  std::vector<RegionRelation> model_relations = relations;
  const StrandOrder strand_order = order_strands(strand_regions, region_depth, &model_relations);
  const std::vector<int>& key = strand_order.depth;
  std::vector<int> order(done.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return key[a] != key[b] ? key[a] < key[b] : done[a].regions.front() < done[b].regions.front();
  });

  HairModel& m = run.model;
  m.width = image.width();
  m.height = image.height();
  m.image = image;
  m.background = std::move(run.completion.background);
  m.head_center = run.completion.head_center;
  m.relations = std::move(model_relations);
  run.regions = std::move(run.completion.regions);
  std::map<int, int> strand_depth_of_region;
  for (int index : order)
    for (int r : done[index].regions) strand_depth_of_region[r] = key[index];

  std::vector<std::optional<Vec2>> root_hints;
  int next = 0;
  for (int index : order) {
    completion::CompletedStrand& c = done[index];
    Strand s;
    s.id = ++next;
    s.name = "strand " + std::to_string(s.id);
    s.regions = c.regions;
    s.depth = key[index];
    s.outline = c.outline;
    s.texture = std::move(c.texture);
    s.texture_origin = c.origin;
    StrandReport info;
    info.mask = std::move(c.mask);
    info.body = std::move(c.body);
    root_hints.push_back(c.root_hint ? c.root_hint : m.head_center);
    m.strands.push_back(std::move(s));
    run.strands.push_back(std::move(info));
  }

  // Skeleton and mesh of one strand; strands, and a strand's skeleton and
  // mesh, are independent: each is a job of its own, so that the largest
  // strand's two do not run one after the other while the other worker idles.
  std::vector<std::string> skeleton_problem(m.strands.size()), mesh_problem(m.strands.size());
  const auto make_skeleton = [&](std::size_t i) {
    Strand& s = m.strands[i];
    StrandReport& info = run.strands[i];
    // The skeleton follows the body: the rim's spurs along lines and at
    // junctions would give it branches that leave the strand.
    const Polyline& shape = info.body.size() >= 3 ? info.body : s.outline;
    if (shape.size() >= 3) {
      // A corner under a strand drawn above is hidden: not a tip (§6). It is
      // under it when its own pixel is that strand's (a visible region or a
      // completed hidden part), or most of the disc round it is: a strand
      // merely lying alongside, sharing or nearing the outline, leaves a
      // visible tip a tip (before, any front pixel within the reach hid it:
      // wikipe-tan's left side lock and lucy's lock lost their skeletons).
      const auto in_front = [&](int x, int y) {
        if (!run.regions.contains(x, y)) return false;
        const auto it = strand_depth_of_region.find(run.regions.at(x, y));
        if (it != strand_depth_of_region.end() && it->second > s.depth) return true;
        for (std::size_t j = 0; j < m.strands.size(); ++j) {
          if (m.strands[j].depth <= s.depth) continue;
          const LabelMap& mask = run.strands[j].mask;
          const int mx = x - m.strands[j].texture_origin.x();
          const int my = y - m.strands[j].texture_origin.y();
          if (mask.contains(mx, my) && mask.at(mx, my) == 2) return true;
        }
        return false;
      };
      std::vector<bool> covered(shape.size(), false);
      const int reach = options.cover_reach;
      for (std::size_t v = 0; v < shape.size(); ++v) {
        const int cx = static_cast<int>(shape[v].x()), cy = static_cast<int>(shape[v].y());
        if (in_front(cx, cy)) {
          covered[v] = true;
          continue;
        }
        int disc = 0, front = 0;
        for (int dy = -reach; dy <= reach; ++dy)
          for (int dx = -reach; dx <= reach; ++dx) {
            if (dx * dx + dy * dy > reach * reach) continue;
            ++disc;
            front += in_front(cx + dx, cy + dy);
          }
        covered[v] = 2 * front > disc;
      }
      try {
        skeleton::Input sk;
        sk.outline = shape;
        sk.covered = std::move(covered);
        sk.root_hint = root_hints[i];
        const skeleton::Result r = skeleton::build_skeleton(sk, options.skeleton);
        s.skeleton = r.skeleton;
        info.skeleton = r.status;
      } catch (const Error& e) {
        skeleton_problem[i] = std::string("skeleton: ") + e.what();
      }
    } else {
      skeleton_problem[i] = "outline has fewer than 3 points";
    }
    if (s.skeleton.nodes.empty()) {
      // Still a usable strand: one fixed node where its pixels are.
      Vec2 centre(0, 0);
      int n = 0;
      for (int y = 0; y < info.mask.height(); ++y)
        for (int x = 0; x < info.mask.width(); ++x)
          if (info.mask.at(x, y))
            centre += Vec2(x + s.texture_origin.x() + 0.5, y + s.texture_origin.y() + 0.5), ++n;
      if (n > 0) {
        s.skeleton.nodes = {centre / n};
        s.skeleton.parent = {-1};
      }
    }
  };
  const auto make_mesh = [&](std::size_t i) {
    Strand& s = m.strands[i];
    if (s.outline.size() < 3) return;
    try {
      const skeleton::MeshResult r = skeleton::mesh_strand(s.outline, options.mesh);
      s.mesh = r.mesh;
      run.strands[i].mesh = r.status;
    } catch (const Error& e) {
      mesh_problem[i] = std::string("mesh: ") + e.what();
    }
  };
  const std::size_t count = m.strands.size();
  // Job 2i is strand i's skeleton, 2i + 1 its mesh.
  const auto job = [&](std::size_t k) { k % 2 == 0 ? make_skeleton(k / 2) : make_mesh(k / 2); };
  if (options.threads > 1 && count > 0) {
    // Two workers each take the next job, longest outline first, so that one
    // large strand does not leave the other worker idle at the end.
    std::vector<std::size_t> work(2 * count);
    for (std::size_t k = 0; k < work.size(); ++k) work[k] = k;
    std::stable_sort(work.begin(), work.end(), [&](std::size_t a, std::size_t b) {
      return m.strands[a / 2].outline.size() > m.strands[b / 2].outline.size();
    });
    std::atomic<std::size_t> next_job{0};
    std::atomic<std::size_t> finished{0};
    std::size_t reported = 0;  // by the reporting worker only
    const auto worker = [&](bool reports) {
      for (std::size_t k = next_job++; k < work.size(); k = next_job++) {
        job(work[k]);
        const std::size_t n = ++finished;
        if (reports) report(progress, "skeleton", static_cast<double>(reported = n) / work.size());
      }
    };
    auto other = std::async(std::launch::async, worker, false);
    worker(true);
    other.get();
    // The silent worker may finish the last job: the stage still ends at 100%.
    if (reported != work.size()) report(progress, "skeleton", 1.0);
  } else {
    for (std::size_t i = 0; i < count; ++i) {
      make_skeleton(i);
      make_mesh(i);
      report(progress, "skeleton", static_cast<double>(i + 1) / count);
    }
  }
  for (std::size_t i = 0; i < count; ++i) {
    std::string& problem = run.strands[i].problem;
    problem = skeleton_problem[i];
    if (!mesh_problem[i].empty()) problem += (problem.empty() ? "" : "; ") + mesh_problem[i];
  }
  run.seconds["skeleton"] = since(start);

  start = Clock::now();
  run.contact_sheet = render_contact_sheet(run);
  run.seconds["contact_sheet"] = since(start);
  std::ostringstream summary;
  int problems = 0;
  for (const StrandReport& r : run.strands) problems += !r.problem.empty();
  summary << m.strands.size() << " strands (" << run.completion.summary << ")";
  if (problems > 0) summary << "; " << problems << " strands without skeleton or mesh";
  if (strand_order.overridden > 0)
    summary << "; " << strand_order.overridden
            << " region relations overridden by the strands' drawing order";
  run.summary = summary.str();
  return run;
}

ModelRun run_model(const Image& image, const LabelMap& regions, std::optional<Vec2> head_center,
                   const ModelOptions& options, Progress* progress) {
  std::string why;
  if (!options.is_valid(&why)) throw Error(why);
  if (regions.labels().empty())
    throw Error("model: the regions hold no hair region (every label is 0); nothing to model");
  // Before layering: too many regions or scattered pieces would run for hours.
  check_label_map(regions, "model: the region map");
  const auto start = Clock::now();
  std::vector<RegionRelation> relations;
  std::map<int, int> depth;
  std::string layering_note;
  try {
    layering::Result l = layering::layer_regions(image, regions, options.layering, progress);
    relations = std::move(l.relations);
    depth = std::move(l.depth);
  } catch (const Error& e) {
    // Too few regions to layer (one strand, say) is not a reason to stop:
    // completion then has no occluders to complete under.
    layering_note = std::string("; layering skipped: ") + e.what();
  }
  const double layering_seconds = since(start);
  ModelRun run = build_model(image, regions, relations, depth, head_center, options, progress);
  run.seconds["layering"] = layering_seconds;
  run.summary += layering_note;
  return run;
}

ModelRun run_model(const Image& image, const Strokes* strokes, const ModelOptions& options,
                   Progress* progress) {
  const auto start = Clock::now();
  const SegmentRun seg = run_segment(image, strokes, progress, false);
  const double segment_seconds = since(start);
  ModelRun run =
      run_model(image, seg.regions, strokes != nullptr ? strokes->head_center : std::nullopt,
                options, progress);
  run.seconds["segment"] = segment_seconds;
  return run;
}

void write_model_run(const std::filesystem::path& folder, const ModelRun& run) {
  // The contact sheet goes in before the rename: the folder is whole when it appears.
  write_folder_atomically(
      folder,
      [&](const std::filesystem::path& tmp) {
        // Encoded beside the model's own files (core encodes those on two threads).
        auto sheet = std::async(std::launch::async, [&] {
          if (!run.contact_sheet.empty()) save_image(tmp / "contact_sheet.png", run.contact_sheet);
        });
        write_model_into(tmp, run.model);
        sheet.get();
      },
      "model");
}

void check_model_folder(const std::filesystem::path& folder, const std::string& what) {
  std::vector<std::string> names = model_folder_names();
  names.push_back("contact_sheet.png");
  check_output_folder(folder, what, names, "model");
}

}  // namespace hair25d::pipeline
