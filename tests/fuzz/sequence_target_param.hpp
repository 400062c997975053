// The sequence targets as a gtest parameter, so that a test over them runs once per target of
// sequence_targets():
//   INSTANTIATE_TEST_SUITE_P(Targets, Suite, testing::ValuesIn(tetcut::fuzz::sequence_targets()),
//                            sequence_target_name);
#pragma once

#include <gtest/gtest.h>

#include <ostream>
#include <string>

#include "operations/sequence_target.hpp"

namespace tetcut::fuzz {
// gtest prints a parameter into the test's description: the name, not the struct's bytes.
inline void PrintTo(const SequenceTarget& target, std::ostream* os) { *os << target.name; }
}  // namespace tetcut::fuzz

inline std::string sequence_target_name(const testing::TestParamInfo<tetcut::fuzz::SequenceTarget>& info) {
  return std::string(info.param.name);
}
