// Which of the layering's relations cost the joins right pairs and add
// wrong ones, against the annotation's relations (session 25, joins50; the
// method of session 22's joins38, docs/completion-record.md). Per generated
// drawing: completion with the annotation's relations (A) and the
// layering's (P); lost = right in A, not in P; added = wrong in P, not in A.
// Each class of the layering's relations that disagrees with the annotation
// is corrected alone (the annotation's relation, as the user's; a pair the
// annotation does not relate dropped) and the lost pairs given back / added
// pairs gone are counted (pairs a correction loses or adds anew are not).
// Equals between two strands are printed one by one with their evidence and
// paint, the true equals of screentone drawings with their tone tests.
// With --seams (session 26, joins52): every touching order of the layering
// with completion's seam tests (one paint, seam geometry and its meeting
// points, x^a: the third region directly above a), whether it overrode a
// measured equal (ov, ev: its EqualEvidence), and the right / wrong pairs
// that uniting its two pieces alone adds (weak orders a seam test could
// take only). Weak ones also print the slices' cue (session 27, joins57,
// strand_continuation.h: cont, the a–b line's length and bend, the median
// widths and slices with both ends seen, each side's fit offset and angle),
// and with --crops DIR those of one paint are written as crops of the
// drawing, a red and b blue.
// With --weak (session 27, joins56): every measured weak order (|score| <
// 2) with the layering's own cues over the pair's common boundaries (the
// boundaries' log-odds before and after Eq. (2)'s couplings, the junction
// ends read and their sectors, the pieces' areas), and the right / wrong
// pairs of the run when it alone is dropped or reversed. --correction says
// how a class is corrected in the default count: the annotation's relation
// as the user's (firm), its direction with the layering's score (weak), or
// the layering's direction made firm (firm_same).
//   diag_relations [--seams [--crops DIR]|--weak] [--correction firm|weak|firm_same]
//                  --shading screentone|mixed|... --seed S --count N
#include <CLI/CLI.hpp>
#include <cstdio>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <set>
#include <string>

#include "../../completion/src/bank_crossings.h"
#include "../../completion/src/context.h"
#include "../../completion/src/join_paint.h"
#include "../../completion/src/measured_relations.h"
#include "../../completion/src/seam_joins.h"
#include "../../completion/src/strand_continuation.h"
#include "../../tests/completion/annotated_eval.h"
#include "case_relations.h"
#include "hair25d/generator/generator.h"
#include "hair25d/layering/layering.h"

using namespace hair25d;
using PairSet = std::set<std::pair<int, int>>;

namespace {

PairSet joined_pairs(const completion::Result& r) {
  PairSet out;
  for (const auto& s : r.strands)
    for (std::size_t i = 0; i < s.regions.size(); ++i)
      for (std::size_t j = i + 1; j < s.regions.size(); ++j)
        out.insert({std::min(s.regions[i], s.regions[j]), std::max(s.regions[i], s.regions[j])});
  return out;
}

Relation flip(Relation r) {
  return r == Relation::kAbove ? Relation::kBelow : r == Relation::kBelow ? Relation::kAbove : r;
}

// What the annotation says of the layering's relation r: no relation,
// equal, the same order, or the order reversed.
const char* truth_class(const std::map<std::pair<int, int>, Relation>& truth,
                        const RegionRelation& r) {
  const auto it = truth.find({r.a, r.b});
  return it == truth.end()                ? "none"
         : it->second == Relation::kEqual ? "equal"
         : it->second == r.relation       ? "order"
                                          : "reversed";
}

// The drawing round a and b, a tinted red and b blue, enlarged twice.
void write_crop(const std::string& path, const Image& image, const LabelMap& labels, int a, int b) {
  cv::Rect box;
  for (int y = 0; y < labels.height(); ++y)
    for (int x = 0; x < labels.width(); ++x)
      if (labels.at(x, y) == a || labels.at(x, y) == b) box |= cv::Rect(x, y, 1, 1);
  box = cv::Rect(box.x - 20, box.y - 20, box.width + 40, box.height + 40) &
        cv::Rect(0, 0, labels.width(), labels.height());
  cv::Mat out(box.height, box.width, CV_8UC3);
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) {
      const int l = labels.at(x + box.x, y + box.y);
      const auto& px = image.at(x + box.x, y + box.y);
      cv::Vec3d c(px.b, px.g, px.r);  // BGR
      if (l == a) c = 0.5 * c + cv::Vec3d(0, 0, 127);
      if (l == b) c = 0.5 * c + cv::Vec3d(127, 0, 0);
      out.at<cv::Vec3b>(y, x) =
          cv::Vec3b(cv::saturate_cast<uchar>(c[0]), cv::saturate_cast<uchar>(c[1]),
                    cv::saturate_cast<uchar>(c[2]));
    }
  cv::resize(out, out, cv::Size(), 2.0, 2.0, cv::INTER_NEAREST);
  cv::imwrite(path, out);
}

struct Tally {
  int relations = 0, back = 0, gone = 0;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"diag"};
  std::string shading = "mixed";
  int seed = 2000, count = 100;
  app.add_option("--seed", seed);
  app.add_option("--count", count);
  app.add_option("--shading", shading);
  bool seams_only = false;
  bool weak_only = false;
  std::string correction = "firm";
  app.add_option("--correction", correction,
                 "how a class is corrected: firm (the annotation's, as the user's), weak (its "
                 "direction, the layering's score), firm_same (the layering's direction, firm)")
      ->check(CLI::IsMember({"firm", "weak", "firm_same"}));
  app.add_flag("--weak", weak_only,
               "print each measured weak order with the layering's cues and what dropping or "
               "reversing it does");
  app.add_flag("--seams", seams_only,
               "print each touching order with its seam tests and what uniting it does");
  std::string crops;
  app.add_option("--crops", crops,
                 "with --seams: write each weak touching order of one paint to this folder, "
                 "its two pieces tinted (red a, blue b)");
  CLI11_PARSE(app, argc, argv);
  completion::Options options;
  options.inpaint_strands = false;
  options.inpaint_background = false;
  const generator::Shading kinds[] = {generator::Shading::kFlat, generator::Shading::kTwoTone,
                                      generator::Shading::kGradient,
                                      generator::Shading::kScreentone};
  std::map<std::string, Tally> tally;
  int lost_total = 0, added_total = 0, none_singly = 0, wrong_left = 0;
  for (int k = 0; k < count; ++k) {
    generator::Options g;
    g.seed = seed + k;
    g.width = 800, g.height = 640, g.strand_count = 20;  // eval_joins' defaults
    g.shading = shading == "mixed"        ? kinds[k % 4]
                : shading == "screentone" ? kinds[3]
                : shading == "flat"       ? kinds[0]
                : shading == "gradient"   ? kinds[2]
                                          : kinds[1];
    const AnnotatedCase c = generator::generate_case(g);
    std::string err;
    const std::vector<RegionRelation> pred = completion::test::predicted_relations(c, &err);
    std::map<int, int> strand;
    for (const auto& reg : c.region_list) strand[reg.id] = reg.strand;
    std::map<std::pair<int, int>, Relation> truth;
    for (const auto& p : c.pairs)
      truth[{p.a, p.b}] = p.relation, truth[{p.b, p.a}] = flip(p.relation);
    auto run = [&](const std::vector<RegionRelation>& rel) {
      completion::Input in = completion::test::input_from_case(c);
      in.relations = rel;
      return joined_pairs(completion::complete_strands(in, options));
    };
    const PairSet A = run(completion::test::relations_from_pairs(c));
    const PairSet P = run(pred);
    PairSet lost, added;
    for (auto p : A)
      if (strand[p.first] == strand[p.second] && !P.count(p)) lost.insert(p);
    for (auto p : P)
      if (strand[p.first] != strand[p.second] && !A.count(p)) added.insert(p);
    lost_total += lost.size();
    added_total += added.size();

    completion::detail::Context ctx;
    ctx.image = &c.image;
    ctx.original = &c.regions;
    ctx.options = &options;
    ctx.labels = completion::assign_outline_pixels(c.image, c.regions, options.outline_reach,
                                                   options.dark_luma);
    completion::detail::describe_regions(ctx);
    PairSet touching;
    const LabelMap& L = ctx.labels;
    for (int y = 0; y < L.height(); ++y)
      for (int x = 0; x < L.width(); ++x) {
        auto add = [&](int a, int b) {
          if (a && b && a != b) touching.insert({std::min(a, b), std::max(a, b)});
        };
        if (x + 1 < L.width()) add(L.at(x, y), L.at(x + 1, y));
        if (y + 1 < L.height()) add(L.at(x, y), L.at(x, y + 1));
      }
    auto interior = [&](int region) {
      const LabelMap& o = c.regions;
      const auto own = [&](int x, int y) { return o.contains(x, y) && o.at(x, y) == region; };
      int n = 0;
      for (int y = 0; y < o.height(); ++y)
        for (int x = 0; x < o.width(); ++x)
          n += own(x, y) && own(x - 2, y) && own(x + 2, y) && own(x, y - 2) && own(x, y + 2);
      return n;
    };
    completion::detail::RegionTones tones(ctx);
    completion::detail::RegionFields fields(ctx);

    if (weak_only) {
      // Each measured weak order (|score| < 2) with the layering's cues over
      // the pair's common boundaries, and the right / wrong pairs of the run
      // when it is dropped (no relation) or reversed.
      const layering::Result lr = layering::layer_regions(c.image, c.regions);
      const std::vector<RegionRelation>& rels = lr.relations;
      int right_p = 0, wrong_p = 0;
      for (auto p : run(rels)) (strand[p.first] == strand[p.second] ? right_p : wrong_p)++;
      for (int i = 0; i < static_cast<int>(rels.size()); ++i) {
        const RegionRelation& r = rels[i];
        if (r.relation == Relation::kEqual || completion::detail::unmeasured(r, touching)) continue;
        if (std::abs(r.score) >= 2.0) continue;
        const bool touch = touching.count({std::min(r.a, r.b), std::max(r.a, r.b)}) > 0;
        const bool one = strand[r.a] == strand[r.b];
        const char* t = truth_class(truth, r);
        // The layering's cues, oriented toward "a above b".
        double total = 0, occl = 0, unary = 0, state = 0, learned = 0, patch = 0, same = 0,
               contrast = 0, colour = 0, sectors = 0, circles = 0;
        int nb = 0, ends = 0, rays3 = 0, rays4 = 0, disagree = 0;
        double area_a = 0, area_b = 0, shared_a = 0, shared_b = 0;
        for (std::size_t k = 0; k < lr.graph.boundaries.size(); ++k) {
          const layering::Boundary& b = lr.graph.boundaries[k];
          if (!((b.left == r.a && b.right == r.b) || (b.left == r.b && b.right == r.a))) continue;
          const layering::BoundaryReport& rep = lr.boundaries[k];
          const double sgn = b.left == r.a ? 1.0 : -1.0;
          ++nb;
          total += rep.length;
          area_a = sgn > 0 ? rep.cues.area_left : rep.cues.area_right;
          area_b = sgn > 0 ? rep.cues.area_right : rep.cues.area_left;
          shared_a = sgn > 0 ? rep.cues.shared_left : rep.cues.shared_right;
          shared_b = sgn > 0 ? rep.cues.shared_right : rep.cues.shared_left;
          if (!rep.occluding) continue;
          occl += rep.length;
          unary += sgn * rep.patch_log_odds * rep.length;
          learned += sgn * rep.learned * rep.length;
          patch += sgn * rep.patch * rep.length;
          state += sgn * rep.state * rep.length;
          same += rep.equal * rep.length;
          contrast += rep.line_contrast * rep.length;
          colour += rep.colour_difference * rep.length;
          if (rep.state != 0 && (rep.patch_log_odds > 0) != (rep.state > 0)) ++disagree;
          for (const layering::EndAngles* e : {&rep.cues.start, &rep.cues.end}) {
            if (!e->used) continue;
            ++ends;
            (e->rays >= 4 ? rays4 : rays3)++;
            sectors += sgn * (e->left - e->right);
            circles += sgn * (e->circle_left - e->circle_right);
          }
        }
        const double w = occl > 0 ? 1.0 / occl : 0.0;
        auto count = [&](const std::vector<RegionRelation>& rel) {
          int right = 0, wrong = 0;
          for (auto p : run(rel)) (strand[p.first] == strand[p.second] ? right : wrong)++;
          return std::pair<int, int>{right - right_p, wrong - wrong_p};
        };
        std::vector<RegionRelation> dropped = rels;
        dropped.erase(dropped.begin() + i);
        const auto d = count(dropped);
        std::vector<RegionRelation> flipped = rels;
        flipped[i].relation = flip(r.relation);
        flipped[i].score = -r.score;
        const auto f = count(flipped);
        std::printf(
            "seed %d weak %d-%d %s %s truth %s score %.3f ov %d ev %s %.2f st %d nb %d len %.0f "
            "occl %.0f unary %.2f learned %.2f patch %.2f state %.2f same %.2f contrast %.0f "
            "colour %.0f disagree %d ends %d r3 %d r4 %d sectors %.2f circles %.2f area %.0f %.0f "
            "shared %.2f %.2f; drop %+d %+d flip %+d %+d\n",
            seed + k, r.a, r.b, touch ? "touch" : "remote", one ? "one" : "two", t, r.score,
            r.overridden,
            !r.equal_evidence        ? "no"
            : r.equal_evidence->open ? "open"
                                     : "occl",
            r.equal_evidence ? r.equal_evidence->log_odds : 0.0, tones.screentone(), nb, total,
            occl, unary * w, learned * w, patch * w, state * w, same * w, contrast * w, colour * w,
            disagree, ends, rays3, rays4, sectors, circles, area_a, area_b, shared_a, shared_b,
            d.first, d.second, f.first, f.second);
      }
      std::fflush(stdout);
      continue;
    }
    if (seams_only) {
      // Each measured touching order, its seam tests (completion.cpp
      // read_relations) and what uniting its pieces (the user's equal) does.
      const completion::detail::DirectOrders direct(pred, touching);
      const auto above = [&](int x, int y) { return direct.above(x, y); };
      int right_p = 0, wrong_p = 0;
      for (auto p : P) (strand[p.first] == strand[p.second] ? right_p : wrong_p)++;
      for (int i = 0; i < static_cast<int>(pred.size()); ++i) {
        const RegionRelation& r = pred[i];
        if (r.relation == Relation::kEqual) continue;
        if (!touching.count({std::min(r.a, r.b), std::max(r.a, r.b)})) continue;
        const bool one = strand[r.a] == strand[r.b];
        const char* t = truth_class(truth, r);
        const bool paint = completion::detail::one_paint(tones, fields, r.a, r.b);
        const bool geom = completion::detail::seam_geometry(ctx, r.a, r.b, above);
        // Only the weak ones that a seam test could take are united (each is
        // one more completion of the drawing).
        int right_c = right_p, wrong_c = wrong_p;
        if (std::abs(r.score) < 2.0 && (one || paint || geom)) {
          std::vector<RegionRelation> rel = pred;
          rel[i] = {r.a, r.b, Relation::kEqual, 1.0, true, false};
          right_c = wrong_c = 0;
          for (auto p : run(rel)) (strand[p.first] == strand[p.second] ? right_c : wrong_c)++;
        }
        std::printf(
            "seed %d seamcand %d-%d %s truth %s score %.2f st %d paint %d geom %d step %.2f "
            "match %d mstep %.3f tone %.3f %.3f px %d %d ttd %d ov %d ev %s %.2f; unite %+d %+d;",
            seed + k, r.a, r.b, one ? "one" : "two", t, r.score, tones.screentone(), paint, geom,
            fields.paint_step(r.a, r.b), static_cast<int>(tones.match(r.a, r.b)),
            tones.mass_step(r.a, r.b), tones.tone(r.a), tones.tone(r.b), tones.tone_pixels(r.a),
            tones.tone_pixels(r.b), completion::detail::two_tones_by_dots(tones, r.a, r.b),
            r.overridden,
            !r.equal_evidence        ? "no"
            : r.equal_evidence->open ? "open"
                                     : "occl",
            r.equal_evidence ? r.equal_evidence->log_odds : 0.0, right_c - right_p,
            wrong_c - wrong_p);
        if (!crops.empty() && paint && std::abs(r.score) < 2.0)
          write_crop(crops + "/" + std::to_string(seed + k) + "_" + std::to_string(r.a) + "_" +
                         std::to_string(r.b) + (one ? "_one.png" : "_two.png"),
                     c.image, ctx.labels, r.a, r.b);
        if (std::abs(r.score) < 2.0) {
          const auto sc = completion::detail::strand_continuation(ctx, r.a, r.b, above);
          std::printf(
              " cont %d len %.1f bend %.1f w %.1f %.1f n %d %d lo %d %.1f %.0f hi %d %.1f %.0f;",
              completion::detail::continues_one_strand(sc), sc.line_length, sc.bend, sc.width_a,
              sc.width_b, sc.slices_a, sc.slices_b, sc.low.measured, sc.low.offset, sc.low.angle,
              sc.high.measured, sc.high.offset, sc.high.angle);
        }
        for (const auto& e : completion::detail::seam_ends(ctx, r.a, r.b))
          std::printf(" [x%d%s%s s%.0f t%.0f]", e.third,
                      e.third != 0 && above(e.third, r.a) ? "^a" : "",
                      e.third != 0 && above(e.third, r.b) ? "^b" : "", e.sides, e.through);
        std::printf("\n");
      }
      std::fflush(stdout);
      continue;
    }
    // Class of each predicted relation (index -> class name).
    std::map<std::string, std::vector<int>> classes;
    std::set<std::pair<int, int>> predicted_pairs;
    for (int i = 0; i < static_cast<int>(pred.size()); ++i) {
      const RegionRelation& r = pred[i];
      const std::pair<int, int> key{std::min(r.a, r.b), std::max(r.a, r.b)};
      const bool touch = touching.count(key);
      if (completion::detail::unmeasured(r, touching)) continue;
      predicted_pairs.insert(key);
      const bool weak = std::abs(r.score) < 2.0;
      const std::string w = weak ? ":weak" : ":firm";
      auto it = truth.find({r.a, r.b});
      const bool one = strand[r.a] == strand[r.b];
      std::string cls;
      if (it != truth.end()) {
        if (it->second == r.relation) {
          if (r.relation == Relation::kEqual && tones.screentone()) {
            const auto& e = r.equal_evidence;
            const bool weak = e && e->log_odds < (e->open ? 0.0 : 2.0);
            std::printf(
                "seed %d true_equal %d=%d px %d %d weak %d lo %.2f open %d tone %.3f %.3f match %d "
                "mstep %.3f ttd %d dsa %d\n",
                seed + k, r.a, r.b, interior(r.a), interior(r.b), weak, e ? e->log_odds : 0.0,
                e ? e->open : 0, tones.tone(r.a), tones.tone(r.b),
                static_cast<int>(tones.match(r.a, r.b)), tones.mass_step(r.a, r.b),
                completion::detail::two_tones_by_dots(tones, r.a, r.b),
                completion::detail::dark_shares_apart(tones, r.a, r.b));
          }
          continue;
        }
        if (r.relation == Relation::kEqual)
          cls = "false_equal";
        else if (it->second == Relation::kEqual)
          cls = "order_of_equal" + w;
        else
          cls = "reversed" + w + (weak && std::abs(r.score) < 0.5 ? ":bare" : "");
      } else if (r.relation == Relation::kEqual)
        cls = one ? "unrel_equal_one" : "unrel_equal_two";
      else
        cls = std::string(touch ? "touch_order_" : "remote_order_") + (one ? "one" : "two") + w;
      classes[cls].push_back(i);
    }
    // Annotated pairs the layering does not relate.
    std::vector<AnnotatedPair> missing;
    for (const auto& p : c.pairs)
      if (!predicted_pairs.count({std::min(p.a, p.b), std::max(p.a, p.b)})) missing.push_back(p);

    auto corrected = [&](const std::vector<int>& idx) {
      std::set<int> drop(idx.begin(), idx.end());
      std::vector<RegionRelation> out;
      for (int i = 0; i < static_cast<int>(pred.size()); ++i) {
        if (!drop.count(i)) {
          out.push_back(pred[i]);
          continue;
        }
        auto it = truth.find({pred[i].a, pred[i].b});
        if (it == truth.end()) continue;
        RegionRelation r = pred[i];
        const double sign = it->second == Relation::kAbove ? 1.0 : -1.0;
        if (correction == "weak" && it->second != Relation::kEqual && !r.user_fixed) {
          // The annotation's direction with the layering's strength.
          r.relation = it->second, r.score = sign * std::abs(r.score), r.overridden = false;
          out.push_back(r);
        } else if (correction == "firm_same" && r.relation != Relation::kEqual) {
          // The layering's direction made firm.
          r.score = (r.relation == Relation::kAbove ? 1.0 : -1.0) * 2.5;
          out.push_back(r);
        } else {
          out.push_back({pred[i].a, pred[i].b, it->second, 1.0, true, false});
        }
      }
      return out;
    };
    PairSet back_any, gone_any;
    for (const auto& [cls, idx] : classes) {
      const PairSet C = run(corrected(idx));
      Tally& t = tally[cls];
      t.relations += idx.size();
      int back = 0, gone = 0;
      for (auto p : lost)
        if (C.count(p)) ++back, back_any.insert(p);
      for (auto p : added)
        if (!C.count(p)) ++gone, gone_any.insert(p);
      t.back += back;
      t.gone += gone;
      if (back || gone)
        std::printf("seed %d class %s: %zu relations, lost back %d, wrong gone %d\n", seed + k,
                    cls.c_str(), idx.size(), back, gone);
    }
    if (!missing.empty()) {
      std::vector<RegionRelation> rel = pred;
      for (const auto& p : missing) rel.push_back({p.a, p.b, p.relation, 1.0, true, false});
      const PairSet C = run(rel);
      Tally& t = tally["missing"];
      t.relations += missing.size();
      for (auto p : lost)
        if (C.count(p)) ++t.back, back_any.insert(p);
      for (auto p : added)
        if (!C.count(p)) ++t.gone, gone_any.insert(p);
    }
    none_singly += lost.size() - back_any.size();
    wrong_left += added.size() - gone_any.size();
    // False equals and unrelated equals of two strands one by one.
    for (const char* cls : {"false_equal", "unrel_equal_two", "unrel_equal_one"})
      for (int i : classes[cls]) {
        const RegionRelation& r = pred[i];
        const PairSet C = run(corrected({i}));
        int back = 0, gone = 0;
        for (auto p : lost) back += C.count(p);
        for (auto p : added) gone += !C.count(p);
        const auto& e = r.equal_evidence;
        std::printf(
            "seed %d %s %d=%d px %d %d (strands %d %d, truth %s) ev %s lo %.2f open %d of %.2f; st "
            "%d "
            "tone %.3f %.3f match %d mstep %.3f ttd %d twotones %d pstep %.2f; back %d gone %d\n",
            seed + k, cls, r.a, r.b, interior(r.a), interior(r.b), strand[r.a], strand[r.b],
            truth.count({r.a, r.b}) ? (truth[{r.a, r.b}] == Relation::kAbove   ? "above"
                                       : truth[{r.a, r.b}] == Relation::kBelow ? "below"
                                                                               : "equal")
                                    : "none",
            e ? "yes" : "no", e ? e->log_odds : 0.0, e ? e->open : 0, e ? e->open_fraction : 0.0,
            tones.screentone(), tones.tone(r.a), tones.tone(r.b),
            static_cast<int>(tones.match(r.a, r.b)), tones.mass_step(r.a, r.b),
            completion::detail::two_tones_by_dots(tones, r.a, r.b),
            tones.screentone() ? tones.two_tones(r.a, r.b) : 0, fields.paint_step(r.a, r.b), back,
            gone);
      }
    for (auto p : added) std::printf("seed %d added wrong %d-%d\n", seed + k, p.first, p.second);
    std::fflush(stdout);
  }
  std::printf("TOTAL lost %d added %d; none singly %d, wrong left %d\n", lost_total, added_total,
              none_singly, wrong_left);
  for (const auto& [cls, t] : tally)
    std::printf("CLASS %-26s relations %4d lost back %4d wrong gone %4d\n", cls.c_str(),
                t.relations, t.back, t.gone);
  return 0;
}
