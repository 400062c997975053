// The values a person writes, in a scenario file or on the `tetcut` command line: numbers,
// points, removal strategy, split method, check mode and check level. Parsed here once, so that
// `strategy wide` in a scenario and `--strategy wide` on the command line cannot come to mean
// different things.
//
// Numbers are strict because they are a user's input like any file: "1.5x", "", " 2", "nan",
// "0x10" or "1e999" are refused instead of being read as something the user did not write.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "tetcut/cut_strategies.hpp"
#include "tetcut/invariants/check.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::scenario {

// A finite double written in full: no leading or trailing characters (not even spaces), no
// "nan"/"inf", no overflow to infinity, no hexadecimal. A leading '+' is allowed.
std::optional<double> parse_double(std::string_view text);

// A non-negative integer in decimal digits only (no sign, no spaces), fitting in 64 bits.
std::optional<std::uint64_t> parse_uint(std::string_view text);

// Three finite doubles separated by commas: "X,Y,Z".
std::optional<Vec3> parse_vec3(std::string_view text);

// basic | neighbours | combined | wide: the engine's own parser (parse_removal_strategy),
// named here so that every value of this file is found in one place.
inline std::optional<RemovalStrategy> parse_strategy(std::string_view text) { return parse_removal_strategy(text); }

// templates | bisection (paper 3.2: the 10 split configurations, or sequential bisection):
// the engine's parse_split_method and to_string(SplitMethod), cut_strategies.hpp.
// paper | graded (the refinement rule): parse_refinement_rule, to_string(RefinementRule), there too.

// When the independent checker runs during a sequence of operations: the local checker after
// every operation, the full one once at the end, or not at all.
enum class CheckMode : std::uint8_t { kEvery, kEnd, kNone };
std::optional<CheckMode> parse_check_mode(std::string_view text);
const char* to_string(CheckMode mode);

// local | full | exact: how deep one check goes (invariants::CheckLevel).
std::optional<invariants::CheckLevel> parse_check_level(std::string_view text);
const char* to_string(invariants::CheckLevel level);

}  // namespace tetcut::scenario
