#include "case_relations.h"

#include <exception>

#include "hair25d/layering/layering.h"

namespace hair25d::completion::test {

std::vector<RegionRelation> predicted_relations(const AnnotatedCase& c, std::string* error) {
  error->clear();
  try {
    return layering::layer_regions(c.image, c.regions).relations;
  } catch (const std::exception& e) {
    *error = e.what();
    return {};
  }
}

}  // namespace hair25d::completion::test
