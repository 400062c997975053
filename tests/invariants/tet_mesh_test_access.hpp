// The test-only friend of TetMesh (declared in mesh.hpp): tests corrupt the engine's private
// state through it to prove that the checker sees what it compares (I2, I8). Defined once, here,
// for every test of tests/invariants.
#pragma once

#include "tetcut/mesh.hpp"

namespace tetcut {
struct TetMeshTestAccess {
  static auto& adjacency(TetMesh& m) { return m.tet_adj_; }
  static auto& vertex_tet(TetMesh& m) { return m.vert_tet_; }
  static auto& boundary_faces(TetMesh& m) { return m.vert_boundary_faces_; }
  static auto& tet_verts(TetMesh& m) { return m.tet_verts_; }
  static auto& live_tets(TetMesh& m) { return m.live_tets_; }
};
}  // namespace tetcut
