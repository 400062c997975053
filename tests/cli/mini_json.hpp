// A small strict JSON reader for the tests: proves that tetcut's --json output is valid JSON
// and lets a test look values up by key instead of matching text.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tetcut::test {

struct Json {
  enum class Kind { kNull, kBool, kNumber, kString, kArray, kObject };
  Kind kind = Kind::kNull;
  bool boolean = false;
  double number = 0.0;
  std::string text;  // the string's content (escapes resolved, \u00XX only)
  std::vector<Json> items;
  std::vector<std::pair<std::string, Json>> members;

  // The member `key` of an object, or nullptr.
  [[nodiscard]] const Json* get(std::string_view key) const;
};

// The whole of `text` as one JSON value (surrounding whitespace allowed), or nothing.
std::optional<Json> parse_json(std::string_view text);

}  // namespace tetcut::test
