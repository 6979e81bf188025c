// A completion input from a generated case, with the generator's exact
// relations standing in for layering (benchmarks time one stage at a time).
// They are certain, so user-fixed: a weak measured relation keeps no two
// pieces out of one strand (completion.cpp), and score 1.0 alone is weak.
#pragma once

#include "hair25d/completion/completion.h"
#include "hair25d/core/annotation.h"

namespace hair25d::bench {

// `c` must outlive the returned input (it points at the image and regions).
inline completion::Input completion_input(const AnnotatedCase& c) {
  completion::Input in;
  in.image = &c.image;
  in.regions = &c.regions;
  for (const AnnotatedPair& p : c.pairs)
    in.relations.push_back({p.a, p.b, p.relation, 1.0, true, false});
  in.head_center = c.head_center;
  return in;
}

}  // namespace hair25d::bench
