// The plain exchange form of a tetrahedral mesh: what file readers produce, what writers and the
// mesh builder consume, and what the independent checker can verify without any adjacency.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "tetcut/raw_mesh_view.hpp"  // kDeadTetMarker, and the view the checker reads
#include "tetcut/vec3.hpp"

namespace tetcut {

inline constexpr std::uint32_t kMaxTetLabel = 0x7FFFFFFFu;

struct RawMesh {
  std::vector<Vec3> positions;                    // #V positions
  std::vector<std::array<std::uint32_t, 4>> tets;  // #T by 4 vertex indices, 0-based
  // #T per-tet labels (a region, a material: Gmsh's physical tag, medit's reference, VTK cell
  // data), or empty: the mesh is unlabelled. A label is any integer in [0, kMaxTetLabel]: what
  // every format's int holds (Gmsh, medit and VTK store 32-bit signed ints); 0xFFFFFFFF is left
  // free for the consumers' "no label" sentinel.
  std::vector<std::uint32_t> labels;

  [[nodiscard]] bool labelled() const { return !labels.empty(); }

  // A file as read is already raw arrays: it converts to the checker's view like a string to a
  // string_view (no tombstones, no engine records).
  operator RawMeshView() const { return {positions, tets}; }  // NOLINT(google-explicit-constructor)
};

}  // namespace tetcut
