// Fuzz input bytes as operations any engine can carry out (engine.h): the engine sequence
// targets. tetcut's own sequence targets (fuzz/operations/) decode their inputs while tetcut
// runs them (a choice there depends on the mesh tetcut left); an engine's state is not the
// harness's to read while decoding, so these inputs mean the same operations whatever the
// engine: every point and diameter is fixed by the bytes and the mesh they choose.
//
// Input, version 1:
//   byte 0      the version (1); another version is not accepted (an empty plan)
//   byte 1      the mesh: one of the small fuzz meshes (corpus/fuzz/meshes), by index modulo
//   then operations, each an opcode byte and its arguments, until the bytes end or
//   kMaxEngineOperations operations (a missing argument byte reads as 0):
//   cut_sequence      opcode % 4: 0, 1 a ball; 2 a capsule; 3 a sweep (balls, or capsules when
//                     its last byte is odd, at most kMaxSweepCuts of them)
//                     a point is 3 x 2 bytes, each coordinate across the mesh's bounding box
//                     widened by a tenth on each side; a diameter is 1 byte, log-uniform from a
//                     quarter to 4 median edge lengths; a sweep's step 1 byte, from a quarter to
//                     one diameter
//   removal_sequence  2 bytes: tet k (modulo the mesh's tets) of the mesh as loaded; the
//                     operation removes the live tet holding its centroid then (none: missed)
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tetcut/harness/engine_plan.hpp"

namespace tetcut::harness {

enum class EngineTarget : std::uint8_t { kCutSequence, kRemovalSequence };

inline constexpr std::uint8_t kEngineInputVersion = 1;
inline constexpr std::size_t kMaxEngineOperations = 24;
inline constexpr std::size_t kMaxSweepCuts = 16;

// "cut_sequence", "removal_sequence".
std::string_view target_name(EngineTarget target);
std::optional<EngineTarget> engine_target(std::string_view name);

struct FuzzMesh {
  std::string path;  // absolute, for the scenarios a finding is written as
  RawMesh mesh;
};

// The small fuzz meshes of `corpus_dir`/fuzz/meshes, in name order. Throws std::runtime_error
// ("FILE:LINE: reason") for one it cannot read.
std::vector<FuzzMesh> load_fuzz_meshes(const std::string& corpus_dir);

// The plan an input means; an input of another version, or without a mesh byte, is an empty
// plan without a mesh (nothing to run).
EnginePlan decode_engine_input(std::span<const std::uint8_t> bytes, EngineTarget target,
                               const std::vector<FuzzMesh>& meshes);

}  // namespace tetcut::harness
