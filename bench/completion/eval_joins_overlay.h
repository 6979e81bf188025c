// Overlay of case-1 joins for a person to check (eval_joins --overlay): the
// drawing dimmed, every region's id, the annotation's strands as thin yellow
// chains between region centres, joins made as green (right) or red (wrong)
// lines between the joined edges.
#pragma once

#include <filesystem>

#include "hair25d/completion/completion.h"
#include "hair25d/core/annotation.h"

namespace hair25d::completion::test {

// Writes the overlay PNG; prints the wrong and missed region pairs of the
// joins (one line each) to stdout, prefixed by `name`.
void write_join_overlay(const std::filesystem::path& path, const AnnotatedCase& c, const Result& r,
                        const std::string& name);

}  // namespace hair25d::completion::test
