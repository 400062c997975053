// Fuzz target cut_sequence: what an input means and what is checked is in fuzz/operations/cut_sequence_decoder.hpp.
// The decoding and the checks live there, shared with `tetcut replay --target cut_sequence`, which
// prints the same input as a scenario.
#include <cstddef>
#include <cstdint>

#include "operations/cut_sequence_decoder.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const tetcut::fuzz::SequenceOptions options{.legacy_versions = tetcut::fuzz::legacy_versions_from_env()};
  tetcut::fuzz::cut_sequence::run(data, size, options);
  return 0;
}
