// What the sequence targets (removal_sequence, cut_sequence) share: the bundled meshes they start
// from, the scenario text they can write of what they decoded (tools/scenario's format, so that
// `tetcut replay` shows an input as something `tetcut run` and `tetcut minimize` take), and the
// one entry point both the fuzz target and the command line call.
//
// The decoded input is recorded while it runs: a choice such as "the first boundary tet at or
// after id k" depends on the mesh the earlier operations left, so decoding and running are one
// pass. Tets are written as a point (their centroid, to the last bit), never as an id, as
// scenarios address them (Cutter::tet_containing); the targets then remove the tet containing
// that point, exactly as `tetcut run` does.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "operations/mesh_edits.hpp"
#include "support/fuzz_failure.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::fuzz {

// The sequence targets' input versions (the first byte; mixed_ops and checker_differential keep
// kInputVersion). What a version means never changes, so that every stored input replays as it
// was found:
//   1  the bundled meshes of corpus/meshes (3,350-4,100 tets), up to 24 operations;
//   2  the small fuzz meshes of corpus/fuzz/meshes (238-395 tets, made by the same generators),
//      fewer operations. On a bundled mesh the O(#T) parts of an input (copying the mesh, the
//      Cutter's index, the full check) were nine tenths of its time.
//   3  as 2, but cut_sequence draws the tool diameter, the D_ref factor and p from wide
//      log-uniform ranges, as users mistype them (issue 16: a 1e6 tool or a D_ref factor of 0.01
//      hung a cut, and the narrow ranges of version 2 never tried them). removal_sequence,
//      which sets none of them, reads 3 as 2.
// The fuzzers run versions 2 and 3 (is_current_sequence_version); 1 only replays.
inline constexpr std::uint8_t kSequenceVersionBundled = 1;
inline constexpr std::uint8_t kSequenceVersionSmall = 2;
inline constexpr std::uint8_t kSequenceVersion = 3;
inline bool is_sequence_version(std::uint8_t v) { return v >= kSequenceVersionBundled && v <= kSequenceVersion; }
inline bool is_current_sequence_version(std::uint8_t v) { return v == kSequenceVersionSmall || v == kSequenceVersion; }

// The meshes an input chooses from with one value, per version.
inline constexpr std::array<std::string_view, 3> kBundledMeshes = {"cylinder.msh", "sheet.msh", "liver-coarse.msh"};
inline constexpr std::array<std::string_view, 3> kFuzzMeshes = {"cylinder-small.msh", "sheet-small.msh",
                                                                "liver-small.msh"};
inline constexpr std::size_t kSequenceMeshCount = 3;

struct BundledMesh {
  std::string path;        // absolute
  TetMesh mesh;
  Box box;
  double mean_edge = 1.0;
};

// The folder of the bundled meshes: $TETCUT_MESH_DIR when set, else corpus/meshes of the source
// tree the harness was built from, else tetcut_meshes/ next to the executable (OSS-Fuzz).
std::string sequence_mesh_dir();
// The folder of the small fuzz meshes: $TETCUT_FUZZ_MESH_DIR when set, else corpus/fuzz/meshes
// of the source tree, else tetcut_meshes/ next to the executable (OSS-Fuzz).
std::string fuzz_mesh_dir();
// Mesh `index` (mod kSequenceMeshCount) of input version `version`, read and built once per
// process, then copied per input. An unreadable or invalid mesh is a harness failure
// ("bundled-mesh").
const BundledMesh& sequence_mesh(std::uint8_t version, std::size_t index);

// Shortest text that reads back as the same double ("0.1", "2.5e-05"); "X,Y,Z" for points.
std::string format_number(double x);
std::string format_point(const Vec3& p);
// x rounded to a multiple of `quantum` (a power of ten), so that scenarios read well.
double round_to(double x, double quantum);
// The power of ten nearest below diagonal / 10^digits: the quantum coordinates are rounded to.
double coordinate_quantum(double diagonal, int digits);

// The scenario text being written, and which line each operation of the run came from.
class ScenarioRecorder {
 public:
  explicit ScenarioRecorder(bool enabled) : enabled_(enabled) {}
  [[nodiscard]] bool enabled() const { return enabled_; }
  // Appends a line; returns its number (1-based), 0 when not recording.
  std::uint32_t add(std::string line);
  void replace(std::uint32_t number, std::string line);
  [[nodiscard]] std::uint32_t lines() const { return static_cast<std::uint32_t>(lines_.size()); }
  // Operation `index` (CheckedMesh's) comes from line `number`.
  void map_operation(std::size_t index, std::uint32_t number);
  [[nodiscard]] std::uint32_t line_of(std::size_t index) const;
  [[nodiscard]] std::string text() const;
  // The canonical hash of the mesh an input ended with (SequenceResult::final_hash).
  void set_final_hash(std::uint64_t hash) { final_hash_ = hash; }
  [[nodiscard]] std::uint64_t final_hash() const { return final_hash_; }

 private:
  bool enabled_;
  std::uint64_t final_hash_ = 0;
  std::vector<std::string> lines_;
  std::vector<std::uint32_t> operation_lines_;
};

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
  std::string (*decode_to_scenario)(const std::uint8_t* data, std::size_t size);
  std::string_view versions;  // the first bytes it accepts, for messages: "1 or 2"
};

std::span<const SequenceTarget> sequence_targets();
const SequenceTarget* find_sequence_target(std::string_view name);

}  // namespace tetcut::fuzz
