// The removal_sequence target's decoder and runner (fuzz/targets/removal_sequence.cpp is its
// libFuzzer entry point; `tetcut replay --target removal_sequence` calls the same run()).
//
// Input: version byte (1 to 5, sequence_target.hpp), then (FuzzedDataProvider) the mesh (version
// 1: the bundled cylinder, sheet, liver-coarse; versions 2 to 5: their small fuzz versions; 3
// reads as 2), then up to max_operations operations, each an opcode and its arguments:
//   strategy S          basic | neighbours | combined, and from version 4 wide, then from
//                       version 5 paper 3.5's set, smallest | first (the initial
//                       strategy is combined)
//   remove boundary     the first live tet with a boundary face at or after a chosen id
//   remove any          the first live tet at or after a chosen id (interior ones included)
//   remove point        the tet containing a point of the bounding box (often none: a no-op)
//   remove set          a boundary tet and up to max_operation_size - 1 face neighbours,
//                       requested one after the other
// Tets are written into the scenario as their centroid; the request removes the tet containing
// that point (Cutter::tet_containing, as `tetcut run` does). After every request: the local
// check; under combined, the request resolved. The full check every full_check_every
// operations and at the end.
// The limits per input version (SequenceLimits) are kLimits in removal_sequence_decoder.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "operations/sequence_target.hpp"

namespace tetcut::fuzz::removal_sequence {

// Runs the input; with options.record_scenario, SequenceResult::scenario is the input as a
// scenario (up to and including the operation that fails, if one does).
SequenceResult run(const std::uint8_t* data, std::size_t size, const SequenceOptions& options);

}  // namespace tetcut::fuzz::removal_sequence
