// How many of an annotated case's same-strand region pairs any case-1 join
// method could find (paper §5.1: the hidden part lies under the occluders):
// pairs whose pieces are linked through pixels of regions lying above them.
#pragma once

#include <cstdio>
#include <map>

#include "hair25d/core/annotation.h"

namespace hair25d::completion::test {

struct UpperBound {
  int truth = 0;  // same-strand region pairs
  // Pairs linked through regions lying above both pieces (one gap each), and
  // with chains of such links (a strand passing under several occluders).
  int both_direct = 0, both_chained = 0;
  // Through regions above any piece of the strand (relations only judge
  // touching regions, so an occluder of one piece may not be known to lie
  // above the other), chained.
  int strand_chained = 0;
  // The same, also through label-0 pixels inside the strand's whole mask
  // (the face, which is no region, hides back hair).
  int strand_face_chained = 0;
  // Pairs of two strands, neither above the other, that are linked through
  // regions above both too: what the criterion alone would join wrongly.
  int other_pairs = 0, other_linked = 0;
};

// Label-0 pixels next to a passable occluder (the light rims of drawn lines)
// count as passable; outline pixels are first assigned as completion does.
// With `csv`, one line a pair of regions neither above the other is
// appended (case, ids, names, same strand, lying above no region, linked
// under both / either, colour distance and spreads, pixels, joined by `joined`).
UpperBound join_upper_bound(const AnnotatedCase& c, std::FILE* csv = nullptr,
                            const std::map<int, int>* joined = nullptr);

}  // namespace hair25d::completion::test
