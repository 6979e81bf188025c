#include "greedy_matching.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <utility>

#include "bank_crossings.h"
#include "hair25d/completion/join_scorer.h"
#include "second_partner.h"

namespace hair25d::completion::detail {
namespace {

// Options::second_partner_p: a candidate the scorer is sure of whose atoms
// are taken on one of its edges only (taken_edge), each by one join.
bool second_partner(const Join& j, const std::vector<Edge>& edges, const std::set<int>& used,
                    const std::set<int>& twice, double bar) {
  if (bar <= 0 || j.probability < bar) return false;
  const int taken = taken_edge(j, edges, used);
  return taken >= 0 &&
         std::ranges::none_of(edges[taken].atoms, [&](int atom) { return twice.count(atom) > 0; });
}

}  // namespace

std::vector<Join> choose_joins(const Context& ctx, const std::vector<Edge>& edges,
                               RegionTones& tones, bool shaded, std::vector<Join> candidates,
                               const std::function<bool(int, int)>& try_join,
                               const std::function<bool(int, int)>& joined) {
  const Options& o = *ctx.options;
  const JoinScorerOptions& scorer = o.join_scorer;
  // Greedy one-to-one: cheapest first, every edge joined at most once.
  std::erase_if(candidates, [&](const Join& x) { return x.cost > o.max_join_cost; });
  std::sort(candidates.begin(), candidates.end(),
            [](const Join& x, const Join& y) { return x.cost < y.cost; });
  // Edges may overlap (an atom and a merged edge holding it): an atom joins once.
  std::set<int> used;
  std::map<int, std::pair<int, int>> taken_by;  // atom -> the regions of its join (traced)
  std::set<int> twice;                          // atoms joined a second time
  std::map<int, std::vector<int>> joins_of;     // atom -> its joins (indices into chosen)
  // Session 37: a cut's second partners judged by their own net, on
  // two-tone and gradient drawings unless second_partner_all_shadings; with
  // the candidates recorded and the scorer on (the model's matching), every
  // one is a row (training data).
  const bool second_net = scorer.enabled && scorer.second_partner_threshold < 1 &&
                          (shaded || scorer.second_partner_all_shadings);
  const bool second_rows = scorer.enabled && ctx.join_log != nullptr;
  std::vector<Join> chosen;
  // The net's inputs for `j`, whose edge `taken` earlier joins hold (none
  // when no chosen join holds its atoms).
  auto second_inputs = [&](const Join& j, int taken) -> std::optional<JoinFeatures> {
    std::vector<FirstPartner> firsts;
    std::set<int> seen;
    for (int atom : edges[taken].atoms)
      for (int k : joins_of[atom]) {
        if (!seen.insert(k).second) continue;
        const Join& c = chosen[k];
        const bool a_holds = std::ranges::any_of(edges[c.edge_a].atoms, [&](int x) {
          return std::ranges::count(edges[taken].atoms, x) > 0;
        });
        firsts.push_back(
            {a_holds ? c.edge_a : c.edge_b, a_holds ? c.edge_b : c.edge_a, c.probability, c.cost});
      }
    if (firsts.empty()) return std::nullopt;
    JoinFeatures f = *j.features;
    add_second_terms(edges, j, taken, firsts, &f);
    return f;
  };
  auto already_one = [&](const Join& j) {
    return joined && joined(edges[j.edge_a].region, edges[j.edge_b].region);
  };
  auto commit = [&](Join& j, JoinTrace* t) {
    for (int e : {j.edge_a, j.edge_b})
      for (int atom : edges[e].atoms) {
        if (!used.insert(atom).second) twice.insert(atom);
        joins_of[atom].push_back(static_cast<int>(chosen.size()));
      }
    if (t) {
      t->stage = JoinStage::kChosen;
      for (int e : {j.edge_a, j.edge_b})
        for (int atom : edges[e].atoms)
          taken_by[atom] = {edges[j.edge_a].region, edges[j.edge_b].region};
    }
    if (j.record >= 0) (*ctx.join_log)[j.record].chosen = true;
    chosen.push_back(std::move(j));
  };
  // Second partners the net accepts, joined after every other candidate
  // (second_partner_last).
  std::vector<Join*> deferred;
  for (Join& j : candidates) {
    bool free = true;
    for (int e : {j.edge_a, j.edge_b})
      for (int atom : edges[e].atoms) free = free && !used.count(atom);
    bool second = !free && second_partner(j, edges, used, twice, o.second_partner_p);
    const int taken = free || second ? -1 : taken_edge(j, edges, used);
    int second_record = -1;
    if (taken >= 0 && j.features && (second_net || second_rows) && !already_one(j))
      if (const std::optional<JoinFeatures> f = second_inputs(j, taken)) {
        const double p = second_net ? join_probability(second_partner_join_scorer(), *f) : -1.0;
        const bool accepted = second_net && p >= scorer.second_partner_threshold;
        if (accepted && scorer.second_partner_last)
          deferred.push_back(&j);
        else
          second = accepted;
        if (second_rows) {
          JoinCandidate c;
          c.region_a = edges[j.edge_a].region;
          c.region_b = edges[j.edge_b].region;
          c.hand_cost = j.record >= 0 ? (*ctx.join_log)[j.record].hand_cost : j.cost;
          c.cost = j.cost;
          c.probability = p;
          c.features = *f;
          second_record = static_cast<int>(ctx.join_log->size());
          ctx.join_log->push_back(c);
        }
      }
    JoinTrace* t = j.trace >= 0 ? &(*ctx.join_trace)[j.trace] : nullptr;
    if (t) {
      t->stage = JoinStage::kAtomTaken;
      for (int e : {j.edge_a, j.edge_b})
        for (int atom : edges[e].atoms)
          if (const auto it = taken_by.find(atom); it != taken_by.end() && t->rival_a == 0)
            std::tie(t->rival_a, t->rival_b) = it->second;
      if (free || second)
        t->stage = two_tones_by_dots(tones, edges[j.edge_a].region, edges[j.edge_b].region)
                       ? JoinStage::kTwoTones
                       : JoinStage::kRefused;
    }
    // Pieces of two tones by their dots are two strands whatever their
    // outlines say; refused here, not among the candidates, so that the
    // scorer still reads them as rivals (refused before scoring, dev
    // screentone 5028 lost a right back-piece path join to a rescued one).
    if ((!free && !second) ||
        two_tones_by_dots(tones, edges[j.edge_a].region, edges[j.edge_b].region) ||
        !try_join(edges[j.edge_a].region, edges[j.edge_b].region))
      continue;
    if (second_record >= 0) (*ctx.join_log)[second_record].chosen = true;
    commit(j, t);
  }
  // The deferred second partners, the surest first, each asked again with
  // the joins made since (its other cut may have been taken, its first
  // partners grown): they take only cuts no other join wanted.
  while (!deferred.empty()) {
    double best = -1.0;
    std::size_t at = deferred.size();
    for (std::size_t k = 0; k < deferred.size(); ++k) {
      const Join& j = *deferred[k];
      const int taken = taken_edge(j, edges, used);
      if (taken < 0 || already_one(j) ||
          two_tones_by_dots(tones, edges[j.edge_a].region, edges[j.edge_b].region))
        continue;
      const std::optional<JoinFeatures> f = second_inputs(j, taken);
      const double p = f ? join_probability(second_partner_join_scorer(), *f) : -1.0;
      if (p >= scorer.second_partner_threshold && p > best) best = p, at = k;
    }
    if (at == deferred.size()) break;
    Join& j = *deferred[at];
    deferred.erase(deferred.begin() + static_cast<std::ptrdiff_t>(at));
    JoinTrace* t = j.trace >= 0 ? &(*ctx.join_trace)[j.trace] : nullptr;
    if (!try_join(edges[j.edge_a].region, edges[j.edge_b].region)) continue;
    commit(j, t);
  }
  return chosen;
}

}  // namespace hair25d::completion::detail
