// Where the case-1 joins lose the annotation's strands (eval_joins --census):
// each true strand left in k predicted groups needs k − 1 links between
// them; they are chosen by Kruskal over the traced edge pairs
// (Options::trace_joins), the pair that got furthest in the matching
// first, so each lost link is named by the stage that stopped its best pair.
#pragma once

#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "hair25d/completion/completion.h"
#include "hair25d/core/annotation.h"

namespace hair25d::completion::test {

struct LostLink {
  int strand = 0;                  // the annotation's strand
  int region_a = 0, region_b = 0;  // the best traced pair, or two regions of the groups
  std::optional<JoinTrace> best;   // none: no edge pair between the two groups
  bool edges_on_both = false;      // without `best`: both groups have an edge
  int pairs = 0;                   // true pairs this link would add
  bool paint_refused = false;      // kRefused by the strand paint (else a firm order)
  bool rival_right = false;        // kAtomTaken: the join that took the edge is right
};

// The class of a lost link, for tables: the stage's name, or the reason
// no edge pair was there.
inline std::string census_class(const LostLink& l) {
  if (!l.best) return l.edges_on_both ? "no edge pair" : "a side without edges";
  switch (l.best->stage) {
    case JoinStage::kRefused:
      return l.paint_refused ? "refused: strand paint" : "refused: firm order";
    case JoinStage::kAtomTaken:
      return l.rival_right ? "atom taken: right rival" : "atom taken: wrong rival";
    default:
      return to_string(l.best->stage);
  }
}

inline std::vector<LostLink> lost_links(const AnnotatedCase& c, const Result& r) {
  std::map<int, int> truth, group;
  for (const AnnotatedRegion& reg : c.region_list) truth[reg.id] = reg.strand;
  for (std::size_t s = 0; s < r.strands.size(); ++s)
    for (int id : r.strands[s].regions) group[id] = static_cast<int>(s);
  // A region in no predicted strand is a group of its own.
  for (const auto& [id, strand] : truth)
    if (!group.count(id)) group[id] = -1 - id;
  const std::set<int> with_edges(r.edge_regions.begin(), r.edge_regions.end());
  std::set<std::pair<int, int>> paint_refused;
  for (const Result::PaintRefusal& f : r.paint_refusals)
    paint_refused.insert(std::minmax(f.a, f.b));

  std::map<int, std::vector<int>> strands;
  for (const auto& [id, strand] : truth) strands[strand].push_back(id);
  std::vector<LostLink> out;
  for (const auto& [strand, ids] : strands) {
    std::map<int, int> parent, size;  // over predicted groups
    for (int id : ids) parent[group[id]] = group[id], ++size[group[id]];
    if (parent.size() < 2) continue;
    std::function<int(int)> find = [&](int g) {
      return parent[g] == g ? g : parent[g] = find(parent[g]);
    };
    // Best traced pair per two groups: the furthest stage, then the cheapest.
    std::map<std::pair<int, int>, const JoinTrace*> best;
    for (const JoinTrace& t : r.join_trace) {
      if (!truth.count(t.region_a) || !truth.count(t.region_b)) continue;
      if (truth[t.region_a] != strand || truth[t.region_b] != strand) continue;
      const int ga = group[t.region_a], gb = group[t.region_b];
      if (ga == gb) continue;
      const JoinTrace*& b = best[std::minmax(ga, gb)];
      if (!b || t.stage > b->stage ||
          (t.stage == b->stage && t.hand_cost >= 0 &&
           (b->hand_cost < 0 || t.hand_cost < b->hand_cost)))
        b = &t;
    }
    std::vector<std::pair<std::pair<int, int>, const JoinTrace*>> order(best.begin(), best.end());
    std::stable_sort(order.begin(), order.end(), [](const auto& x, const auto& y) {
      return x.second->stage > y.second->stage;
    });
    auto link = [&](int ga, int gb, LostLink l) {
      const int ra = find(ga), rb = find(gb);
      l.strand = strand;
      l.pairs = size[ra] * size[rb];
      parent[ra] = rb;
      size[rb] += size[ra];
      out.push_back(l);
    };
    for (const auto& [groups, t] : order) {
      if (find(groups.first) == find(groups.second)) continue;
      LostLink l;
      l.region_a = t->region_a, l.region_b = t->region_b;
      l.best = *t;
      l.paint_refused = paint_refused.count(std::minmax(t->region_a, t->region_b)) > 0;
      if (t->rival_a != 0 && truth.count(t->rival_a) && truth.count(t->rival_b))
        l.rival_right = truth[t->rival_a] == truth[t->rival_b];
      link(groups.first, groups.second, l);
    }
    // Groups no traced pair links: one link each to the first group.
    const int first = group[ids.front()];
    for (int id : ids) {
      if (find(group[id]) == find(first)) continue;
      LostLink l;
      l.region_a = ids.front(), l.region_b = id;
      bool edges_a = false, edges_b = false;
      for (int x : ids) {
        if (!with_edges.count(x)) continue;
        if (find(group[x]) == find(first)) edges_a = true;
        if (find(group[x]) == find(group[id])) edges_b = true;
      }
      l.edges_on_both = edges_a && edges_b;
      link(group[id], first, l);
    }
  }
  return out;
}

}  // namespace hair25d::completion::test
