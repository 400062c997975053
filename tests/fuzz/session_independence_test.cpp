// The sequence targets keep one session per bundled mesh for the whole process and reset it for
// each input (fuzzer throughput). libFuzzer, `tetcut replay` and ctest's corpus replay
// all run many inputs in one process, so a state left behind by one input would make another
// behave differently than it does alone: a crash that does not reproduce. These tests run the
// stored inputs in two orders and require every input to end the same way: same scenario, same
// finding (or none), same final mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "operations/sequence_target.hpp"
#include "sequence_target_param.hpp"

namespace {

namespace fs = std::filesystem;
using tetcut::fuzz::SequenceOptions;
using tetcut::fuzz::SequenceResult;
using tetcut::fuzz::SequenceTarget;

std::vector<std::vector<std::uint8_t>> stored_inputs(std::string_view target) {
  std::vector<fs::path> files;
  for (const char* folder : {"fuzz", "regressions"}) {
    const fs::path dir = fs::path(TETCUT_CORPUS_DIR) / folder / target;
    if (!fs::is_directory(dir)) continue;
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.is_regular_file() && entry.path().filename().string().front() != '.') files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<std::vector<std::uint8_t>> inputs;
  for (const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    inputs.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return inputs;
}

struct Outcome {
  bool accepted;
  std::string scenario;
  std::string finding;
  std::uint64_t final_hash;
  bool operator==(const Outcome&) const = default;
};

Outcome run(const SequenceTarget& target, const std::vector<std::uint8_t>& input) {
  SequenceOptions options;
  options.record_scenario = true;
  options.capture_failures = true;
  const SequenceResult r = target.run(input.data(), input.size(), options);
  return {r.accepted, r.scenario, r.finding ? to_string(*r.finding) : std::string(), r.final_hash};
}

// Every sequence target (sequence_targets()).
class SequenceSession : public testing::TestWithParam<tetcut::fuzz::SequenceTarget> {};

TEST_P(SequenceSession, StoredInputsEndTheSameInAnyOrder) {
  const SequenceTarget& target = GetParam();
  const std::string_view name = target.name;
  const auto inputs = stored_inputs(name);
  ASSERT_GE(inputs.size(), 10u) << "too few stored inputs of " << name << " to mean anything";
  std::vector<Outcome> forward;
  for (const auto& input : inputs) forward.push_back(run(target, input));
  std::size_t ran = 0;
  for (std::size_t i = inputs.size(); i-- > 0;) {
    const Outcome backward = run(target, inputs[i]);
    EXPECT_TRUE(backward == forward[i]) << name << " input " << i << " ends differently after other inputs:\n"
                                        << "forward: " << forward[i].finding << " hash " << forward[i].final_hash
                                        << "\nbackward: " << backward.finding << " hash " << backward.final_hash;
    if (backward.accepted && backward.final_hash != 0) ++ran;
  }
  // The comparison means something only if inputs ran to the end and were hashed.
  EXPECT_GE(ran, inputs.size() / 2) << name << ": most inputs were not run to a final mesh";
}

INSTANTIATE_TEST_SUITE_P(Targets, SequenceSession, testing::ValuesIn(tetcut::fuzz::sequence_targets()), sequence_target_name);

}  // namespace
