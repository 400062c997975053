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

void RefinementStrategies::reserve() {
  search_.reserve();
  reserve_touched(edges_, 512);
  for (auto* v : {&parents_, &sides_, &set_, &larger_, &repaired_}) reserve_touched(*v, 512);
  groups_.reserve(8);  // T has four vertices
  reserve_touched(sizes_, 64);
}

void RefinementStrategies::add_edges_from(const TetMesh& mesh, VertId from, std::span<const TetId> tets,
                                          std::span<const VertId> skip) {
  for (TetId u : tets)
    for (int i = 0; i < 4; ++i) {
      const VertId w = mesh.vertex(u, i);
      if (w == from || std::find(skip.begin(), skip.end(), w) != skip.end()) continue;
      const bool known = std::any_of(edges_.begin(), edges_.end(), [&](const Edge& e) { return e.a == from && e.b == w; });
      if (!known) edges_.push_back({from, w, u});
    }
}

std::uint32_t RefinementStrategies::split_and_remove(RemovalContext& ctx, TetId t, const WideSearchLimits& repair) {
  const TetMesh::Savepoint before = ctx.mesh.savepoint();
  for (const CornerGroup& g : groups_)
    std::sort(parents_.begin() + g.begin, parents_.begin() + g.begin + g.size);
  if (!ctx.split(edges_)) return 0;
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
    for (const CornerGroup& g : groups_) {
      const auto begin = parents_.begin() + g.begin, end = begin + g.size;
      if (std::binary_search(begin, end, parent) && contains_all(ctx.mesh, c.tet, g.vertices())) {
        set_.push_back(c.tet);
        break;
      }
    }
  }
  if (!t_split) set_.push_back(t);
  close_pinched_midpoints(ctx, ctx.mesh.vertices_made_since(before), repair.max_set_size);
  if (ctx.with_selected_children(set_, ctx.mesh.tets_made_since(before), larger_))
    if (const std::uint32_t n = remove_or_repair(ctx, larger_, repair)) return n;
  if (const std::uint32_t n = remove_or_repair(ctx, set_, repair)) return n;
  ctx.mesh.rollback_to(before);
  return 0;
}

std::uint32_t RefinementStrategies::remove_or_repair(RemovalContext& ctx, const std::vector<TetId>& set,
                                                     const WideSearchLimits& repair) {
  const Removability check = ctx.ws.check(ctx.mesh, set);
  if (check.removable()) {
    ctx.remove_set(set);
    return static_cast<std::uint32_t>(set.size());
  }
  if (search_.find(ctx.mesh, ctx.ws, set, check, repair, repaired_)) {
    ctx.remove_set(repaired_);
    return static_cast<std::uint32_t>(repaired_.size());
  }
  return 0;
}

std::uint32_t RefinementStrategies::basic(RemovalContext& ctx, TetId t, const Removability& first,
                                          const WideSearchLimits& repair) {
  edges_.clear();
  if (first.kind == SingularityKind::kVertex) {
    ctx.mesh.vertex_shell(first.vertex, parents_);
    add_edges_from(ctx.mesh, first.vertex, parents_, {});
    groups_.assign(1, CornerGroup{{first.vertex, VertId{}}, 0, static_cast<std::uint32_t>(parents_.size())});
    return split_and_remove(ctx, t, repair);
  }
  const VertId ends[2] = {first.edge.a, first.edge.b};
  const int local_edge = ctx.mesh.local_edge(t, ends[0], ends[1]);
  ctx.mesh.edge_shell(t, local_edge, parents_);
  for (VertId end : ends) add_edges_from(ctx.mesh, end, parents_, ends);
  groups_.assign(1, CornerGroup{{ends[0], ends[1]}, 0, static_cast<std::uint32_t>(parents_.size())});
  return split_and_remove(ctx, t, repair);
}

bool RefinementStrategies::extend_at(RemovalContext& ctx, std::vector<TetId>& set, std::size_t begin, VertId v,
                                     const Removability& offence, std::uint32_t max_set_size) {
  // The pieces are listed while the set is still marked (check_at marked it).
  sides_.clear();
  sizes_.clear();
  ctx.ws.remaining_pieces(ctx.mesh, offence, sides_, sizes_);
  const std::size_t end = set.size();
  std::uint32_t best_begin = 0, best_size = 0;
  for (std::uint32_t k = 0, first = 0; k < sizes_.size(); first += sizes_[k++]) {
    const std::uint32_t n = sizes_[k];
    if ((best_size != 0 && n >= best_size) || end - begin + n > max_set_size) continue;
    set.resize(end);
    set.insert(set.end(), sides_.begin() + first, sides_.begin() + first + n);
    if (ctx.ws.check_at(ctx.mesh, std::span<const TetId>(set.data() + begin, set.size() - begin), v).removable()) {
      best_begin = first;
      best_size = n;
    }
  }
  set.resize(end);
  if (best_size == 0) return false;
  set.insert(set.end(), sides_.begin() + best_begin, sides_.begin() + best_begin + best_size);
  return true;
}

bool RefinementStrategies::plan_at_vertex(RemovalContext& ctx, TetId t, VertId v, const WideSearchLimits& limits,
                                          std::span<const TetId> searched_path) {
  const auto group_begin = static_cast<std::uint32_t>(parents_.size());
  if (!searched_path.empty()) {
    parents_.insert(parents_.end(), searched_path.begin(), searched_path.end());
  } else {
    if (!shortest_path_to_border(ctx.mesh, ctx.ws, t, v, limits.max_path_depth, sides_)) return false;
    parents_.push_back(t);
    parents_.insert(parents_.end(), sides_.begin(), sides_.end());
  }
  const std::span<const TetId> path(parents_.data() + group_begin, parents_.size() - group_begin);
  const Removability at_v = ctx.ws.check_at(ctx.mesh, path, v);
  // 3.5's extension, decided at v alone: each piece the path leaves around v (or around the
  // pinched edge at v), smallest first.
  if (!at_v.removable() && !extend_at(ctx, parents_, group_begin, v, at_v, limits.max_set_size)) return false;
  groups_.push_back({{v, VertId{}}, group_begin, static_cast<std::uint32_t>(parents_.size()) - group_begin});
  return true;
}

void RefinementStrategies::close_pinched_midpoints(RemovalContext& ctx, std::span<const TetMesh::VertexBirth> midpoints,
                                                   std::uint32_t max_set_size) {
  if (groups_.size() < 2) return;
  auto planned = [&](VertId x) {
    return std::any_of(groups_.begin(), groups_.end(), [&](const CornerGroup& g) { return g.at[0] == x || g.at[1] == x; });
  };
  for (const TetMesh::VertexBirth& m : midpoints) {
    if (!planned(m.a) || !planned(m.b)) continue;
    const Removability at_m = ctx.ws.check_at(ctx.mesh, set_, m.vertex);
    if (!at_m.removable()) extend_at(ctx, set_, 0, m.vertex, at_m, max_set_size);
  }
}

std::uint32_t RefinementStrategies::optimized(RemovalContext& ctx, TetId t, const Removability& first,
                                              const WideSearchLimits& repair, std::span<const TetId> searched_path) {
  if (first.kind == SingularityKind::kVertex) {
    // Along the shortest path from T to the border of v's shell (paper 3.7, figure 4), and
    // likewise at each other vertex of T where T alone would leave a singularity: T goes whole,
    // so each of its vertices needs its own path (plan_at_vertex, before any split).
    parents_.clear();
    groups_.clear();
    if (!plan_at_vertex(ctx, t, first.vertex, repair, searched_path)) return 0;
    const TetId one[1] = {t};
    for (VertId x : ctx.mesh.tet(t))
      if (x != first.vertex && !ctx.ws.check_at(ctx.mesh, one, x).removable() && !plan_at_vertex(ctx, t, x, repair)) return 0;
    edges_.clear();
    for (const CornerGroup& g : groups_)
      add_edges_from(ctx.mesh, g.at[0], std::span<const TetId>(parents_.data() + g.begin, g.size), {});
    return split_and_remove(ctx, t, repair);
  }
  // One side of T around the edge, the smaller first (paper 3.7: "the rightmost or leftmost").
  const VertId ends[2] = {first.edge.a, first.edge.b};
  sides_of_edge(ctx.mesh, ctx.ws, t, ends[0], ends[1], sides_, sizes_);
  if (sizes_.size() != 2) return 0;
  const bool first_smaller = sizes_[0] <= sizes_[1];
  for (int attempt = 0; attempt < 2; ++attempt) {
    const bool take_first = (attempt == 0) == first_smaller;
    const auto begin = sides_.begin() + (take_first ? 0 : sizes_[0]);
    parents_.assign(1, t);
    parents_.insert(parents_.end(), begin, begin + (take_first ? sizes_[0] : sizes_[1]));
    edges_.clear();
    for (VertId end : ends) add_edges_from(ctx.mesh, end, parents_, ends);
    groups_.assign(1, CornerGroup{{ends[0], ends[1]}, 0, static_cast<std::uint32_t>(parents_.size())});
    if (const std::uint32_t n = split_and_remove(ctx, t, repair)) return n;
    if (ctx.over_budget) return 0;
  }
  return 0;
}

}  // namespace tetcut::detail
