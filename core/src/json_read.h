// Strict reading of JSON files: every error names the file, the key path
// ("strokes[2].width") and what was expected.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "hair25d/core/error.h"
#include "hair25d/core/geometry.h"

namespace hair25d::json_read {

using nlohmann::json;

// Arrays and objects nested deeper than this are refused: the project's
// files nest at most 5 deep (model.json's mesh vertices).
inline constexpr int kMaxDepth = 64;

// Parses text; throws Error naming `source` on a syntax error, a number
// beyond double, or nesting deeper than kMaxDepth.
json parse(const std::string& text, const std::string& source);

[[noreturn]] void fail(const std::string& source, const std::string& key,
                       const std::string& expected, const json* got);

const json& member(const json& object, const std::string& source, const std::string& path,
                   const char* key);
const json* optional_member(const json& object, const std::string& source, const std::string& path,
                            const char* key);
void expect_object(const json& value, const std::string& source, const std::string& key);
void expect_array(const json& value, const std::string& source, const std::string& key);
int as_int(const json& value, const std::string& source, const std::string& key);
double as_number(const json& value, const std::string& source, const std::string& key);
std::string as_string(const json& value, const std::string& source, const std::string& key);
bool as_bool(const json& value, const std::string& source, const std::string& key);
Vec2 as_point(const json& value, const std::string& source, const std::string& key);

// "parent" + ".key" or "key" when parent is empty; "parent[i]".
std::string join(const std::string& parent, const char* key);
std::string index(const std::string& parent, std::size_t i);

}  // namespace hair25d::json_read
