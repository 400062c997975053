// Command-line arguments of the `tetcut` subcommands: options and strictly parsed numbers.
//
// Strict because a command line is a user's input like any file: "1.5x", "", " 2", "nan" or
// "1e999" are refused with a message instead of being read as something the user did not write.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tetcut/vec3.hpp"

namespace tetcut::cli {

// A finite double written in full: no leading or trailing characters (not even spaces), no
// "nan"/"inf", no overflow to infinity.
std::optional<double> parse_double(std::string_view text);

// A non-negative integer in decimal digits only (no sign, no spaces), fitting in 64 bits.
std::optional<std::uint64_t> parse_uint(std::string_view text);

// Three finite doubles separated by commas: "X,Y,Z".
std::optional<Vec3> parse_vec3(std::string_view text);

struct OptionSpec {
  std::string_view name;  // with its dashes: "--level"
  bool takes_value = false;
};

struct ParsedArgs {
  std::vector<std::string> positionals;
  // Options in the order given; a flag has an empty value.
  std::vector<std::pair<std::string, std::string>> options;

  [[nodiscard]] bool has(std::string_view name) const;
  [[nodiscard]] std::optional<std::string> value(std::string_view name) const;
};

struct ArgParseResult {
  ParsedArgs args;
  std::string error;  // empty on success; otherwise one line for people

  [[nodiscard]] bool ok() const { return error.empty(); }
};

// Splits `args` into options (as declared in `specs`) and positionals. Accepts "--opt value" and
// "--opt=value"; "--" ends the options; a lone "-" is a positional. Refuses an unknown option, a
// missing value, a value given to a flag, and an option given twice.
ArgParseResult parse_args(std::span<const std::string> args, std::span<const OptionSpec> specs);

}  // namespace tetcut::cli
