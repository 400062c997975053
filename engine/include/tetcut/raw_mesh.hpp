// The plain exchange form of a tetrahedral mesh: what file readers produce, what writers and the
// mesh builder consume, and what the independent checker can verify without any adjacency.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "tetcut/raw_mesh_view.hpp"  // kDeadTetMarker, and the view the checker reads
#include "tetcut/vec3.hpp"

namespace tetcut {

struct RawMesh {
  std::vector<Vec3> positions;                    // #V positions
  std::vector<std::array<std::uint32_t, 4>> tets;  // #T by 4 vertex indices, 0-based

  // A file as read is already raw arrays: it converts to the checker's view like a string to a
  // string_view (no tombstones, no engine records).
  operator RawMeshView() const { return {positions, tets}; }  // NOLINT(google-explicit-constructor)
};

}  // namespace tetcut
