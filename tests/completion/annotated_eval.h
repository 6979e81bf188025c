// Scoring completion against annotated cases: precision / recall of the
// region pairs put into one strand, and each completed strand's IoU with its
// annotated whole mask. Ground truth is read here only, never by the module.
#pragma once

#include <map>
#include <set>
#include <vector>

#include "hair25d/completion/completion.h"
#include "hair25d/core/annotation.h"

namespace hair25d::completion::test {

struct PairScore {
  int predicted = 0, truth = 0, correct = 0;
  double precision() const { return predicted ? static_cast<double>(correct) / predicted : 1.0; }
  double recall() const { return truth ? static_cast<double>(correct) / truth : 1.0; }
};

inline std::vector<RegionRelation> relations_from_pairs(const AnnotatedCase& c) {
  std::vector<RegionRelation> out;
  for (const AnnotatedPair& p : c.pairs) out.push_back({p.a, p.b, p.relation, 1.0, true, false});
  return out;
}

// The completion input of a case with its annotated relations; `c` must
// outlive it (it points at the image and regions).
inline Input input_from_case(const AnnotatedCase& c) {
  Input in;
  in.image = &c.image;
  in.regions = &c.regions;
  in.relations = relations_from_pairs(c);
  in.head_center = c.head_center;
  return in;
}

inline PairScore score_pairs(const AnnotatedCase& c, const Result& r) {
  std::map<int, int> truth, predicted;
  for (const AnnotatedRegion& reg : c.region_list) truth[reg.id] = reg.strand;
  for (std::size_t s = 0; s < r.strands.size(); ++s)
    for (int id : r.strands[s].regions) predicted[id] = static_cast<int>(s);
  PairScore score;
  std::vector<int> ids;
  for (const auto& [id, strand] : truth) ids.push_back(id);
  for (std::size_t i = 0; i < ids.size(); ++i)
    for (std::size_t j = i + 1; j < ids.size(); ++j) {
      const bool t = truth[ids[i]] == truth[ids[j]];
      const bool p = predicted.count(ids[i]) && predicted.count(ids[j]) &&
                     predicted[ids[i]] == predicted[ids[j]];
      score.truth += t;
      score.predicted += p;
      score.correct += t && p;
    }
  return score;
}

// IoU of every completed strand with the annotated mask of the strand most of
// its regions belong to.
inline std::vector<double> strand_ious(const AnnotatedCase& c, const Result& r) {
  std::map<int, int> truth;
  for (const AnnotatedRegion& reg : c.region_list) truth[reg.id] = reg.strand;
  std::vector<double> out;
  for (const CompletedStrand& s : r.strands) {
    std::map<int, int> votes;
    for (int id : s.regions) ++votes[truth[id]];
    int best = 0, n = -1;
    for (auto [strand, v] : votes)
      if (v > n) n = v, best = strand;
    auto it = c.strand_masks.find(best);
    if (it == c.strand_masks.end()) continue;
    const LabelMap& gt = it->second;
    long inter = 0, uni = 0;
    for (int y = 0; y < gt.height(); ++y)
      for (int x = 0; x < gt.width(); ++x) {
        const int mx = x - s.origin.x(), my = y - s.origin.y();
        const bool p = s.mask.contains(mx, my) && s.mask.at(mx, my) != 0;
        const bool g = gt.at(x, y) != 0;
        inter += p && g;
        uni += p || g;
      }
    out.push_back(uni ? static_cast<double>(inter) / uni : 1.0);
  }
  return out;
}

}  // namespace hair25d::completion::test
