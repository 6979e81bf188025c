// Case-1 join accuracy of completion (paper §5.1) on annotated cases or on
// generated drawings: precision / recall of the region pairs put into one
// strand and the mean IoU of completed strands with their whole masks, with
// the relations of the annotation or predicted by the layering stage.
// Prints one line per case and the total; the figures in docs/completion.md.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <functional>
#include <map>
#include <set>
#include <string>

#include "../../tests/completion/annotated_eval.h"
#include "../../tests/completion/join_census.h"
#include "case_relations.h"
#include "eval_joins_overlay.h"
#include "hair25d/core/annotation.h"
#include "hair25d/generator/generator.h"
#include "join_upper_bound.h"
#include "relation_gap.h"
#ifdef HAIR25D_HAVE_PIPELINE
#include "hair25d/pipeline/joint_layering.h"
#endif

namespace {

using namespace hair25d;

struct Total {
  completion::test::PairScore pairs;
  double iou_sum = 0.0;
  int strands = 0;
  completion::test::UpperBound bound;
  // Joins refused by Options::strand_paint: right (the two regions are of
  // two strands) and wrong (of one).
  int refused_right = 0, refused_wrong = 0;
  // --census: lost links (and their pairs) by class, then by the drawing's shading.
  std::map<std::string, std::map<std::string, std::pair<int, int>>> census;
  // --census: wrong merges (links and pairs) by chosen case-1 joins and by other passes.
  std::pair<int, int> wrong_chosen{0, 0}, wrong_other{0, 0};
};

// --census: one line per lost link, counted in `total`.
void print_census(const AnnotatedCase& c, const completion::Result& r, const std::string& name,
                  const std::string& kind, Total* total) {
  for (const completion::test::LostLink& l : completion::test::lost_links(c, r)) {
    const std::string cls = completion::test::census_class(l);
    std::pair<int, int>& n = total->census[cls][kind];
    n.first += 1, n.second += l.pairs;
    std::printf("%s: lost link %d-%d (strand %d, %d pairs): %s", name.c_str(), l.region_a,
                l.region_b, l.strand, l.pairs, cls.c_str());
    if (l.best)
      std::printf(", cost %.2f, angle %.0f, p %.2f, cover %.2f", l.best->hand_cost,
                  l.best->angle_deg, l.best->probability, l.best->cover);
    if (l.best && l.best->cover >= 0 && l.best->cover < 1)
      std::printf(" (holes: background %.2f, below %.2f, sibling %.2f, other %.2f)",
                  l.best->hole_background, l.best->hole_below, l.best->hole_sibling,
                  l.best->hole_other);
    if (l.best && l.best->stage == completion::JoinStage::kAtomTaken)
      std::printf(", taken by %d-%d", l.best->rival_a, l.best->rival_b);
    std::printf("\n");
  }
}

// --census: the wrong merges. Within each predicted strand, its regions'
// true strands are linked first by the case-1 joins chosen across them
// (each printed with its trace); what stays apart came by another pass
// (equals, bank, mass, path, face or seam joins), printed with its pairs.
void print_wrong_merges(const AnnotatedCase& c, const completion::Result& r,
                        const std::string& name, Total* total) {
  std::map<int, int> truth;
  for (const AnnotatedRegion& reg : c.region_list) truth[reg.id] = reg.strand;
  for (const completion::CompletedStrand& s : r.strands) {
    std::map<int, int> count;  // regions by true strand
    for (int id : s.regions)
      if (truth.count(id)) ++count[truth[id]];
    if (count.size() < 2) continue;
    std::map<int, int> parent, size;
    for (const auto& [t, n] : count) parent[t] = t, size[t] = n;
    std::function<int(int)> find = [&](int g) {
      return parent[g] == g ? g : parent[g] = find(parent[g]);
    };
    const std::set<int> in(s.regions.begin(), s.regions.end());
    for (const completion::JoinTrace& t : r.join_trace) {
      if (t.stage != completion::JoinStage::kChosen) continue;
      if (!in.count(t.region_a) || !in.count(t.region_b)) continue;
      const int a = find(truth[t.region_a]), b = find(truth[t.region_b]);
      if (a == b) continue;
      const int pairs = size[a] * size[b];
      parent[a] = b, size[b] += size[a];
      total->wrong_chosen.first += 1, total->wrong_chosen.second += pairs;
      std::printf("%s: wrong join %d-%d (%d pairs): cost %.2f, angle %.0f, p %.2f, cover %.2f\n",
                  name.c_str(), t.region_a, t.region_b, pairs, t.hand_cost, t.angle_deg,
                  t.probability, t.cover);
    }
    std::map<int, std::vector<int>> rest;  // the groups left apart, by their root
    for (const auto& [t, n] : count) rest[find(t)].push_back(t);
    if (rest.size() < 2) continue;
    int pairs = 0, sum = 0;
    for (const auto& [root, ts] : rest) pairs += sum * size[root], sum += size[root];
    total->wrong_other.first += static_cast<int>(rest.size()) - 1;
    total->wrong_other.second += pairs;
    std::printf("%s: wrong merge by another pass (%d pairs):", name.c_str(), pairs);
    for (const auto& [root, ts] : rest) {
      std::printf(" {");
      for (int id : s.regions)
        if (truth.count(id) && find(truth[id]) == root) std::printf(" %d", id);
      std::printf(" }");
    }
    std::printf("\n");
  }
}

void print_census_table(const Total& total) {
  std::set<std::string> kinds;
  for (const auto& [cls, by] : total.census)
    for (const auto& [kind, n] : by) kinds.insert(kind);
  std::printf("census: lost links (pairs) by class");
  for (const std::string& k : kinds) std::printf(" | %s", k.c_str());
  std::printf(" | all\n");
  std::map<std::string, std::pair<int, int>> column;
  for (const auto& [cls, by] : total.census) {
    std::printf("census: %s", cls.c_str());
    std::pair<int, int> all{0, 0};
    for (const std::string& k : kinds) {
      const auto it = by.find(k);
      const std::pair<int, int> n = it == by.end() ? std::pair{0, 0} : it->second;
      std::printf(" | %d (%d)", n.first, n.second);
      all.first += n.first, all.second += n.second;
      column[k].first += n.first, column[k].second += n.second;
    }
    std::printf(" | %d (%d)\n", all.first, all.second);
  }
  std::printf("census: all");
  std::pair<int, int> all{0, 0};
  for (const std::string& k : kinds) {
    std::printf(" | %d (%d)", column[k].first, column[k].second);
    all.first += column[k].first, all.second += column[k].second;
  }
  std::printf(" | %d (%d)\n", all.first, all.second);
}

const char* relation_name(Relation r) {
  return r == Relation::kAbove ? "above" : r == Relation::kBelow ? "below" : "equal";
}

// The predicted relations that disagree with the annotation (or that it
// does not judge), to see which of layering's errors a lost join follows.
void print_relation_errors(const AnnotatedCase& c, const std::vector<RegionRelation>& predicted,
                           const std::string& name) {
  std::map<std::pair<int, int>, Relation> truth;
  auto flip = [](Relation r) {
    return r == Relation::kAbove ? Relation::kBelow : r == Relation::kBelow ? Relation::kAbove : r;
  };
  for (const AnnotatedPair& p : c.pairs) {
    truth[{p.a, p.b}] = p.relation;
    truth[{p.b, p.a}] = flip(p.relation);
  }
  for (const RegionRelation& r : predicted) {
    auto it = truth.find({r.a, r.b});
    if (it != truth.end() && it->second == r.relation) continue;
    std::printf("%s: relation %d %s %d (score %.2f), annotated %s\n", name.c_str(), r.a,
                relation_name(r.relation), r.b, r.score,
                it == truth.end() ? "not judged" : relation_name(it->second));
  }
}

void print_bound(const std::string& name, const completion::test::UpperBound& b) {
  std::printf(
      "%s: upper bound of %d true pairs: through regions above both %d direct, %d chained; "
      "above any piece %d, with the face %d; other pairs linked under both %d of %d\n",
      name.c_str(), b.truth, b.both_direct, b.both_chained, b.strand_chained, b.strand_face_chained,
      b.other_linked, b.other_pairs);
}

// Which relations completion is given.
enum class Relations { kAnnotated, kPredicted, kJoint };

void score(const AnnotatedCase& c, Relations relations, const completion::Options& options,
           const std::string& name, const std::string& overlay, bool bound, std::FILE* csv,
           const std::string& kind, Total* total) {
  completion::Input in = completion::test::input_from_case(c);
  if (relations != Relations::kAnnotated) {
    std::string error;
#ifdef HAIR25D_HAVE_PIPELINE
    if (relations == Relations::kJoint) {
      in.relations.clear();  // a failed layering leaves no relations, not the annotation's
      try {
        in.relations =
            pipeline::layer_with_joins(c.image, c.regions, {}, options).layering.relations;
      } catch (const std::exception& e) {
        error = e.what();
      }
    } else
#endif
      in.relations = completion::test::predicted_relations(c, &error);
    if (!error.empty())
      std::printf("%s: layering failed (%s); no relations\n", name.c_str(), error.c_str());
    else if (!overlay.empty())
      print_relation_errors(c, in.relations, name);
  }
  const completion::Result r = completion::complete_strands(in, options);
  if (bound) {
    std::map<int, int> joined;
    for (std::size_t s = 0; s < r.strands.size(); ++s)
      for (int id : r.strands[s].regions) joined[id] = static_cast<int>(s);
    const completion::test::UpperBound b = completion::test::join_upper_bound(c, csv, &joined);
    print_bound(name, b);
    total->bound.truth += b.truth;
    total->bound.both_direct += b.both_direct;
    total->bound.both_chained += b.both_chained;
    total->bound.strand_chained += b.strand_chained;
    total->bound.strand_face_chained += b.strand_face_chained;
    total->bound.other_pairs += b.other_pairs;
    total->bound.other_linked += b.other_linked;
  }
  const completion::test::PairScore s = completion::test::score_pairs(c, r);
  if (options.trace_joins) {
    print_census(c, r, name, kind, total);
    print_wrong_merges(c, r, name, total);
  }
  if (!r.paint_refusals.empty()) {
    std::map<int, int> strand;
    for (const AnnotatedRegion& reg : c.region_list) strand[reg.id] = reg.strand;
    for (const completion::Result::PaintRefusal& f : r.paint_refusals) {
      const bool right = strand[f.a] != strand[f.b];
      (right ? total->refused_right : total->refused_wrong) += 1;
      std::printf("%s: strand paint refused %d-%d (%s; pieces %d-%d, %s)\n", name.c_str(), f.a, f.b,
                  right ? "right" : "wrong", f.piece_a, f.piece_b,
                  strand[f.piece_a] != strand[f.piece_b] ? "two strands" : "one strand");
    }
  }
  if (!overlay.empty()) {
    std::string file = name;
    for (char& ch : file)
      if (ch == ' ') ch = '_';
    completion::test::write_join_overlay(std::filesystem::path(overlay) / (file + ".png"), c, r,
                                         name);
    // The case itself beside its overlay, to look at its regions and pairs.
    if (name.rfind("seed ", 0) == 0) write_annotated_case(std::filesystem::path(overlay) / file, c);
  }
  const std::vector<double> ious = completion::test::strand_ious(c, r);
  double sum = 0.0;
  for (double v : ious) sum += v;
  std::printf(
      "%s: pairs predicted %d, true %d, correct %d: precision %.3f recall %.3f; "
      "mean strand IoU %.3f over %zu strands\n",
      name.c_str(), s.predicted, s.truth, s.correct, s.precision(), s.recall(),
      ious.empty() ? 0.0 : sum / ious.size(), ious.size());
  total->pairs.predicted += s.predicted;
  total->pairs.truth += s.truth;
  total->pairs.correct += s.correct;
  total->iou_sum += sum;
  total->strands += static_cast<int>(ious.size());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Case-1 join accuracy of completion on annotated or generated cases"};
  std::string overlay, annotated, relations = "annotated", shading = "flat";
  int width = 800, height = 640, strands = 20, seed = 1, count = 4;
  app.add_option("--annotated", annotated, "Folder of annotated cases (else generated ones)");
  app.add_option("--relations", relations,
                 "annotated (the case's pairs), predicted (layering) or joint (layering's "
                 "revised with the joins, pipeline/joint_layering.h)")
      ->check(CLI::IsMember({"annotated", "predicted", "joint"}));
  app.add_option("--width", width, "Generated drawing width")->check(CLI::Range(64, 8192));
  app.add_option("--height", height, "Generated drawing height")->check(CLI::Range(64, 8192));
  app.add_option("--strands", strands, "Generated strands")->check(CLI::Range(1, 400));
  app.add_option("--seed", seed, "First seed")->check(CLI::NonNegativeNumber);
  app.add_option("--count", count, "Generated cases (seeds seed .. seed + count - 1)")
      ->check(CLI::Range(1, 1000));
  app.add_option("--shading", shading, "flat, two-tone, gradient, screentone or mixed (cycles)")
      ->check(CLI::IsMember({"flat", "two-tone", "gradient", "screentone", "mixed"}));
  app.add_option("--overlay", overlay,
                 "Folder for one PNG a case: joins right (green) and wrong (red), the "
                 "annotation's strands missed (thick yellow); wrong and missed pairs printed, "
                 "and with --relations predicted the relations that disagree with the annotation");
  completion::Options options;
  options.inpaint_strands = false;  // colours are not scored
  options.inpaint_background = false;
  app.add_option("--max-join-cost", options.max_join_cost, "completion::Options::max_join_cost");
  app.add_option("--max-join-angle", options.max_join_angle_deg,
                 "completion::Options::max_join_angle_deg");
  app.add_option("--tangent-arm", options.tangent_arm, "completion::Options::tangent_arm");
  app.add_flag("!--no-face-joins", options.face_joins, "no joins across the face");
  app.add_flag("--remote-across-occluder,--no-remote-across-occluder",
               options.remote_across_occluder,
               "completion::Options::remote_across_occluder: no occluder from a remote order "
               "between two pieces of one paint under a common occluder");
  app.add_flag("--continuation-seams", options.continuation_seams,
               "read weak orders between pieces whose sides run on as seams (session 27)");
  app.add_flag("--strand-paint,!--no-strand-paint", options.strand_paint,
               "refuse joins whose strand would hold two pieces painted apart (session 28)");
  app.add_flag("!--no-path-joins", options.path_joins,
               "no joins of back-hair pieces through the regions above both");
  app.add_option("--min-join-coverage", options.min_join_coverage,
                 "completion::Options::min_join_coverage");
  app.add_option("--cover-fringe", options.cover_fringe,
                 "completion::Options::cover_fringe: label-0 pixels this near a region count as "
                 "its own in the cover test");
  app.add_option("--second-partner-p", options.second_partner_p,
                 "completion::Options::second_partner_p: the scorer's least p for a cut's second "
                 "partner (0: never)");
  app.add_option("--cover-fringe-layering-cost", options.cover_fringe_layering_cost,
                 "completion::Options::cover_fringe_layering_cost");
  app.add_option("--face-piece-mass-step", options.face_piece_mass_step,
                 "completion::Options::face_piece_mass_step: on screentone, back-hair passes "
                 "leave apart pieces whose dots step more than this when one runs along the "
                 "face (0: off)");
  app.add_option("--tone-path-landing-share", options.tone_path_landing_share,
                 "completion::Options::tone_path_landing_share: on screentone, tone path joins "
                 "of two front pieces need this many landings per square root of the smaller "
                 "piece's pixels (0: off, the default)");
  app.add_option("--join-arm-shares", options.join_arm_shares,
                 "completion::Options::join_arm_shares: tangent arms (shares of the chord) tried "
                 "where the join patch lies under min_join_coverage, e.g. 0.2 0.33 0.5 0.7")
      ->delimiter(',');
  app.add_option("--corridor-width", options.corridor_width,
                 "completion::Options::corridor_width (share of the narrower cut; 0: none)");
  app.add_option("--corridor-min-probability", options.corridor_min_probability,
                 "completion::Options::corridor_min_probability");
  app.add_flag("--join-scorer,!--no-join-scorer", options.join_scorer.enabled,
               "decide strand joins in the cost band by the learned scorer (join_scorer.h)");
  app.add_option("--scorer-band-low", options.join_scorer.band_low, "JoinScorerOptions::band_low");
  app.add_option("--scorer-band-high", options.join_scorer.band_high,
                 "JoinScorerOptions::band_high");
  app.add_option("--scorer-threshold", options.join_scorer.threshold,
                 "JoinScorerOptions::threshold");
  app.add_option("--scorer-screentone-threshold", options.join_scorer.screentone_threshold,
                 "JoinScorerOptions::screentone_threshold");
  app.add_flag("--scorer-retrained,!--no-scorer-retrained", options.join_scorer.retrained,
               "JoinScorerOptions::retrained: the retrained net off screentone");
  app.add_option("--scorer-retrained-threshold", options.join_scorer.retrained_threshold,
                 "JoinScorerOptions::retrained_threshold");
  app.add_option("--scorer-retrained-shaded-threshold",
                 options.join_scorer.retrained_shaded_threshold,
                 "JoinScorerOptions::retrained_shaded_threshold: the retrained net's bar for the "
                 "band on two-tone and gradient drawings");
  const std::map<std::string, completion::JoinScorerOptions::Ensemble> ensembles{
      {"none", completion::JoinScorerOptions::Ensemble::kNone},
      {"screentone", completion::JoinScorerOptions::Ensemble::kScreentone},
      {"all", completion::JoinScorerOptions::Ensemble::kAll},
      {"each", completion::JoinScorerOptions::Ensemble::kEach}};
  app.add_option("--scorer-ensemble", options.join_scorer.ensemble,
                 "JoinScorerOptions::ensemble: none, screentone, all or each")
      ->transform(CLI::CheckedTransformer(ensembles));
  app.add_option("--scorer-ensemble-threshold", options.join_scorer.ensemble_threshold,
                 "JoinScorerOptions::ensemble_threshold");
  app.add_option("--scorer-paint-ensemble-threshold", options.join_scorer.paint_ensemble_threshold,
                 "JoinScorerOptions::paint_ensemble_threshold");
  app.add_option("--scorer-cel-ensemble-threshold", options.join_scorer.cel_ensemble_threshold,
                 "JoinScorerOptions::cel_ensemble_threshold");
  app.add_option("--scorer-max-angle", options.join_scorer.max_angle_deg,
                 "JoinScorerOptions::max_angle_deg");
  app.add_option("--scorer-wide-threshold", options.join_scorer.wide_threshold,
                 "JoinScorerOptions::wide_threshold");
  app.add_option("--scorer-side-threshold", options.join_scorer.side_threshold,
                 "JoinScorerOptions::side_threshold: side-tangent candidates (1 = off)");
  app.add_option("--scorer-second-partner-threshold", options.join_scorer.second_partner_threshold,
                 "JoinScorerOptions::second_partner_threshold: a cut's second partners judged "
                 "by their own net at this p (1 = off)");
  app.add_option("--scorer-field-cross-max", options.join_scorer.field_cross_max,
                 "JoinScorerOptions::field_cross_max: on gradient drawings a refused candidate "
                 "whose pieces' colour fields predict each other's paint at the cuts within this "
                 "RGB joins last (0 = off)");
  app.add_option("--scorer-field-cross-larger-max", options.join_scorer.field_cross_larger_max,
                 "JoinScorerOptions::field_cross_larger_max: or the larger piece's field alone "
                 "within this RGB (0 = not)");
  app.add_option("--scorer-field-cross-low", options.join_scorer.field_cross_low,
                 "JoinScorerOptions::field_cross_low: the least p of its net for that");
  app.add_option("--scorer-second-partner-last", options.join_scorer.second_partner_last,
                 "JoinScorerOptions::second_partner_last: the net's second partners join after "
                 "every other candidate (1) or at their own place in the matching (0)");
  app.add_flag("--scorer-second-partner-all-shadings",
               options.join_scorer.second_partner_all_shadings,
               "JoinScorerOptions::second_partner_all_shadings: also on flat and screentone "
               "drawings");
  app.add_option("--scorer-cover-refusal-threshold", options.join_scorer.cover_refusal_threshold,
                 "JoinScorerOptions::cover_refusal_threshold: cover refusals' second chances, "
                 "joined at this probability of their own net (1: off)");
  app.add_flag("--scorer-cover-refusal-all-shadings",
               options.join_scorer.cover_refusal_all_shadings,
               "JoinScorerOptions::cover_refusal_all_shadings: also on flat and screentone "
               "drawings");
  app.add_option("--scorer-cover-flat-threshold", options.join_scorer.cover_flat_threshold,
                 "JoinScorerOptions::cover_flat_threshold: cover refusals' second chances on "
                 "flat drawings, joined at this probability of cover_plain_join_scorer (1: off)");
  app.add_option("--scorer-cover-screentone-threshold",
                 options.join_scorer.cover_screentone_threshold,
                 "JoinScorerOptions::cover_screentone_threshold: likewise on screentone "
                 "drawings (1: off)");
  app.add_option("--scorer-angle-refusal-threshold", options.join_scorer.angle_refusal_threshold,
                 "JoinScorerOptions::angle_refusal_threshold: angle refusals' second chances, "
                 "judged by their own net (1 = off)");
  app.add_flag("--scorer-angle-refusal-turned,!--no-scorer-angle-refusal-turned",
               options.join_scorer.angle_refusal_turned,
               "JoinScorerOptions::angle_refusal_turned: also reversed and turned tangents");
  app.add_option("--scorer-second-threshold", options.join_scorer.second_threshold,
                 "JoinScorerOptions::second_threshold: the retrained net's bar for the default "
                 "net's band refusals on flat drawings (1 = off)");
  app.add_option("--scorer-second-low", options.join_scorer.second_low,
                 "JoinScorerOptions::second_low: the band net's least p for a second opinion");
  app.add_option("--scorer-refuse-below", options.join_scorer.refuse_below,
                 "JoinScorerOptions::refuse_below");
  app.add_option("--scorer-veto-low", options.join_scorer.veto_low, "JoinScorerOptions::veto_low");
  app.add_option("--scorer-veto-below", options.join_scorer.veto_below,
                 "JoinScorerOptions::veto_below");
  app.add_option("--scorer-rescue-high", options.join_scorer.rescue_high,
                 "JoinScorerOptions::rescue_high");
  app.add_option("--scorer-rescue-threshold", options.join_scorer.rescue_threshold,
                 "JoinScorerOptions::rescue_threshold");
  app.add_option("--scorer-screentone-veto-below", options.join_scorer.screentone_veto_below,
                 "JoinScorerOptions::screentone_veto_below");
  app.add_option("--scorer-screentone-veto-low", options.join_scorer.screentone_veto_low,
                 "JoinScorerOptions::screentone_veto_low");
  app.add_option("--scorer-screentone-rescue-threshold",
                 options.join_scorer.screentone_rescue_threshold,
                 "JoinScorerOptions::screentone_rescue_threshold");
  app.add_flag("--scorer-screentone-band,!--no-scorer-screentone-band",
               options.join_scorer.screentone_band,
               "JoinScorerOptions::screentone_band: the screentone net judges the band there");
  app.add_flag("--scorer-shaded,!--no-scorer-shaded", options.join_scorer.shaded,
               "JoinScorerOptions::shaded: the shaded net on two-tone and gradient drawings");
  app.add_flag("--scorer-shaded-band,!--no-scorer-shaded-band", options.join_scorer.shaded_band,
               "JoinScorerOptions::shaded_band: the shaded net judges the band there");
  app.add_flag("--scorer-retrained-shaded,!--no-scorer-retrained-shaded",
               options.join_scorer.retrained_shaded,
               "JoinScorerOptions::retrained_shaded: the retrained net judges the band on "
               "two-tone and gradient drawings");
  app.add_option("--scorer-shaded-threshold", options.join_scorer.shaded_threshold,
                 "JoinScorerOptions::shaded_threshold");
  app.add_option("--scorer-shaded-veto-below", options.join_scorer.shaded_veto_below,
                 "JoinScorerOptions::shaded_veto_below");
  app.add_option("--scorer-shaded-rescue-threshold", options.join_scorer.shaded_rescue_threshold,
                 "JoinScorerOptions::shaded_rescue_threshold");
  bool gap = false;
  app.add_flag("--relation-gap", gap,
               "Run each generated case with both relations and print the links the "
               "annotation's make but the layering's lose, by census stage and by what in the "
               "layering's relations differs (relation_gap.h); no figures");
  app.add_flag("--census", options.trace_joins,
               "Name the stage where each lost link of a true strand was stopped "
               "(Options::trace_joins, tests/completion/join_census.h): a line per link and a "
               "table by class and shading");
  bool bound = false;
  app.add_flag("--upper-bound", bound,
               "Also count the true pairs linked through regions lying above them (what any "
               "join under known occluders could find)");
  std::string csv_path;
  app.add_option("--pairs-csv", csv_path,
                 "With --upper-bound: a CSV line per region pair neither above the other "
                 "(features for studying join rules)");
  CLI11_PARSE(app, argc, argv);
  std::FILE* csv = nullptr;
  if (!csv_path.empty() && bound) {
    csv = std::fopen(csv_path.c_str(), "a");
    if (!csv) {
      std::fprintf(stderr, "eval_joins: cannot write %s\n", csv_path.c_str());
      return 1;
    }
  }
  const Relations predicted = relations == "predicted" ? Relations::kPredicted
                              : relations == "joint"   ? Relations::kJoint
                                                       : Relations::kAnnotated;
#ifndef HAIR25D_HAVE_PIPELINE
  if (predicted == Relations::kJoint) {
    std::fprintf(stderr, "eval_joins: --relations joint needs the pipeline library\n");
    return 1;
  }
#endif
  Total total;
  completion::test::GapTotal gap_total;
  try {
    if (!annotated.empty()) {
      for (const auto& folder : find_annotated_cases(annotated)) {
        const AnnotatedCase c = read_annotated_case(folder);
        score(c, predicted, options, c.name, overlay, bound, csv, "annotated", &total);
      }
    } else {
      const generator::Shading kinds[] = {generator::Shading::kFlat, generator::Shading::kTwoTone,
                                          generator::Shading::kGradient,
                                          generator::Shading::kScreentone};
      for (int k = 0; k < count; ++k) {
        generator::Options g;
        g.width = width;
        g.height = height;
        g.strand_count = strands;
        g.seed = static_cast<std::uint64_t>(seed + k);
        g.shading = shading == "mixed"        ? kinds[k % 4]
                    : shading == "two-tone"   ? kinds[1]
                    : shading == "gradient"   ? kinds[2]
                    : shading == "screentone" ? kinds[3]
                                              : kinds[0];
        const char* names[] = {"flat", "two-tone", "gradient", "screentone"};
        const int kind = shading == "mixed"        ? k % 4
                         : shading == "two-tone"   ? 1
                         : shading == "gradient"   ? 2
                         : shading == "screentone" ? 3
                                                   : 0;
        if (gap) {
          completion::test::relation_gap(generator::generate_case(g), options,
                                         "seed " + std::to_string(seed + k), &gap_total);
          continue;
        }
        score(generator::generate_case(g), predicted, options, "seed " + std::to_string(seed + k),
              overlay, bound, csv, names[kind], &total);
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "eval_joins: %s\n", e.what());
    return 1;
  }
  if (gap) {
    completion::test::print_gap_table(gap_total);
    return 0;
  }
  std::printf(
      "all: precision %.3f recall %.3f (pairs predicted %d, true %d, correct %d), "
      "mean strand IoU %.3f\n",
      total.pairs.precision(), total.pairs.recall(), total.pairs.predicted, total.pairs.truth,
      total.pairs.correct, total.strands > 0 ? total.iou_sum / total.strands : 0.0);
  if (options.strand_paint)
    std::printf("strand paint refusals: %d right, %d wrong\n", total.refused_right,
                total.refused_wrong);
  if (bound) print_bound("all", total.bound);
  if (options.trace_joins) {
    print_census_table(total);
    std::printf("census: wrong merges: case-1 joins %d (%d pairs), other passes %d (%d pairs)\n",
                total.wrong_chosen.first, total.wrong_chosen.second, total.wrong_other.first,
                total.wrong_other.second);
  }
  if (csv) std::fclose(csv);
  return 0;
}
