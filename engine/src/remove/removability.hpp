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

// The verdict on removing one tet (removability() below) or a set of tets (SetRemovalWorkspace,
// set_removal.hpp): removable, or the first vertex or edge that would become singular. One type
// for both, so that a search that starts from a tet's offence (the wide search, 3.7's planning)
// takes it as the set test would have named it.
struct Removability {
  SingularityKind kind = SingularityKind::kNone;
  VertId vertex;  // kind == kVertex: the vertex that would become singular
  Edge edge{};    // kind == kEdge: the edge that would become singular
  // A tet of the set containing the offending vertex or edge (and its local edge for kEdge):
  // where a search that wants to repair the offence starts.
  TetId tet;
  std::uint8_t local_edge = 0;
  // One tet (removability()): paper 3.3's case, 1 + the number of its boundary faces, capped
  // at 4. A set: 0.
  std::uint8_t paper_case = 0;
  // A set: how many of its vertices, in the order the test visits them, passed before the
  // offence (all of them when removable): what a test of a larger set starting with this one
  // reuses (TestedPrefix). One tet: 0.
  std::uint32_t vertices_passed = 0;

  [[nodiscard]] bool removable() const { return kind == SingularityKind::kNone; }
};

// Precondition: t is live.
Removability removability(const TetMesh& mesh, TetId t);

}  // namespace tetcut
