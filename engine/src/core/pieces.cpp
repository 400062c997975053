#include "core/pieces.hpp"

namespace tetcut {

Pieces face_connected_pieces(const TetMesh& mesh) {
  Pieces pieces;
  pieces.of_tet.assign(mesh.tet_capacity(), kNoPiece);
  std::vector<TetId> stack;
  for (std::uint32_t s = 0; s < mesh.tet_capacity(); ++s) {
    if (!mesh.is_live(TetId{s}) || pieces.of_tet[s] != kNoPiece) continue;
    const std::uint32_t piece = pieces.count++;
    pieces.of_tet[s] = piece;
    stack.assign(1, TetId{s});
    while (!stack.empty()) {
      const TetId t = stack.back();
      stack.pop_back();
      for (int f = 0; f < 4; ++f) {
        const FaceRef n = mesh.neighbour(t, f);
        if (n.valid() && pieces.of_tet[n.tet.value] == kNoPiece) {
          pieces.of_tet[n.tet.value] = piece;
          stack.push_back(n.tet);
        }
      }
    }
  }
  return pieces;
}

}  // namespace tetcut
