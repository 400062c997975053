#include "remove/removability.hpp"

#include <cassert>
#include <cstddef>
#include <iterator>

#include "tetcut/detail/local_tables.hpp"

namespace tetcut {

const char* to_string(SingularityKind kind) {
  constexpr const char* kNames[] = {"none", "vertex", "edge"};  // in the enum's order
  const auto i = static_cast<std::size_t>(kind);
  return i < std::size(kNames) ? kNames[i] : "?";
}

Removability removability(const TetMesh& mesh, TetId t) {
  assert(mesh.is_live(t));
  int faces[4];
  int n = 0;
  for (int f = 0; f < 4; ++f)
    if (mesh.is_boundary_face(t, f)) faces[n++] = f;

  Removability r;
  r.paper_case = static_cast<std::uint8_t>(n >= 3 ? 4 : n + 1);
  r.tet = t;
  // Whether removing t would leave v a singular vertex: v is on the boundary but none of t's
  // boundary faces holds it (cases 1 and 2 of paper 3.3).
  auto singular_at = [&](VertId v) {
    if (!mesh.is_boundary_vertex(v)) return false;
    r.kind = SingularityKind::kVertex;
    r.vertex = v;
    return true;
  };
  switch (n) {
    case 0:
      for (int i = 0; i < 4; ++i)
        if (singular_at(mesh.vertex(t, i))) return r;
      break;
    case 1:
      singular_at(mesh.vertex(t, faces[0]));  // face i is opposite vertex i
      break;
    case 2: {
      // Faces f1 and f2 omit vertices f1 and f2 respectively: the edge joining those two is
      // contained in neither face.
      const int e = kEdgeIndex[faces[0]][faces[1]];
      if (mesh.is_boundary_edge(t, e)) {
        r.kind = SingularityKind::kEdge;
        r.edge = {mesh.vertex(t, faces[0]), mesh.vertex(t, faces[1])};
        r.local_edge = static_cast<std::uint8_t>(e);
      }
      break;
    }
    default:
      break;
  }
  return r;
}

}  // namespace tetcut
