#include "tetcut/scenario/values.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

namespace tetcut::scenario {

std::optional<double> parse_double(std::string_view text) {
  if (text.empty()) return std::nullopt;
  // from_chars accepts neither a leading '+' nor spaces, which is what we want for spaces; a
  // leading '+' is common enough in coordinates to allow explicitly.
  if (text.front() == '+') {
    text.remove_prefix(1);
    if (text.empty() || text.front() == '-' || text.front() == '+') return std::nullopt;
  }
  double value = 0.0;
  const char* last = text.data() + text.size();
  const auto [end, ec] = std::from_chars(text.data(), last, value, std::chars_format::general);
  if (ec != std::errc{} || end != last) return std::nullopt;
  if (!std::isfinite(value)) return std::nullopt;  // "inf", "nan"
  return value;
}

std::optional<std::uint64_t> parse_uint(std::string_view text) {
  if (text.empty()) return std::nullopt;
  for (const char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
  }
  std::uint64_t value = 0;
  const char* last = text.data() + text.size();
  const auto [end, ec] = std::from_chars(text.data(), last, value, 10);
  if (ec != std::errc{} || end != last) return std::nullopt;  // overflow
  return value;
}

std::optional<Vec3> parse_vec3(std::string_view text) {
  double xyz[3] = {0.0, 0.0, 0.0};
  for (int i = 0; i < 3; ++i) {
    const std::size_t comma = text.find(',');
    const bool last = i == 2;
    if (last != (comma == std::string_view::npos)) return std::nullopt;
    const auto part = parse_double(last ? text : text.substr(0, comma));
    if (!part) return std::nullopt;
    xyz[i] = *part;
    if (!last) text.remove_prefix(comma + 1);
  }
  return Vec3{xyz[0], xyz[1], xyz[2]};
}

std::optional<CheckMode> parse_check_mode(std::string_view text) {
  if (text == "every") return CheckMode::kEvery;
  if (text == "end") return CheckMode::kEnd;
  if (text == "none") return CheckMode::kNone;
  return std::nullopt;
}

const char* to_string(CheckMode mode) {
  switch (mode) {
    case CheckMode::kEvery: return "every";
    case CheckMode::kEnd: return "end";
    case CheckMode::kNone: return "none";
  }
  return "?";
}

std::optional<invariants::CheckLevel> parse_check_level(std::string_view text) {
  if (text == "local") return invariants::CheckLevel::kLocal;
  if (text == "full") return invariants::CheckLevel::kFull;
  if (text == "exact") return invariants::CheckLevel::kExact;
  return std::nullopt;
}

const char* to_string(invariants::CheckLevel level) {
  switch (level) {
    case invariants::CheckLevel::kLocal: return "local";
    case invariants::CheckLevel::kFull: return "full";
    case invariants::CheckLevel::kExact: return "exact";
  }
  return "?";
}

}  // namespace tetcut::scenario
