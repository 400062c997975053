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
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz_failure.hpp"
#include "mesh_edits.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::fuzz {

// The bundled meshes (corpus/meshes/), chosen by one value of the input.
inline constexpr std::array<std::string_view, 3> kSequenceMeshes = {"cylinder.msh", "sheet.msh", "liver-coarse.msh"};

struct BundledMesh {
  std::string path;        // absolute
  TetMesh mesh;
  Box box;
  double mean_edge = 1.0;
};

// The folder of the bundled meshes: $TETCUT_MESH_DIR when set, else corpus/meshes of the source
// tree the harness was built from, else tetcut_meshes/ next to the executable (OSS-Fuzz).
std::string sequence_mesh_dir();
// kSequenceMeshes[index], read and built once per process (then copied per input). An unreadable
// or invalid mesh is a harness failure ("bundled-mesh").
const BundledMesh& bundled_mesh(std::size_t index);

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

 private:
  bool enabled_;
  std::vector<std::string> lines_;
  std::vector<std::uint32_t> operation_lines_;
};

// What a sequence target does with an input.
struct SequenceOptions {
  bool record_scenario = false;   // fill SequenceResult::scenario
  bool capture_failures = false;  // a finding becomes SequenceResult::finding instead of abort()
};

struct SequenceResult {
  bool accepted = false;          // false: not this target's version byte (nothing ran)
  std::string scenario;           // when recorded: up to the failing operation when there is one
  std::optional<Finding> finding; // when captured
  std::uint32_t finding_line = 0; // the scenario line of the failing operation (0: none)
};

// Internal to the targets: how far to run, to re-create the mesh as it was before a rolled back
// operation (sequence_session.hpp).
struct RunControl {
  std::size_t stop_before = std::numeric_limits<std::size_t>::max();  // operation index
  bool stopped = false;
  std::uint64_t hash_at_stop = 0;
};

// One sequence target, for the command line and the tests.
struct SequenceTarget {
  std::string_view name;
  SequenceResult (*run)(const std::uint8_t* data, std::size_t size, const SequenceOptions& options);
  std::string (*decode_to_scenario)(const std::uint8_t* data, std::size_t size);
};

std::span<const SequenceTarget> sequence_targets();
const SequenceTarget* find_sequence_target(std::string_view name);

}  // namespace tetcut::fuzz
