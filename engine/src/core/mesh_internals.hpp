// The one way under TetMesh's public interface: references to its private arrays.
//
// mesh.hpp befriends this type and nothing else (`friend struct detail::MeshInternals;`), so the
// public header names no builder, no test and no tool. Two callers need the arrays themselves:
// the mesh builder (mesh_builder.cpp), which fills them from validated input in one pass, and
// the checker's tests (tests/invariants), which corrupt exactly one record to prove that the
// independent checker sees it. Both reach them here, through an internal header that is not
// installed; an integrator only ever sees the forward declaration.
#pragma once

#include "tetcut/mesh.hpp"

namespace tetcut::detail {

struct MeshInternals {
  static auto& tet_verts(TetMesh& m) { return m.tet_verts_; }
  static auto& adjacency(TetMesh& m) { return m.tet_adj_; }
  static auto& positions(TetMesh& m) { return m.positions_; }
  static auto& vertex_tet(TetMesh& m) { return m.vert_tet_; }
  static auto& boundary_faces(TetMesh& m) { return m.vert_boundary_faces_; }
  static auto& attributes(TetMesh& m) { return m.attributes_; }
  static auto& live_tets(TetMesh& m) { return m.live_tets_; }
  static auto& live_vertices(TetMesh& m) { return m.live_vertices_; }
  static auto& free_vert_next(TetMesh& m) { return m.free_vert_next_; }
  static auto& free_vert_head(TetMesh& m) { return m.free_vert_head_; }
};

}  // namespace tetcut::detail
