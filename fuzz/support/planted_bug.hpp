// A bug planted on purpose, and switched off: the tests of triage (tests/ci/bisect_planted_test.sh)
// copy the repository into a throw-away history, switch it on in one commit, and check that
// `ci/bisect` and `ci/fuzz-nightly` name that commit as the first bad one. A constant in one
// small header, so that each bisection step there rebuilds one file (reader_contract.cpp).
// When on, every tet format target (fuzz_tet_reader: msh22, vtu, ...) fails ("planted-bug") on an
// input holding the marker.
#pragma once

#include <string_view>

namespace tetcut::fuzz {

inline constexpr bool kPlantedReaderBug = false;
inline constexpr std::string_view kPlantedBugMarker = "TETCUT-PLANTED-BUG";

}  // namespace tetcut::fuzz
