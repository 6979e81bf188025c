// The layering's relations for an annotated or generated case, as
// `hair25d model` gives them to completion. Shared by eval_joins
// (--relations predicted) and train_join_scorer (collect --relations
// predicted), so the trainer records the candidates the evaluation meets.
#pragma once

#include <string>
#include <vector>

#include "hair25d/core/annotation.h"
#include "hair25d/core/hair_model.h"

namespace hair25d::completion::test {

// The relations layering::layer_regions measures on the case's image and
// regions. A failed layering gives no relations (not the annotation's) and
// its message in *error.
std::vector<RegionRelation> predicted_relations(const AnnotatedCase& c, std::string* error);

}  // namespace hair25d::completion::test
