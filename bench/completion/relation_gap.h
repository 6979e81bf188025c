// eval_joins --relation-gap: the links the annotation's relations make but
// the layering's lose, each named by the census stage that stopped it with
// the layering's relations and by what in those relations differs for the
// pair (docs/completion-record.md, session 33, joins77).
#pragma once

#include <map>
#include <string>
#include <utility>

#include "hair25d/completion/completion.h"
#include "hair25d/core/annotation.h"

namespace hair25d::completion::test {

struct GapTotal {
  // Links and pairs by (relation class, census stage).
  std::map<std::pair<std::string, std::string>, std::pair<int, int>> by_class;
};

// Runs completion on `c` with the annotation's relations and the layering's
// (options.trace_joins is set for both), prints one line per gap link and
// adds them to `total`.
void relation_gap(const AnnotatedCase& c, const Options& options, const std::string& name,
                  GapTotal* total);

void print_gap_table(const GapTotal& total);

}  // namespace hair25d::completion::test
