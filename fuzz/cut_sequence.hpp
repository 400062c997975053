// The cut_sequence target's decoder and runner (fuzz/targets/cut_sequence.cpp is its libFuzzer
// entry point; `tetcut replay --target cut_sequence` calls the same run()).
//
// Input: version byte, then (FuzzedDataProvider) the bundled mesh (cylinder, sheet, liver-coarse),
// then up to kMaxOperations operations, each an opcode and its arguments:
//   param       one of diameter (0.5..2 mean edge lengths), dref_factor (1..3), p (1.1..3),
//               depth (1..16), iterations (1..8), strategy, split; rounded so scenarios read well
//   cut point   a point of the bounding box grown by 10 %
//   cut surface a boundary tet's centroid moved by up to a tool radius on each axis
//   sweep       from such a point along a direction, 0.5..4 diameters long, 1..8 steps
// Every cut goes through Cutter::cut, followed by the local check; under combined every tet it
// selects is resolved; a rolled back cut leaves the canonical hash as it was (and is written
// into the scenario as a comment, since the mesh is as if it had not happened). The full check
// every kFullCheckEvery operations and at the end.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "sequence_support.hpp"

namespace tetcut::fuzz::cut_sequence {

inline constexpr std::size_t kMaxOperations = 24;
inline constexpr std::size_t kFullCheckEvery = 16;
// The sequence ends once the mesh has grown beyond this many times its initial tets: repeated
// refinement around small tools multiplies the tets (a cut on 45 000 tets took 50 s in Release),
// and executions per second are what finds bugs. It ends the input as the scenario ends.
inline constexpr std::uint32_t kMaxTetsFactor = 3;
inline constexpr std::uint64_t kMaxSweepSteps = 8;

SequenceResult run(const std::uint8_t* data, std::size_t size, const SequenceOptions& options);
// The input as a scenario (up to and including the operation that fails, if one does).
std::string decode_to_scenario(const std::uint8_t* data, std::size_t size);

}  // namespace tetcut::fuzz::cut_sequence
