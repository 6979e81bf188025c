#include "json_read.h"

#include <algorithm>
#include <cmath>

namespace hair25d::json_read {

namespace {

// The deepest nesting of arrays and objects outside strings, stopping at the
// first level beyond `limit`. nlohmann::json parses deep nesting fine but
// prints and copies it recursively: a file of 200000 '[' crashed the reader
// (stack overflow) when an error message showed the value.
int nesting_depth(const std::string& text, int limit) {
  int depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
      if (deepest > limit) break;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return deepest;
}

}  // namespace

json parse(const std::string& text, const std::string& source) {
  const int depth = nesting_depth(text, kMaxDepth);
  if (depth > kMaxDepth) {
    throw Error(source + ": arrays and objects nested more than " + std::to_string(kMaxDepth) +
                " levels deep; at most " + std::to_string(kMaxDepth) + " are allowed");
  }
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    throw Error(source + ": not valid JSON (" + e.what() + ")");
  } catch (const json::exception& e) {
    // e.g. out_of_range.406 for a number beyond double ("1e999").
    throw Error(source + ": not valid JSON (" + e.what() + ")");
  }
}

void fail(const std::string& source, const std::string& key, const std::string& expected,
          const json* got) {
  std::string message = source + ": key '" + key + "': expected " + expected;
  if (got != nullptr && got->is_structured() && got->size() > 16) {
    // Not printed whole: it may be most of a large file.
    message += ", got " + std::string(got->is_array() ? "an array of " : "an object of ") +
               std::to_string(got->size()) + (got->is_array() ? " values" : " keys");
  } else if (got != nullptr) {
    std::string shown = got->dump();
    if (shown.size() > 60) shown = shown.substr(0, 57) + "...";
    message += ", got " + shown;
  } else {
    message += ", but it is missing";
  }
  throw Error(message);
}

std::string join(const std::string& parent, const char* key) {
  return parent.empty() ? std::string(key) : parent + "." + key;
}

std::string index(const std::string& parent, std::size_t i) {
  return parent + "[" + std::to_string(i) + "]";
}

void expect_object(const json& value, const std::string& source, const std::string& key) {
  if (!value.is_object()) fail(source, key.empty() ? "(top level)" : key, "an object", &value);
}

void expect_array(const json& value, const std::string& source, const std::string& key) {
  if (!value.is_array()) fail(source, key, "an array", &value);
}

const json& member(const json& object, const std::string& source, const std::string& path,
                   const char* key) {
  const auto it = object.find(key);
  if (it == object.end()) fail(source, join(path, key), "a value", nullptr);
  return *it;
}

const json* optional_member(const json& object, const std::string&, const std::string&,
                            const char* key) {
  const auto it = object.find(key);
  if (it == object.end() || it->is_null()) return nullptr;
  return &*it;
}

int as_int(const json& value, const std::string& source, const std::string& key) {
  if (value.is_number_integer()) {
    const auto v = value.get<long long>();
    if (v >= -2147483647LL && v <= 2147483647LL) return static_cast<int>(v);
  } else if (value.is_number_float()) {
    const double v = value.get<double>();
    if (std::isfinite(v) && v == std::floor(v) && std::abs(v) < 2147483647.0)
      return static_cast<int>(v);
  }
  fail(source, key, "an integer", &value);
}

double as_number(const json& value, const std::string& source, const std::string& key) {
  if (value.is_number()) {
    const double v = value.get<double>();
    if (std::isfinite(v)) return v;
  }
  fail(source, key, "a finite number", &value);
}

std::string as_string(const json& value, const std::string& source, const std::string& key) {
  if (!value.is_string()) fail(source, key, "a string", &value);
  return value.get<std::string>();
}

bool as_bool(const json& value, const std::string& source, const std::string& key) {
  if (!value.is_boolean()) fail(source, key, "true or false", &value);
  return value.get<bool>();
}

Vec2 as_point(const json& value, const std::string& source, const std::string& key) {
  if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number()) {
    fail(source, key, "a point [x, y] of two numbers", &value);
  }
  const double x = value[0].get<double>(), y = value[1].get<double>();
  if (!std::isfinite(x) || !std::isfinite(y)) fail(source, key, "finite coordinates", &value);
  return {x, y};
}

}  // namespace hair25d::json_read
