// Topological improvement: flips that replace a few tets by a better triangulation of the same
// polytope (Shewchuk, "Two discrete optimization algorithms for the topological improvement of
// tetrahedral meshes", 2002; Klingner and Shewchuk, "Aggressive tetrahedral mesh improvement",
// 2007). Each is planned on the const mesh and applied only when its worst tet is better than the
// worst tet it replaces (by quality(), core/quality.hpp, as every operator of the pass), so a
// sequence of them never lowers the worst quality of a region and ends.
//
//   edge removal  the n tets around an interior edge (a, b), n = 3..kMaxRing, replaced by
//                 2(n - 2) tets: a triangulation of their ring polygon coned to a and to b,
//                 the best one by dynamic programming over the polygon (Klincsek's algorithm,
//                 as in Shewchuk's paper). n = 3 is the 3-2 flip, n = 4 the 4-4 flip. On the
//                 surface, the tets around a boundary edge whose two boundary faces are coplanar
//                 likewise (n = 2: the 2-2 flip): the boundary stays the same surface, its two
//                 triangles re-split along the other diagonal of their quadrilateral.
//   face removal  the 2-3 flip: the two tets sharing an interior face replaced by the three
//                 around the edge joining their opposite vertices.
//
// Why the mesh stays a conformal 3-manifold: a flip retriangulates a polytope whose boundary it
// keeps (same boundary triangles, or on the surface the same plane), with every new tet
// positively oriented by the exact predicate; and no new edge or face may already exist
// elsewhere in the mesh (a duplicate edge would give it two disconnected shells, I6). Plan
// (operation.hpp), then apply: a refused plan says why and leaves the mesh untouched.
#pragma once

#include <cstdint>
#include <vector>

#include "improve/operation.hpp"
#include "tetcut/ids.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::detail {

inline constexpr int kMaxRing = 9;  // tets around an edge that edge removal considers

class Flipper {
 public:
  // Working sizes, allocated and touched now.
  void reserve();
  // The best retriangulation of the tets around edge (t, local_edge), if its worst tet beats the
  // worst of those by more than `margin` (a relative improvement): Operator::kEdgeRemoval.
  [[nodiscard]] Refusal plan_edge_removal(const TetMesh& mesh, TetId t, int local_edge, double margin, Plan& plan);
  // The 2-3 flip of the interior face (t, face), under the same rule: Operator::kFaceRemoval.
  [[nodiscard]] Refusal plan_face_flip(const TetMesh& mesh, TetId t, int face, double margin, Plan& plan);

 private:
  // Whether an edge (u, w) or a face (u, w, x) exists anywhere in the mesh.
  bool has_edge(const TetMesh& mesh, VertId u, VertId w);
  bool has_face(const TetMesh& mesh, VertId u, VertId w, VertId x);

  std::vector<TetId> shell_, scratch_;
};

}  // namespace tetcut::detail
