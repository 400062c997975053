// The face-connected pieces of a mesh: what a resection separates (scenarios expect a count,
// reports draw the pieces apart). O(#T): for reports and checks, never on the cut path.
#pragma once

#include <cstdint>
#include <vector>

#include "tetcut/mesh.hpp"

namespace tetcut {

inline constexpr std::uint32_t kNoPiece = 0xFFFFFFFFu;

struct Pieces {
  std::uint32_t count = 0;
  // Per tet id (tet_capacity() entries): its piece, numbered 0, 1, ... in the order of each
  // piece's lowest tet id; kNoPiece for dead ids.
  std::vector<std::uint32_t> of_tet;
};

Pieces face_connected_pieces(const TetMesh& mesh);

}  // namespace tetcut
