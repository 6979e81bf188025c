// The join scorers' committed weights files (completion/src/*_weights.cpp),
// which the tests compare with their nets printed again.
#pragma once

#include <fstream>
#include <sstream>
#include <string>

namespace hair25d::completion::test {

// The committed source completion/src/NAME; empty when it cannot be read.
inline std::string committed_source(const std::string& name) {
  std::ifstream in(std::string(HAIR25D_TEST_DATA_DIR) + "/../../completion/src/" + name);
  std::stringstream file;
  file << in.rdbuf();
  return file.str();
}

// A generated weights source from its "// Generated file" line on: what
// the committed file and the nets printed again share byte for byte (above
// it, the comment on how the nets were trained); empty without that line.
inline std::string generated_part(const std::string& source) {
  const std::string::size_type at = source.find("// Generated file");
  return at == std::string::npos ? std::string() : source.substr(at);
}

}  // namespace hair25d::completion::test
