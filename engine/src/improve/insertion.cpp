#include "improve/insertion.hpp"

#include <algorithm>

#include "core/quality.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/reserve_touched.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut::detail {

void Inserter::reserve(std::uint32_t tets) {
  splitter_.reserve(tets);
  reserve_touched(shell_, 128);
}

Refusal Inserter::plan(const TetMesh& mesh, TetId t, Plan& plan) {
  plan.start(Operator::kInsertion);
  int longest = 0;
  double length = -1.0;
  const TetMesh::TetVerts v = mesh.tet(t);
  for (int e = 0; e < 6; ++e)
    if (const double l = norm(mesh.position(v[kEdgeVerts[e][1]]) - mesh.position(v[kEdgeVerts[e][0]])); l > length) {
      length = l;
      longest = e;
    }
  const VertId a = v[kEdgeVerts[longest][0]], b = v[kEdgeVerts[longest][1]];
  mesh.edge_shell(t, longest, shell_);
  plan.split_edge = Edge{a, b, t};
  plan.splitter = &splitter_;
  // The midpoint as add_vertex_on_edge(lo, hi, 1/2) makes it: the splitter names the edge from
  // its lower id.
  const VertId lo = std::min(a, b), hi = std::max(a, b);
  plan.placed = kPlannedVertex;
  plan.placed_at = (1.0 - 0.5) * mesh.position(lo) + 0.5 * mesh.position(hi);
  plan.removed.assign(shell_.begin(), shell_.end());
  plan.worst_before = worst_quality(mesh, shell_);
  for (TetId u : shell_) {
    const TetMesh::TetVerts c = mesh.tet(u);
    for (const VertId end : {a, b}) {
      TetMesh::TetVerts half = c;
      half[static_cast<std::size_t>(mesh.local_index(u, end))] = kPlannedVertex;
      const std::array<Vec3, 4> x = plan.corners(mesh, half);
      if (orientation(x[0], x[1], x[2], x[3]) <= 0) return Refusal::kInvertedChild;
      plan.worst_after = std::min(plan.worst_after, quality(x[0], x[1], x[2], x[3]));
      plan.added.push_back(half);
    }
  }
  return Refusal::kNone;
}

}  // namespace tetcut::detail
