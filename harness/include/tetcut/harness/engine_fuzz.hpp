// Fuzzing any engine through its adapter: the shipped seeds of an engine sequence target
// (corpus/fuzz/engines/<target>/, engine_input.hpp says what their bytes mean), mutated by a
// seeded generator, each input decoded into a plan and checked in a child process
// (engine_check.hpp). A new kind of failure (a signature not seen before in the run) is
// minimized and written as a regression (engine_regression.hpp).
//
// Deterministic: the same adapter, seed and run count give the same inputs, findings and files.
// It is a mutation fuzzer without coverage feedback: it finds what an engine breaks on ordinary
// cuts (the demonstration: blind removal's singular vertices), not deep paths.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tetcut/harness/engine_check.hpp"
#include "tetcut/harness/engine_input.hpp"

namespace tetcut::harness {

inline constexpr std::size_t kMaxEngineInputSize = 512;

struct EngineFuzzOptions {
  EngineTarget target = EngineTarget::kCutSequence;
  std::uint64_t seed = 1;
  std::uint64_t runs = 100;        // inputs tried, the seeds first
  std::string corpus_dir;          // its fuzz/meshes and fuzz/engines/<target>/ seeds
  std::string regressions_dir;     // findings go to <this>/<engine>/<target>/; "" writes none
  EngineCheckOptions check;
};

struct EngineFinding {
  std::uint64_t run = 0;             // the input that found it (0-based)
  std::string signature;             // signature_of() its check
  std::string first_operation;       // the operation the failure came at, as first found
  std::size_t operations = 0;        // in the input's plan
  std::size_t minimized_operations = 0;
  std::uint64_t minimize_checks = 0;
  std::string scenario;              // the minimized plan as a scenario file
  std::string path;                  // where it was written ("" when not)
};

struct EngineFuzzResult {
  std::uint64_t runs = 0;            // inputs checked (an input that decodes to nothing is not)
  std::uint64_t failing = 0;         // inputs whose check failed, every signature
  std::vector<EngineFinding> findings;  // one per signature, in the order found
  double seconds = 0.0;              // wall time, minimization included
};

// The bytes of `input` mutated 1 to 4 times (a bit flipped, a byte set, inserted or erased, a
// span copied, the tail of another seed spliced in); the version byte is kept.
std::vector<std::uint8_t> mutate(const std::vector<std::uint8_t>& input, const std::vector<std::vector<std::uint8_t>>& seeds,
                                 std::uint64_t& random_state);

// The seeds of a target: every file in `corpus_dir`/fuzz/engines/<target>/, in name order.
std::vector<std::vector<std::uint8_t>> load_engine_seeds(const std::string& corpus_dir, EngineTarget target);

EngineFuzzResult fuzz_engine(const AdapterInfo& adapter, const EngineFuzzOptions& options);

}  // namespace tetcut::harness
