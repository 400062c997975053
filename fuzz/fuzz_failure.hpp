// How a fuzz target reports a broken property: one line on stderr, then std::abort(), so that
// libFuzzer keeps the input as a crash and the line names what broke.
//
//   tetcut-fuzz: I5 violated after operation 7 (split): vertex 12: link is an annulus
//
// The first word after "tetcut-fuzz:" is the property's id (an invariant I1-I9 of the design, or
// one of the harness's own: reader-contract, round-trip, interpolation, checker-differential,
// refused-split); ci/fuzz-nightly deduplicates crashes by it and by the top stack frames, and
// reads the operation's index and name from the same line.
#pragma once

#include <cstddef>
#include <string_view>

namespace tetcut::fuzz {

[[noreturn]] void fail(std::string_view property, std::size_t operation_index, std::string_view operation,
                       std::string_view detail);

}  // namespace tetcut::fuzz
