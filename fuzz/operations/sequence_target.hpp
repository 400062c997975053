// A sequence fuzz target (removal_sequence, cut_sequence) as its entry point, `tetcut replay`
// and the tests call it: what the input's first byte means, what the caller asks of a run, what
// the run reports, and the table of the targets by name.
//
// The decoded input is recorded while it runs (scenario_recorder.hpp): a choice such as "the
// first boundary tet at or after id k" depends on the mesh the earlier operations left, so
// decoding and running are one pass. Tets are written as a point (their centroid, to the last
// bit), never as an id, as scenarios address them (Cutter::tet_containing); the targets then
// remove the tet containing that point, exactly as `tetcut run` does. Each target's decoder
// (cut_sequence_decoder.hpp, removal_sequence_decoder.hpp) says what its operations are.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "support/fuzz_failure.hpp"

namespace tetcut::fuzz {

// The sequence targets' input versions (the first byte; mixed_ops and checker_differential keep
// kInputVersion). What a version means never changes, so that every stored input replays as it
// was found:
//   1  the bundled meshes of corpus/meshes (3,350-4,100 tets), up to 24 operations;
//   2  the small fuzz meshes of corpus/fuzz/meshes (238-395 tets, made by the same generators),
//      fewer operations. On a bundled mesh the O(#T) parts of an input (copying the mesh, the
//      Cutter's index, the full check) were nine tenths of its time.
//   3  as 2, but cut_sequence draws the tool diameter, the D_ref factor and p from wide
//      log-uniform ranges, as users mistype them (a 1e6 tool or a D_ref factor of 0.01
//      hung a cut, and the narrow ranges of version 2 never tried them). removal_sequence,
//      which sets none of them, reads 3 as 2.
//   4  as 3, but both targets draw the removal strategy among all four: `wide` too (the
//      extension of paper 3.5 in remove/wide_search.cpp), which versions 1-3 never drew.
//   5  as 4, but the paper's readings are drawn too (cut_strategies.hpp): cut_sequence's
//      parameters include the removal order (direct-first, surface-first-by-id, revisit) and
//      3.5's set (smallest, first); removal_sequence's strategy operation draws 3.5's set after
//      the strategy. Versions 1-4 never drew them.
//   6  as 5, but cut_sequence's sweeps may be swept (`sweep A B STEP swept`: the samples joined
//      by capsules, Cutter::cut_segment), drawn after the sweep's pieces. Versions 1-5 never
//      drew it; removal_sequence reads 6 as 5.
// The fuzzers run versions 2 to 6 (is_current_sequence_version); 1 only replays.
inline constexpr std::uint8_t kSequenceVersionBundled = 1;
inline constexpr std::uint8_t kSequenceVersionSmall = 2;
inline constexpr std::uint8_t kSequenceVersionWideParams = 3;
inline constexpr std::uint8_t kSequenceVersionAllStrategies = 4;
inline constexpr std::uint8_t kSequenceVersionReadings = 5;
inline constexpr std::uint8_t kSequenceVersionSwept = 6;
inline constexpr std::uint8_t kSequenceVersion = kSequenceVersionSwept;  // the newest
inline bool is_sequence_version(std::uint8_t v) { return v >= kSequenceVersionBundled && v <= kSequenceVersion; }
inline bool is_current_sequence_version(std::uint8_t v) { return v >= kSequenceVersionSmall && v <= kSequenceVersion; }

// How much of an input a sequence target runs: up to max_operations operations, with the full
// check every full_check_every of them and at the end, and the target's own bound on one
// operation (removal_sequence: the tets of a set; cut_sequence: the cuts of a sweep).
struct SequenceLimits {
  std::size_t max_operations;
  std::size_t full_check_every;
  std::uint32_t max_operation_size;
};
// A target's limits per input version. Version 1 as it was found; version 2 bounds an input's
// cost (executions per second are what find bugs). The mesh may also grow to kMaxTetsFactor
// times its tets.
struct VersionedLimits {
  SequenceLimits bundled;  // kSequenceVersionBundled
  SequenceLimits small;    // the later versions
  [[nodiscard]] constexpr const SequenceLimits& of(std::uint8_t version) const {
    return version == kSequenceVersionBundled ? bundled : small;
  }
};
// The sequence also ends once the mesh has grown beyond this many times its initial tets:
// repeated refinement around small tools multiplies the tets (a cut on 45 000 tets took 50 s in
// Release), and executions per second are what finds bugs. It ends the input as the scenario ends.
inline constexpr std::uint32_t kMaxTetsFactor = 3;

// What a sequence target does with an input.
struct SequenceOptions {
  bool record_scenario = false;   // fill SequenceResult::scenario
  bool capture_failures = false;  // a finding becomes SequenceResult::finding instead of abort()
  // false: only the small-mesh versions (is_current_sequence_version) are accepted.
  // ci/fuzz-nightly fuzzes so (legacy_versions_from_env):
  // a version 1 input is an order of magnitude slower (its mesh is ten times larger), and
  // libFuzzer gave most of its time to the version 1 seeds and their mutants; ctest and
  // `tetcut replay` still run every version.
  bool legacy_versions = true;
};

// SequenceOptions::legacy_versions for the fuzz targets: false when
// TETCUT_FUZZ_CURRENT_VERSION_ONLY is set to anything but "" or "0".
bool legacy_versions_from_env();

struct SequenceResult {
  bool accepted = false;          // false: not one of this target's version bytes (nothing ran)
  std::uint8_t version = 0;       // the input's version byte, when accepted
  std::string scenario;           // when recorded: up to the failing operation when there is one
  std::optional<Finding> finding; // when captured
  std::uint32_t finding_line = 0; // the scenario line of the failing operation (0: none)
  std::uint64_t final_hash = 0;   // when recorded and no finding: the final mesh's canonical hash
};

// One sequence target, for the command line and the tests.
struct SequenceTarget {
  std::string_view name;
  SequenceResult (*run)(const std::uint8_t* data, std::size_t size, const SequenceOptions& options);
};

std::span<const SequenceTarget> sequence_targets();
const SequenceTarget* find_sequence_target(std::string_view name);

}  // namespace tetcut::fuzz
