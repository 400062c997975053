// Fuzz target removal_sequence: what an input means and what is checked is in fuzz/operations/removal_sequence_decoder.hpp.
// The decoding and the checks live there, shared with `tetcut replay --target removal_sequence`, which
// prints the same input as a scenario. With -engine=LIB it fuzzes another engine's adapter
// instead (engines/engine_mode.hpp).
#include <cstddef>
#include <cstdint>

#include "engines/engine_mode.hpp"
#include "operations/removal_sequence_decoder.hpp"

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  tetcut::fuzz::engine_mode_init(argc, argv, "removal_sequence");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (tetcut::fuzz::engine_mode_on()) {
    tetcut::fuzz::run_engine_input(data, size);
    return 0;
  }
  static const tetcut::fuzz::SequenceOptions options{.legacy_versions = tetcut::fuzz::legacy_versions_from_env()};
  tetcut::fuzz::removal_sequence::run(data, size, options);
  return 0;
}
