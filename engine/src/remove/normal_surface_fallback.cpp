#include "remove/normal_surface_fallback.hpp"

#include <algorithm>

#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut::detail {

void NormalSurfaceFallback::reserve() {
  reserve_touched(edges_, 1024);
  for (auto* v : {&shell_, &set_, &larger_}) reserve_touched(*v, 1024);
  reserve_touched(split_points_, 1024);
}

void NormalSurfaceFallback::plan(const TetMesh& mesh, TetId t, std::vector<Edge>& edges) {
  const TetMesh::TetVerts corners = mesh.tet(t);
  auto in_t = [&](VertId w) { return std::find(corners.begin(), corners.end(), w) != corners.end(); };
  edges.clear();
  for (VertId a : corners) {
    const std::size_t first = edges.size();
    mesh.vertex_shell(a, shell_);
    for (TetId u : shell_)
      for (int i = 0; i < 4; ++i) {
        const VertId w = mesh.vertex(u, i);
        if (in_t(w)) continue;
        // Edges from different corners differ in `a`: only this corner's need the check.
        const bool known = std::any_of(edges.begin() + static_cast<std::ptrdiff_t>(first), edges.end(),
                                       [&](const Edge& e) { return e.b == w; });
        if (!known) edges.push_back({a, w, u});
      }
  }
}

std::uint32_t NormalSurfaceFallback::remove(RemovalContext& ctx, TetId t) {
  plan(ctx.mesh, t, edges_);
  const TetMesh::Savepoint before = ctx.mesh.savepoint();
  // The proof is combinatorial: any point inside each edge will do, so where a midpoint would
  // make a child flat or inverted (a sliver in the stars), the splitter moves it.
  if (!ctx.split(edges_, SplitPoint::kPositiveChildren)) return 0;

  // f = 1 at T's corners (T is untouched), 1/2 at the new vertices, 0 elsewhere.
  const TetMesh::TetVerts corners = ctx.mesh.tet(t);
  split_points_.clear();
  for (const TetMesh::VertexBirth& v : ctx.mesh.vertices_made_since(before)) split_points_.push_back(v.vertex.value);
  std::sort(split_points_.begin(), split_points_.end());
  auto f_at_least_half = [&](VertId w) {
    return std::find(corners.begin(), corners.end(), w) != corners.end() ||
           std::binary_search(split_points_.begin(), split_points_.end(), w.value);
  };
  set_.assign(1, t);
  for (const TetMesh::TetBirth& c : ctx.mesh.tets_made_since(before)) {
    const TetMesh::TetVerts v = ctx.mesh.tet(c.tet);
    if (std::all_of(v.begin(), v.end(), f_at_least_half)) set_.push_back(c.tet);
  }
  // With the selected parents' other children, if that is removable too (removal_context.hpp).
  if (ctx.with_selected_children(set_, ctx.mesh.tets_made_since(before), larger_) && ctx.may_remove_beyond_reach(larger_) &&
      ctx.ws.check(ctx.mesh, larger_).removable()) {
    ctx.remove_set(larger_);
    return static_cast<std::uint32_t>(larger_.size());
  }
  // Removable by the proof; tested all the same, as every set is, so that a bug shows up as an
  // unresolved request in the tests rather than as a broken mesh.
  if (!ctx.may_remove_beyond_reach(set_) || !ctx.ws.check(ctx.mesh, set_).removable()) {
    ctx.mesh.rollback_to(before);
    return 0;
  }
  ctx.remove_set(set_);
  return static_cast<std::uint32_t>(set_.size());
}

}  // namespace tetcut::detail
