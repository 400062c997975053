// The scenario a sequence input is recorded as (tools/scenario's format, so that `tetcut replay`
// shows an input as something `tetcut run` and `tetcut minimize` take): its lines, which line
// each operation came from, and the numbers in them, rounded so that they read well and read
// back to the same doubles.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "tetcut/vec3.hpp"

namespace tetcut::fuzz {

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

}  // namespace tetcut::fuzz
