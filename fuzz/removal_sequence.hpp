// The removal_sequence target's decoder and runner (fuzz/targets/removal_sequence.cpp is its
// libFuzzer entry point; `tetcut replay --target removal_sequence` calls the same run()).
//
// Input: version byte, then (FuzzedDataProvider) the bundled mesh (cylinder, sheet, liver-coarse),
// then up to kMaxOperations operations, each an opcode and its arguments:
//   strategy S          basic | neighbours | combined (the initial strategy is combined)
//   remove boundary     the first live tet with a boundary face at or after a chosen id
//   remove any          the first live tet at or after a chosen id (interior ones included)
//   remove point        the tet containing a point of the bounding box (often none: a no-op)
//   remove set          a boundary tet and up to 5 face neighbours, requested one after the other
// Tets are written into the scenario as their centroid; the request removes the tet containing
// that point (Cutter::tet_containing, as `tetcut run` does). After every request: the local
// check; under combined, the request resolved. The full check every kFullCheckEvery operations
// and at the end.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "sequence_support.hpp"

namespace tetcut::fuzz::removal_sequence {

inline constexpr std::size_t kMaxOperations = 24;
inline constexpr std::size_t kFullCheckEvery = 16;
// The sequence ends once the mesh has grown beyond this many times its initial tets: repeated
// refinement around small tools multiplies the tets (a cut on 45 000 tets took 50 s in Release),
// and executions per second are what finds bugs. It ends the input as the scenario ends.
inline constexpr std::uint32_t kMaxTetsFactor = 3;
inline constexpr std::uint32_t kMaxSetSize = 6;

SequenceResult run(const std::uint8_t* data, std::size_t size, const SequenceOptions& options);
// The input as a scenario (up to and including the operation that fails, if one does).
std::string decode_to_scenario(const std::uint8_t* data, std::size_t size);

}  // namespace tetcut::fuzz::removal_sequence
