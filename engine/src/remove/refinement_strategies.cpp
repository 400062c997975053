#include "remove/refinement_strategies.hpp"

#include <algorithm>

#include "remove/neighbour_search.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut::detail {
namespace {

bool contains_all(const TetMesh& mesh, TetId t, std::span<const VertId> verts) {
  for (VertId v : verts)
    if (mesh.local_index(t, v) < 0) return false;
  return true;
}

}  // namespace

bool RefinementPlan::planned(VertId x) const {
  return std::any_of(groups.begin(), groups.end(), [&](const CornerGroup& g) { return g.at[0] == x || g.at[1] == x; });
}

void RefinementStrategies::reserve() {
  search_.reserve();
  reserve_touched(plan_.edges, 512);
  reserve_touched(plan_.parents, 512);
  plan_.groups.reserve(8);  // T has four vertices
  for (auto* v : {&path_, &runs_, &pieces_, &set_, &larger_, &repaired_, &shell_}) reserve_touched(*v, 512);
  for (auto* v : {&run_sizes_, &piece_sizes_}) reserve_touched(*v, 64);
}

// ---- planning ----------------------------------------------------------------------------------

void RefinementStrategies::add_edges_from(const TetMesh& mesh, VertId from, std::span<const TetId> tets,
                                          std::span<const VertId> skip, RefinementPlan& plan) {
  for (TetId u : tets)
    for (int i = 0; i < 4; ++i) {
      const VertId w = mesh.vertex(u, i);
      if (w == from || std::find(skip.begin(), skip.end(), w) != skip.end()) continue;
      const bool known =
          std::any_of(plan.edges.begin(), plan.edges.end(), [&](const Edge& e) { return e.a == from && e.b == w; });
      if (!known) plan.edges.push_back({from, w, u});
    }
}

void RefinementStrategies::seal(RefinementPlan& plan) {
  for (const RefinementPlan::CornerGroup& g : plan.groups)
    std::sort(plan.parents.begin() + g.begin, plan.parents.begin() + g.begin + g.size);
}

void RefinementStrategies::plan_basic(const TetMesh& mesh, SetRemovalWorkspace& ws, TetId t, RefinementPlan& plan) {
  plan.edges.clear();
  plan.parents.clear();
  plan.groups.clear();
  // Every singularity T alone would leave, from the set test's verdict at each of T's vertices
  // (exact, where 3.3's cases name only one): a vertex, or an edge of T pinched at it.
  const TetId one[1] = {t};
  std::array<VertId, 4> vertices{};
  std::array<Edge, 4> edges{};
  int nv = 0, ne = 0;
  for (VertId x : mesh.tet(t)) {
    const Removability at_x = ws.check_at(mesh, one, x);
    if (at_x.kind == SingularityKind::kVertex) vertices[nv++] = at_x.vertex;
    if (at_x.kind == SingularityKind::kEdge &&
        std::none_of(edges.begin(), edges.begin() + ne, [&](const Edge& e) {
          return (e.a == at_x.edge.a && e.b == at_x.edge.b) || (e.a == at_x.edge.b && e.b == at_x.edge.a);
        }))
      edges[ne++] = at_x.edge;
  }
  auto singular = [&](VertId x) { return std::find(vertices.begin(), vertices.begin() + nv, x) != vertices.begin() + nv; };
  // A vertex: every edge at it split, the children at it (its whole star) go.
  for (int i = 0; i < nv; ++i) {
    const auto begin = static_cast<std::uint32_t>(plan.parents.size());
    mesh.vertex_shell(vertices[i], shell_);
    plan.parents.insert(plan.parents.end(), shell_.begin(), shell_.end());
    add_edges_from(mesh, vertices[i], shell_, {}, plan);
    plan.groups.push_back({{vertices[i], VertId{}}, begin, static_cast<std::uint32_t>(plan.parents.size()) - begin});
  }
  // An edge (a, b): every edge from a or b to its ring split, the children on the edge go. When an
  // end is a singular vertex too, that vertex's refinement splits the edge itself: the other end's
  // children around the ring go instead (the tube along the edge); both ends: nothing to add.
  for (int i = 0; i < ne; ++i) {
    const VertId ends[2] = {edges[i].a, edges[i].b};
    if (singular(ends[0]) && singular(ends[1])) continue;
    const auto begin = static_cast<std::uint32_t>(plan.parents.size());
    mesh.edge_shell(t, mesh.local_edge(t, ends[0], ends[1]), shell_);
    plan.parents.insert(plan.parents.end(), shell_.begin(), shell_.end());
    const auto size = static_cast<std::uint32_t>(plan.parents.size()) - begin;
    if (singular(ends[0]) || singular(ends[1])) {
      const VertId other = singular(ends[0]) ? ends[1] : ends[0];
      add_edges_from(mesh, other, shell_, {}, plan);
      plan.groups.push_back({{other, VertId{}}, begin, size});
    } else {
      for (VertId end : ends) add_edges_from(mesh, end, shell_, ends, plan);
      plan.groups.push_back({{ends[0], ends[1]}, begin, size});
    }
  }
  seal(plan);
}

bool RefinementStrategies::extend_at(const TetMesh& mesh, SetRemovalWorkspace& ws, std::vector<TetId>& set,
                                     std::size_t begin, VertId v, const Removability& offence,
                                     std::uint32_t max_set_size) {
  // The pieces are listed while the set is still marked (check_at marked it).
  pieces_.clear();
  piece_sizes_.clear();
  ws.remaining_pieces(mesh, offence, pieces_, piece_sizes_);
  const std::size_t end = set.size();
  std::uint32_t best_begin = 0, best_size = 0;
  for (std::uint32_t k = 0, first = 0; k < piece_sizes_.size(); first += piece_sizes_[k++]) {
    const std::uint32_t n = piece_sizes_[k];
    if ((best_size != 0 && n >= best_size) || end - begin + n > max_set_size) continue;
    set.resize(end);
    set.insert(set.end(), pieces_.begin() + first, pieces_.begin() + first + n);
    if (ws.check_at(mesh, std::span<const TetId>(set.data() + begin, set.size() - begin), v).removable()) {
      best_begin = first;
      best_size = n;
    }
  }
  set.resize(end);
  if (best_size == 0) return false;
  set.insert(set.end(), pieces_.begin() + best_begin, pieces_.begin() + best_begin + best_size);
  return true;
}

bool RefinementStrategies::plan_at_vertex(const TetMesh& mesh, SetRemovalWorkspace& ws, TetId t, VertId v,
                                          const WideSearchLimits& limits, std::span<const TetId> searched_path,
                                          RefinementPlan& plan) {
  const auto group_begin = static_cast<std::uint32_t>(plan.parents.size());
  if (!searched_path.empty()) {
    plan.parents.insert(plan.parents.end(), searched_path.begin(), searched_path.end());
  } else {
    if (!shortest_path_to_border(mesh, ws, t, v, limits.max_path_depth, path_)) return false;
    plan.parents.push_back(t);
    plan.parents.insert(plan.parents.end(), path_.begin(), path_.end());
  }
  const std::span<const TetId> path(plan.parents.data() + group_begin, plan.parents.size() - group_begin);
  const Removability at_v = ws.check_at(mesh, path, v);
  // 3.5's extension, decided at v alone: each piece the path leaves around v (or around the
  // pinched edge at v), smallest first.
  if (!at_v.removable() && !extend_at(mesh, ws, plan.parents, group_begin, v, at_v, limits.max_set_size)) return false;
  plan.groups.push_back({{v, VertId{}}, group_begin, static_cast<std::uint32_t>(plan.parents.size()) - group_begin});
  return true;
}

bool RefinementStrategies::plan_optimized_vertex(const TetMesh& mesh, SetRemovalWorkspace& ws, TetId t,
                                                 const Removability& first, const WideSearchLimits& limits,
                                                 std::span<const TetId> searched_path, RefinementPlan& plan) {
  // Along the shortest path from T to the border of v's shell (paper 3.7, figure 4), and
  // likewise at each other vertex of T where T alone would leave a singularity: T goes whole,
  // so each of its vertices needs its own path.
  plan.parents.clear();
  plan.groups.clear();
  if (!plan_at_vertex(mesh, ws, t, first.vertex, limits, searched_path, plan)) return false;
  const TetId one[1] = {t};
  for (VertId x : mesh.tet(t))
    if (x != first.vertex && !ws.check_at(mesh, one, x).removable() && !plan_at_vertex(mesh, ws, t, x, limits, {}, plan))
      return false;
  plan.edges.clear();
  for (const RefinementPlan::CornerGroup& g : plan.groups) add_edges_from(mesh, g.at[0], plan.parents_of(g), {}, plan);
  seal(plan);
  return true;
}

void RefinementStrategies::plan_edge_side(const TetMesh& mesh, TetId t, std::span<const VertId, 2> ends,
                                          std::span<const TetId> side, RefinementPlan& plan) {
  plan.parents.assign(1, t);
  plan.parents.insert(plan.parents.end(), side.begin(), side.end());
  plan.edges.clear();
  for (VertId end : ends) add_edges_from(mesh, end, plan.parents, ends, plan);
  plan.groups.assign(1, {{ends[0], ends[1]}, 0, static_cast<std::uint32_t>(plan.parents.size())});
  seal(plan);
}

// ---- applying a plan ---------------------------------------------------------------------------

std::uint32_t RefinementStrategies::split_and_remove(RemovalContext& ctx, TetId t, const RefinementPlan& plan,
                                                     const WideSearchLimits* repair) {
  const TetMesh::Savepoint before = ctx.mesh.savepoint();
  if (!ctx.split(plan.edges)) return 0;
  set_.clear();
  bool t_split = false;
  for (const TetMesh::TetBirth& c : ctx.mesh.tets_made_since(before)) {
    // No id is reused inside the transaction, so a parent id still names the tet it named.
    const TetId parent = ctx.mesh.parents(c)[0];
    if (parent == t) {
      t_split = true;
      set_.push_back(c.tet);
      continue;
    }
    for (const RefinementPlan::CornerGroup& g : plan.groups) {
      const std::span<const TetId> parents = plan.parents_of(g);
      if (std::binary_search(parents.begin(), parents.end(), parent) && contains_all(ctx.mesh, c.tet, g.vertices())) {
        set_.push_back(c.tet);
        break;
      }
    }
  }
  if (!t_split) set_.push_back(t);
  if (repair) close_pinched_midpoints(ctx, plan, ctx.mesh.vertices_made_since(before), repair->max_set_size);
  if (ctx.with_selected_children(set_, ctx.mesh.tets_made_since(before), larger_))
    if (const std::uint32_t n = remove_or_repair(ctx, larger_, repair)) return n;
  if (const std::uint32_t n = remove_or_repair(ctx, set_, repair)) return n;
  ctx.mesh.rollback_to(before);
  return 0;
}

void RefinementStrategies::close_pinched_midpoints(RemovalContext& ctx, const RefinementPlan& plan,
                                                   std::span<const TetMesh::VertexBirth> midpoints,
                                                   std::uint32_t max_set_size) {
  if (plan.groups.size() < 2) return;
  for (const TetMesh::VertexBirth& m : midpoints) {
    if (!plan.planned(m.a) || !plan.planned(m.b)) continue;
    const Removability at_m = ctx.ws.check_at(ctx.mesh, set_, m.vertex);
    if (!at_m.removable()) extend_at(ctx.mesh, ctx.ws, set_, 0, m.vertex, at_m, max_set_size);
  }
}

std::uint32_t RefinementStrategies::remove_or_repair(RemovalContext& ctx, const std::vector<TetId>& set,
                                                     const WideSearchLimits* repair) {
  const Removability check = ctx.ws.check(ctx.mesh, set);
  if (check.removable()) {
    if (!ctx.may_remove(set)) return 0;
    ctx.remove_set(set);
    return static_cast<std::uint32_t>(set.size());
  }
  if (repair && search_.find(ctx.mesh, ctx.ws, set, check, *repair, repaired_) && ctx.may_remove(repaired_)) {
    ctx.remove_set(repaired_);
    return static_cast<std::uint32_t>(repaired_.size());
  }
  return 0;
}

// ---- the two strategies ------------------------------------------------------------------------

std::uint32_t RefinementStrategies::basic(RemovalContext& ctx, TetId t) {
  plan_basic(ctx.mesh, ctx.ws, t, plan_);
  // The paper's set as it stands: no repair (the fallback follows in the dispatcher).
  return split_and_remove(ctx, t, plan_, nullptr);
}

std::uint32_t RefinementStrategies::optimized(RemovalContext& ctx, TetId t, const Removability& first,
                                              const WideSearchLimits& repair, std::span<const TetId> searched_path) {
  if (first.kind == SingularityKind::kVertex) {
    if (!plan_optimized_vertex(ctx.mesh, ctx.ws, t, first, repair, searched_path, plan_)) return 0;
    return split_and_remove(ctx, t, plan_, &repair);
  }
  // One side of T around the edge, the smaller first (paper 3.7: "the rightmost or leftmost").
  const VertId ends[2] = {first.edge.a, first.edge.b};
  sides_of_edge(ctx.mesh, ctx.ws, t, ends[0], ends[1], runs_, run_sizes_);
  if (run_sizes_.size() != 2) return 0;
  const std::span<const TetId> sides[2] = {std::span<const TetId>(runs_.data(), run_sizes_[0]),
                                           std::span<const TetId>(runs_.data() + run_sizes_[0], run_sizes_[1])};
  const int smaller = run_sizes_[0] <= run_sizes_[1] ? 0 : 1;
  for (const int side : {smaller, 1 - smaller}) {
    plan_edge_side(ctx.mesh, t, ends, sides[side], plan_);
    if (const std::uint32_t n = split_and_remove(ctx, t, plan_, &repair)) return n;
    if (ctx.over_budget) return 0;
  }
  return 0;
}

}  // namespace tetcut::detail
