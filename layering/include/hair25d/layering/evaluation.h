// Layering accuracy against annotated cases, as in the paper's Table 1 (§7):
// the share of judged region pairs whose predicted relation equals the
// annotation; a judged pair the layering does not relate counts as wrong.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hair25d/core/annotation.h"
#include "hair25d/core/hair_model.h"
#include "hair25d/layering/layering.h"

namespace hair25d::layering {

struct PairOutcome {
  int a = 0;
  int b = 0;
  Relation truth = Relation::kEqual;  // of a to b, annotated
  std::optional<Relation> predicted;  // of a to b; none: not seen as neighbours
  bool correct = false;
};

struct CaseScore {
  std::string name;
  int regions = 0;  // hair regions in the map layered
  int pairs = 0;    // judged pairs
  int correct = 0;
  double seconds = 0.0;  // layering time, wall clock
  std::vector<PairOutcome> outcomes;
  double accuracy() const { return pairs > 0 ? static_cast<double>(correct) / pairs : 0.0; }
};

// Compares `relations` with the case's judged pairs. Throws hair25d::Error
// when two pairs judge the same two regions (either order): it would count twice.
CaseScore score_relations(const AnnotatedCase& annotated,
                          const std::vector<RegionRelation>& relations);

// Layers the case's own regions.png over its image and scores the result;
// `result` (optional) receives the layering. Throws what layer_regions throws.
CaseScore evaluate_case(const AnnotatedCase& annotated, const Options& options = {},
                        Result* result = nullptr);

}  // namespace hair25d::layering
