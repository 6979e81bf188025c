// clang-format off
// Placeholder until bench/completion/train_join_scorer train --cover-only
// writes the trained net here: every weight 0 (p = 0.5).
#include "hair25d/completion/join_scorer.h"

namespace hair25d::completion {

const JoinScorerNet& cover_join_scorer() {
  static const JoinScorerNet net{};
  return net;
}

}  // namespace hair25d::completion
