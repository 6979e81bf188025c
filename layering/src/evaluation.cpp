#include "hair25d/layering/evaluation.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <string>

#include "hair25d/core/error.h"

namespace hair25d::layering {

CaseScore score_relations(const AnnotatedCase& annotated,
                          const std::vector<RegionRelation>& relations) {
  std::map<std::pair<int, int>, Relation> predicted;  // keyed (min, max), of min to max
  for (const RegionRelation& r : relations) {
    if (r.a < r.b)
      predicted[{r.a, r.b}] = r.relation;
    else
      predicted[{r.b, r.a}] = reversed(r.relation);
  }
  CaseScore score;
  score.name = annotated.name;
  score.regions = static_cast<int>(annotated.regions.labels().size());
  // A pair judged twice would count twice (read_annotated_case refuses such
  // files; a case built in code is checked here).
  std::map<std::pair<int, int>, std::size_t> judged;
  for (std::size_t i = 0; i < annotated.pairs.size(); ++i) {
    const AnnotatedPair& p = annotated.pairs[i];
    const auto [at, fresh] = judged.try_emplace({std::min(p.a, p.b), std::max(p.a, p.b)}, i);
    if (!fresh) {
      throw Error(annotated.name + ": pairs[" + std::to_string(i) + "] judges regions " +
                  std::to_string(p.a) + " and " + std::to_string(p.b) + " again (pairs[" +
                  std::to_string(at->second) + "] did); each pair of regions is judged once");
    }
  }
  for (const AnnotatedPair& p : annotated.pairs) {
    PairOutcome o{p.a, p.b, p.relation, std::nullopt, false};
    auto it = predicted.find({std::min(p.a, p.b), std::max(p.a, p.b)});
    if (it != predicted.end()) {
      o.predicted = p.a < p.b ? it->second : reversed(it->second);
      o.correct = *o.predicted == p.relation;
    }
    score.correct += o.correct ? 1 : 0;
    score.outcomes.push_back(o);
  }
  score.pairs = static_cast<int>(annotated.pairs.size());
  return score;
}

CaseScore evaluate_case(const AnnotatedCase& annotated, const Options& options, Result* result) {
  const auto start = std::chrono::steady_clock::now();
  Result r = layer_regions(annotated.image, annotated.regions, options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CaseScore score = score_relations(annotated, r.relations);
  score.seconds = seconds;
  if (result != nullptr) *result = std::move(r);
  return score;
}

}  // namespace hair25d::layering
