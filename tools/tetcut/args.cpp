#include "args.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

namespace tetcut::cli {

std::optional<double> parse_double(std::string_view text) {
  if (text.empty()) return std::nullopt;
  // from_chars accepts neither a leading '+' nor spaces, which is what we want for spaces; a
  // leading '+' is common enough in coordinates to allow explicitly.
  if (text.front() == '+') {
    text.remove_prefix(1);
    if (text.empty() || text.front() == '-' || text.front() == '+') return std::nullopt;
  }
  double value = 0.0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  const auto [end, ec] = std::from_chars(first, last, value, std::chars_format::general);
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

bool ParsedArgs::has(std::string_view name) const {
  for (const auto& [key, value] : options) {
    if (key == name) return true;
  }
  return false;
}

std::optional<std::string> ParsedArgs::value(std::string_view name) const {
  for (const auto& [key, value] : options) {
    if (key == name) return value;
  }
  return std::nullopt;
}

ArgParseResult parse_args(std::span<const std::string> args, std::span<const OptionSpec> specs) {
  ArgParseResult result;
  bool options_ended = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (options_ended || arg.size() < 2 || arg[0] != '-') {
      result.args.positionals.push_back(arg);
      continue;
    }
    if (arg == "--") {
      options_ended = true;
      continue;
    }
    // "-0.5" is a number, not an option: let the command refuse or use it as a positional.
    if (parse_double(arg)) {
      result.args.positionals.push_back(arg);
      continue;
    }
    const std::size_t eq = arg.find('=');
    const std::string name = arg.substr(0, eq);
    const OptionSpec* spec = nullptr;
    for (const OptionSpec& s : specs) {
      if (s.name == name) spec = &s;
    }
    if (spec == nullptr) {
      result.error = "unknown option '" + name + "'";
      return result;
    }
    if (result.args.has(name)) {
      result.error = "option '" + name + "' given twice";
      return result;
    }
    std::string value;
    if (eq != std::string::npos) {
      if (!spec->takes_value) {
        result.error = "option '" + name + "' takes no value";
        return result;
      }
      value = arg.substr(eq + 1);
    } else if (spec->takes_value) {
      if (i + 1 == args.size()) {
        result.error = "option '" + name + "' needs a value";
        return result;
      }
      value = args[++i];
    }
    result.args.options.emplace_back(name, std::move(value));
  }
  return result;
}

}  // namespace tetcut::cli
