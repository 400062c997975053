// Can one tetrahedron be removed without making the mesh non-manifold? (paper 3.3)
//
// The paper's test looks only at how many faces of T lie on the surface, and at the boundary
// status of one vertex or edge of T:
//   case 1  no boundary face:    removable iff none of T's vertices is on the boundary
//   case 2  one boundary face:   iff the vertex opposite that face is interior
//   case 3  two boundary faces:  iff the edge opposite both (joining the two vertices those
//                                faces omit) is interior
//   case 4  three or four:       always
// Why it is exact: removing T deletes one triangle from the link of each of its vertices; the
// link (a disk on the boundary, a sphere inside) stays a disk iff that triangle touches the
// link's border in a single arc, which is what the four cases spell out.
//
// Cost: O(1) with the mesh's boundary flags, except case 3 which asks is_boundary_edge, O(edge
// shell).
#pragma once

#include <cstdint>

#include "refine/edge_split.hpp"
#include "tetcut/ids.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut {

// What removing a tet (or a set of tets) would break.
enum class SingularityKind : std::uint8_t {
  kNone,
  kVertex,  // a vertex whose remaining shell is not one face-connected ball (its link a disk)
  kEdge,    // an edge whose remaining tets are not one contiguous run around it
};

const char* to_string(SingularityKind kind);

struct Removability {
  bool removable = false;
  std::uint8_t paper_case = 0;  // 1..4: 1 + number of boundary faces, capped at 4
  SingularityKind kind = SingularityKind::kNone;
  VertId vertex;  // kind == kVertex: the vertex that would become singular
  Edge edge{};    // kind == kEdge: the edge that would become singular
};

// Precondition: t is live.
Removability removability(const TetMesh& mesh, TetId t);

}  // namespace tetcut
