// The cut_sequence target's decoder and runner (fuzz/targets/cut_sequence.cpp is its libFuzzer
// entry point; `tetcut replay --target cut_sequence` calls the same run()).
//
// Input: version byte (1 to 5, sequence_target.hpp), then (FuzzedDataProvider) the mesh (version
// 1: the bundled cylinder, sheet, liver-coarse; versions 2 to 5: their small fuzz versions), then up to
// max_operations operations, each an opcode and its arguments:
//   param       one of diameter (0.5..2 mean edge lengths), dref_factor (1..3), p (1.1..3),
//               depth (1..16), iterations (1..8), strategy, split; rounded so scenarios read well.
//               From version 3, log-uniform: diameter 0.01..10^4 mean edges, dref_factor
//               0.003..10, p 1.001..11 (two significant digits; p: of p - 1). Strategy:
//               basic, neighbours, combined, and from version 4 wide. From version 5 also
//               order (direct-first, surface-first-by-id, revisit) and neighbour_set
//               (smallest, first): the paper's readings (cut_strategies.hpp).
//   cut point   a point of the bounding box grown by 10 %
//   cut surface a boundary tet's centroid moved by up to a tool radius on each axis
//   sweep       from such a point along a direction, 0.5..4 diameters long, 1..8 steps (at
//               most max_operation_size + 1 cuts)
// Every cut goes through Cutter::cut, followed by the local check; under combined every tet it
// selects is resolved; a rolled back cut leaves the canonical hash as it was (and is written
// into the scenario as a comment, since the mesh is as if it had not happened). The full check
// every full_check_every operations and at the end.
// The limits per input version (SequenceLimits) are kLimits in cut_sequence_decoder.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "operations/sequence_target.hpp"

namespace tetcut::fuzz::cut_sequence {

// Runs the input; with options.record_scenario, SequenceResult::scenario is the input as a
// scenario (up to and including the operation that fails, if one does).
SequenceResult run(const std::uint8_t* data, std::size_t size, const SequenceOptions& options);

}  // namespace tetcut::fuzz::cut_sequence
