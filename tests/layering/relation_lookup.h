// The relation a layering result gives a region pair, in either order
// (shared by the layering tests).
#pragma once

#include <gtest/gtest.h>

#include "hair25d/layering/layering.h"

namespace hair25d::layering::test {

// `a` relative to `b`; a test failure (and "equal") when the pair is missing.
inline Relation relation_of(const Result& r, int a, int b) {
  for (const RegionRelation& x : r.relations) {
    if (x.a == a && x.b == b) return x.relation;
    if (x.a == b && x.b == a) return reversed(x.relation);
  }
  ADD_FAILURE() << "no relation between " << a << " and " << b;
  return Relation::kEqual;
}

}  // namespace hair25d::layering::test
