// Options for the tests that judge only which pieces are joined: the
// strands' and the background's inpainting, the slow part of
// complete_strands, is left out.
#pragma once

#include "hair25d/completion/completion.h"

namespace hair25d::completion::test {

inline Options joins_only() {
  Options o;
  o.inpaint_strands = false;
  o.inpaint_background = false;
  return o;
}

}  // namespace hair25d::completion::test
