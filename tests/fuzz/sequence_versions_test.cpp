// What a sequence input's version byte means (fuzz/operations/sequence_target.hpp): version 4
// draws the `wide` strategy, which versions 1-3 never drew, and a version 3 input still decodes
// as it was found. Random inputs, the same bytes after the version byte for 3 and 4: under 3 no
// scenario sets `strategy wide`; under 4 some do, and every input runs to its end without a
// finding (the local check after every operation, the full check at the end).
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "operations/sequence_target.hpp"
#include "sequence_target_param.hpp"

namespace {

using tetcut::fuzz::SequenceOptions;
using tetcut::fuzz::SequenceResult;

struct Tally {
  std::size_t accepted = 0, wide = 0, findings = 0;
  std::string first_finding;
};

Tally run_random_inputs(const tetcut::fuzz::SequenceTarget& target, std::uint8_t version, std::size_t count) {
  Tally tally;
  std::mt19937 random(20261124);  // the same bytes for every version
  std::uniform_int_distribution<int> byte(0, 255);
  SequenceOptions options;
  options.record_scenario = true;
  options.capture_failures = true;
  for (std::size_t i = 0; i < count; ++i) {
    std::vector<std::uint8_t> input(48);
    for (std::uint8_t& b : input) b = static_cast<std::uint8_t>(byte(random));
    input[0] = version;
    const SequenceResult r = target.run(input.data(), input.size(), options);
    tally.accepted += r.accepted ? 1 : 0;
    if (r.scenario.find("\nstrategy wide\n") != std::string::npos) ++tally.wide;
    if (r.finding) {
      if (tally.findings++ == 0) tally.first_finding = r.scenario;
    }
  }
  return tally;
}

// Every sequence target (sequence_targets()).
class SequenceVersions : public testing::TestWithParam<tetcut::fuzz::SequenceTarget> {};

TEST_P(SequenceVersions, Version4DrawsWideAndVersion3DecodesAsFound) {
  const std::string_view name = GetParam().name;
  constexpr std::size_t kInputs = 400;
  const Tally v3 = run_random_inputs(GetParam(), 3, kInputs);
  const Tally v4 = run_random_inputs(GetParam(), 4, kInputs);
  EXPECT_EQ(v3.accepted, kInputs) << name;
  EXPECT_EQ(v4.accepted, kInputs) << name;
  EXPECT_EQ(v3.wide, 0u) << name << ": a version 3 input chose the wide strategy, so it no longer decodes as found";
  EXPECT_GT(v4.wide, 0u) << name << ": no version 4 input of " << kInputs << " chose the wide strategy";
  EXPECT_EQ(v3.findings + v4.findings, 0u) << name << ": first finding:\n" << v3.first_finding << v4.first_finding;
}

INSTANTIATE_TEST_SUITE_P(Targets, SequenceVersions, testing::ValuesIn(tetcut::fuzz::sequence_targets()), sequence_target_name);

}  // namespace
