#include "relation_gap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

#include "../../tests/completion/annotated_eval.h"
#include "../../tests/completion/join_census.h"
#include "case_relations.h"

namespace hair25d::completion::test {
namespace {

constexpr double kFirm = 2.0;  // completion's kFirmRelationScore

struct Pred {
  Relation relation = Relation::kEqual;  // where the first lies relative to the second
  double score = 0.0;
};

Relation flip(Relation r) {
  return r == Relation::kAbove ? Relation::kBelow : r == Relation::kBelow ? Relation::kAbove : r;
}

// 4-neighbour contacts between regions in completion's outline-assigned labels.
std::set<std::pair<int, int>> contacts(const LabelMap& m) {
  std::set<std::pair<int, int>> out;
  for (int y = 0; y < m.height(); ++y)
    for (int x = 0; x < m.width(); ++x) {
      const int a = m.at(x, y);
      if (a <= 0) continue;
      if (x + 1 < m.width() && m.at(x + 1, y) > 0 && m.at(x + 1, y) != a)
        out.insert(std::minmax(a, m.at(x + 1, y)));
      if (y + 1 < m.height() && m.at(x, y + 1) > 0 && m.at(x, y + 1) != a)
        out.insert(std::minmax(a, m.at(x, y + 1)));
    }
  return out;
}

}  // namespace

void relation_gap(const AnnotatedCase& c, const Options& base, const std::string& name,
                  GapTotal* total) {
  Options options = base;
  options.trace_joins = true;
  Input in = input_from_case(c);
  const Result ra = complete_strands(in, options);
  std::string error;
  in.relations = predicted_relations(c, &error);
  if (!error.empty()) return;
  const Result rp = complete_strands(in, options);

  std::map<int, int> truth, ann_group, pred_group;
  for (const AnnotatedRegion& reg : c.region_list) truth[reg.id] = reg.strand;
  for (std::size_t s = 0; s < ra.strands.size(); ++s)
    for (int id : ra.strands[s].regions) ann_group[id] = static_cast<int>(s);
  for (std::size_t s = 0; s < rp.strands.size(); ++s)
    for (int id : rp.strands[s].regions) pred_group[id] = static_cast<int>(s);
  auto same = [](const std::map<int, int>& g, int a, int b) {
    const auto ia = g.find(a), ib = g.find(b);
    return ia != g.end() && ib != g.end() && ia->second == ib->second;
  };
  std::map<std::pair<int, int>, Relation> ann;  // where .first lies relative to .second
  for (const AnnotatedPair& p : c.pairs) {
    ann[{p.a, p.b}] = p.relation;
    ann[{p.b, p.a}] = flip(p.relation);
  }
  std::map<std::pair<int, int>, Pred> pred;
  for (const RegionRelation& r : in.relations) {
    pred[{r.a, r.b}] = {r.relation, r.score};
    pred[{r.b, r.a}] = {flip(r.relation), r.score};
  }
  const std::set<std::pair<int, int>> touch = contacts(rp.regions);
  auto touching = [&](int a, int b) { return touch.count(std::minmax(a, b)) > 0; };
  auto ann_above = [&](int o, int x) {
    const auto it = ann.find({o, x});
    return it != ann.end() && it->second == Relation::kAbove;
  };
  // The layering's relation of o to x, in words.
  auto pred_of = [&](int o, int x) -> std::string {
    const auto it = pred.find({o, x});
    if (it == pred.end()) return "none";
    const char* strength = std::abs(it->second.score) >= kFirm ? "firm" : "weak";
    if (it->second.relation == Relation::kEqual) return "equal";
    const std::string dir = it->second.relation == Relation::kAbove ? "above" : "below";
    if (it->second.score == 0.0) return dir + "0";
    return dir + ":" + strength;
  };

  for (const LostLink& l : lost_links(c, rp)) {
    if (!same(ann_group, l.region_a, l.region_b)) continue;  // lost with both
    // The two predicted groups of the link, within its true strand.
    std::set<int> g1, g2;
    for (const auto& [id, s] : truth) {
      if (s != l.strand) continue;
      if (id == l.region_a || same(pred_group, id, l.region_a)) g1.insert(id);
      if (id == l.region_b || same(pred_group, id, l.region_b)) g2.insert(id);
    }
    // The annotated run's case-1 join between the groups, if any.
    int x = l.region_a, y = l.region_b;
    std::string pass = "other pass";
    for (const JoinTrace& t : ra.join_trace) {
      if (t.stage != JoinStage::kChosen) continue;
      if ((g1.count(t.region_a) && g2.count(t.region_b)) ||
          (g2.count(t.region_a) && g1.count(t.region_b))) {
        x = t.region_a, y = t.region_b, pass = "edge join";
        break;
      }
    }
    // The stage of (x, y) with the layering's relations.
    const JoinTrace* best = nullptr;
    for (const JoinTrace& t : rp.join_trace)
      if (std::minmax(t.region_a, t.region_b) == std::minmax(x, y) &&
          (!best || t.stage > best->stage))
        best = &t;
    const std::string stage = best ? census_class(LostLink{0, x, y, *best}) : "no trace";

    // What differs. The relation between the two pieces first.
    std::string cls, detail;
    const std::string direct = pred_of(x, y);
    const auto ia = ann.find({x, y});
    const std::string ann_xy = ia == ann.end()                  ? "unjudged"
                               : ia->second == Relation::kEqual ? "equal"
                                                                : "ordered";
    if (direct != "none" && direct != "equal")
      cls = std::string("direct order ") +
            (direct.find("firm") != std::string::npos ? "firm" : "weak") +
            (touching(x, y) ? ", touching" : ", remote") + " (annotation " + ann_xy + ")";
    // The annotation's occluders over both pieces.
    std::vector<int> common;
    for (const auto& [id, s] : truth)
      if (ann_above(id, x) && ann_above(id, y)) common.push_back(id);
    bool kept = false;
    std::string lost;
    for (int o : common) {
      const std::string px = pred_of(o, x), py = pred_of(o, y);
      const bool ax = px.rfind("above", 0) == 0, ay = py.rfind("above", 0) == 0;
      if (ax && ay) kept = true;
      detail += " occ " + std::to_string(o) + " x:" + px + " y:" + py;
      if (!ax || !ay) {
        const std::string miss = !ax ? px : py;
        const std::string kind = ax || ay ? "over one piece only, other " : "over neither, ";
        const std::string m = miss == "none" ? "missing" : miss == "equal" ? "equal" : "reversed";
        if (lost.empty()) lost = kind + m;
      }
    }
    if (cls.empty() && !common.empty() && !kept) cls = "common occluder " + lost;
    if (cls.empty() && common.empty()) cls = "no common occluder (annotation)";
    // Regions the layering puts above a piece that the annotation does not.
    std::string extra;
    for (int p : {x, y})
      for (const auto& [key, v] : pred) {
        if (key.second != p || v.relation != Relation::kAbove) continue;
        if (ann_above(key.first, p)) continue;
        if (truth.count(key.first) && truth[key.first] == l.strand) continue;
        const auto ia = ann.find({key.first, p});
        const std::string kind =
            ia == ann.end() ? (touching(key.first, p) ? "unjudged touching" : "unjudged remote")
                            : "reversed";
        detail += " extra " + std::to_string(key.first) + ">" + std::to_string(p) + " " + kind +
                  (std::abs(v.score) >= kFirm ? " firm" : " weak");
        if (extra.empty() || kind == "reversed") extra = "extra occluder " + kind;
      }
    if (cls.empty() && !extra.empty()) cls = extra;
    if (cls.empty()) cls = "relations of the pair read right";
    std::printf("%s: gap link %d-%d (strand %d, %d pairs, %s %d-%d): %s | %s |%s\n", name.c_str(),
                l.region_a, l.region_b, l.strand, l.pairs, pass.c_str(), x, y, stage.c_str(),
                cls.c_str(), detail.c_str());
    auto& n = total->by_class[{cls, stage}];
    n.first += 1, n.second += l.pairs;
  }
}

void print_gap_table(const GapTotal& total) {
  std::map<std::string, std::pair<int, int>> by_cls, by_stage;
  for (const auto& [k, n] : total.by_class) {
    by_cls[k.first].first += n.first, by_cls[k.first].second += n.second;
    by_stage[k.second].first += n.first, by_stage[k.second].second += n.second;
    std::printf("gap: %s | %s | %d (%d)\n", k.first.c_str(), k.second.c_str(), n.first, n.second);
  }
  for (const auto& [k, n] : by_cls)
    std::printf("gap class: %s | %d (%d)\n", k.c_str(), n.first, n.second);
  for (const auto& [k, n] : by_stage)
    std::printf("gap stage: %s | %d (%d)\n", k.c_str(), n.first, n.second);
}

}  // namespace hair25d::completion::test
