// The plain exchange form of a tetrahedral mesh: what file readers produce, what writers and the
// mesh builder consume, and what the independent checker can verify without any adjacency.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "tetcut/vec3.hpp"

namespace tetcut {

struct RawMesh {
  std::vector<Vec3> positions;                    // #V positions
  std::vector<std::array<std::uint32_t, 4>> tets;  // #T by 4 vertex indices, 0-based
};

// Marks a dead tet in a raw tet array (TetMesh::raw_tets() keeps tombstones): its first entry.
inline constexpr std::uint32_t kDeadTetMarker = 0xFFFFFFFFu;

}  // namespace tetcut
