// The removal dispatcher: one request, the strategy's stages in the paper's order (removal.hpp).
#include "remove/removal.hpp"

#include <algorithm>
#include <cassert>
#include <vector>

#include "refine/edge_split.hpp"
#include "refine/split_templates.hpp"
#include "remove/neighbour_search.hpp"
#include "remove/normal_surface_fallback.hpp"
#include "remove/refinement_strategies.hpp"
#include "remove/removal_context.hpp"
#include "remove/set_removal.hpp"
#include "remove/wide_search.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut {

struct Remover::Workspace {
  SetRemovalWorkspace set_test;
  EdgeSplitter splitter;
  detail::NeighbourSearch neighbours;
  detail::WideSearch wide;
  detail::RefinementStrategies refinement;
  detail::NormalSurfaceFallback fallback;
  std::vector<TetId> set;
  std::vector<TetId> net_removed, net_created, exposed;
  StampedSet<TetId> met_unresolved;  // already counted as unresolved (cleared by reset() only)
  // Of those, the ones a search-only request left (RequestLimits::search_only): put off, not
  // given up, so that their going later in any set takes them off the unresolved count.
  StampedSet<TetId> put_off;
  std::uint32_t put_off_count = 0;  // its size: 0 outside RemovalOrder::kRevisit, where nothing is looked up
  detail::TissueRemoval tissue;      // the removal path of a request made without a caller's
  // The wide search's bounds (as the strategy wide and as 3.4/3.7's repair), from the options
  // when they are set.
  detail::WideSearchLimits limits;
};

namespace {

// One request in the caller's request-by-request counts, when it keeps them. `put_off`: a
// search-only request (RequestLimits::search_only) left the tet for a later one, which counts
// what becomes of it.
void count_request(RequestCounts& counts, const RemovalResult& result, bool put_off) {
  ++counts.requests;
  if (!result.repeat) {
    counts.vertex_singularities += result.first.kind == SingularityKind::kVertex ? 1 : 0;
    counts.edge_singularities += result.first.kind == SingularityKind::kEdge ? 1 : 0;
  }
  if (result.outcome != RemovalOutcome::kUnresolved) counts.tets_removed += result.tets_removed;
  switch (result.outcome) {
    case RemovalOutcome::kDirect: counts.direct += result.repeat ? 0 : 1; break;
    case RemovalOutcome::kNeighbours: ++counts.resolved_by_neighbours; break;
    case RemovalOutcome::kRefinement: ++counts.resolved_by_refinement; break;
    case RemovalOutcome::kFallback: ++counts.resolved_by_fallback; break;
    case RemovalOutcome::kUnresolved:
      if (put_off) break;
      ++(result.over_budget ? counts.stopped_by_budget : counts.unresolved);
      break;
  }
}

// One request in the Remover's statistics, per distinct tet (removal_report.hpp), and in the
// caller's counts: the one tally of a request.
void count_request(RemovalReport& report, RequestCounts* counts, const RemovalResult& result, bool put_off) {
  if (counts) count_request(*counts, result, put_off);
  const SingularityKind kind = result.first.kind;
  const bool repeat = result.repeat;
  if (repeat) {
    ++report.repeated_requests;
  } else {
    ++report.requested;
    if (kind == SingularityKind::kVertex) ++report.vertex_singularities;
    if (kind == SingularityKind::kEdge) ++report.edge_singularities;
    if (result.first.paper_case >= 2) {  // a face on the surface (paper 3.3: case 1 has none)
      ++report.surface_requested;
      if (kind == SingularityKind::kNone) ++report.surface_direct;
      if (kind == SingularityKind::kVertex) ++report.surface_vertex_singularities;
      if (kind == SingularityKind::kEdge) ++report.surface_edge_singularities;
    }
    if (result.edge_search != detail::NeighbourSearch::kNoConfiguration) ++report.edge_search.counts[result.edge_search];
  }
  if (result.outcome != RemovalOutcome::kUnresolved) {
    ++report.removed;
    if (repeat) --report.unresolved;
    report.tets_removed += result.tets_removed;
    report.tets_created += result.tets_created;
    report.edges_split += result.edges_split;
  }
  switch (result.outcome) {
    case RemovalOutcome::kDirect:
      if (!repeat) {
        ++report.direct;
        report.selected_in_sets += result.selected_removed;
      }
      break;
    case RemovalOutcome::kNeighbours:
      ++report.resolved_by_neighbours;
      report.neighbour_set_tets += result.tets_removed;
      report.selected_in_sets += result.selected_removed;
      if (kind == SingularityKind::kVertex) {
        ++report.vertex_resolved_by_neighbours;
        report.vertex_neighbour_set_tets += result.tets_removed;
      } else {
        ++report.edge_resolved_by_neighbours;
        report.edge_neighbour_set_tets += result.tets_removed;
      }
      break;
    case RemovalOutcome::kRefinement:
      ++report.resolved_by_refinement;
      if (result.optimized_refinement) ++report.resolved_by_optimized_refinement;
      break;
    case RemovalOutcome::kFallback:
      ++report.resolved_by_fallback;
      break;
    case RemovalOutcome::kUnresolved:
      if (!repeat) ++(result.over_budget ? report.stopped_by_budget : report.unresolved);
      break;
  }
}

}  // namespace

const char* to_string(RemovalOutcome outcome) {
  switch (outcome) {
    case RemovalOutcome::kDirect: return "direct";
    case RemovalOutcome::kNeighbours: return "neighbours";
    case RemovalOutcome::kRefinement: return "refinement";
    case RemovalOutcome::kFallback: return "fallback";
    case RemovalOutcome::kUnresolved: return "unresolved";
  }
  return "?";
}

Remover::Remover(RemovalOptions options) : ws_(std::make_unique<Workspace>()) {
  set_options(options);
  // The split templates are a table built on first use, costlier than many requests: pay it
  // here, not inside the first request that refines.
  (void)split_template(1, 0);
}
Remover::~Remover() = default;
Remover::Remover(Remover&&) noexcept = default;
Remover& Remover::operator=(Remover&&) noexcept = default;

void Remover::reserve(std::uint32_t tets, std::uint32_t vertices) {
  // The working size of one request's lists: a larger request grows them once.
  using detail::reserve_touched;
  for (auto* v : {&ws_->net_removed, &ws_->net_created, &ws_->exposed}) reserve_touched(*v, 4096);
  reserve_touched(ws_->set, 1024);
  ws_->set_test.reserve(tets, vertices);
  ws_->splitter.reserve(tets);
  ws_->neighbours.reserve();
  ws_->wide.reserve();
  ws_->refinement.reserve();
  ws_->fallback.reserve();
  ws_->met_unresolved.reserve(tets);
}

void Remover::reserve_search_only(std::uint32_t tets) { ws_->put_off.reserve(tets); }

void Remover::set_options(const RemovalOptions& options) {
  options_ = options;
  ws_->limits = {options.max_path_depth, options.wide_rounds, options.wide_evaluations, options.max_set_size};
  reset();
}

void Remover::reset() {
  report_ = {};
  ws_->met_unresolved.clear();
  ws_->put_off.clear();
  ws_->put_off_count = 0;
}

std::span<const TetId> Remover::last_removed() const { return ws_->net_removed; }
std::span<const TetId> Remover::last_created() const { return ws_->net_created; }
std::span<const TetId> Remover::last_exposed() const { return ws_->exposed; }

RemovalResult Remover::remove(TetMesh& mesh, TetId t, const RequestLimits& limits) {
  return remove(mesh, t, removability(mesh, t), limits);
}

RemovalResult Remover::remove(TetMesh& mesh, TetId t, const Removability& first, const RequestLimits& limits) {
  assert(mesh.is_live(t));
  assert(first.kind == removability(mesh, t).kind && "first is t's verdict on this mesh");
  Workspace& w = *ws_;
  const bool own_transaction = !mesh.in_transaction();
  if (own_transaction) mesh.begin_transaction();
  const TetMesh::Savepoint start = mesh.savepoint();
  w.exposed.clear();
  detail::RemovalContext ctx{mesh, w.set_test, w.splitter, w.exposed, start, limits.max_tets_created, limits.selection};
  ctx.uncuttable = limits.uncuttable;
  ctx.tissue = limits.tissue;
  if (!ctx.tissue) {
    w.tissue.begin(nullptr, 0.0);
    ctx.tissue = &w.tissue;
  }

  RemovalResult result;
  result.first = first;
  result.repeat = w.met_unresolved.contains(t);
  auto count_selected = [&](std::span<const TetId> set) {
    if (!limits.selection) return static_cast<std::uint32_t>(1);  // the requested tet
    // The requested tet counts even when the caller did not select it (a cut's piece of a kept
    // tet left in the tool): it is a tet that should go.
    std::uint32_t n = limits.selection->contains(t) ? 0u : 1u;
    for (TetId u : set) n += limits.selection->contains(u) ? 1u : 0u;
    return n;
  };

  const TetId requested[1] = {t};
  if (first.removable() && ctx.may_remove(requested)) {
    const TetId one[1] = {t};
    if (options_.verify_direct) result.set_test_disagrees = !w.set_test.check(mesh, one).removable();
    result.selected_removed = count_selected(one);
    ctx.remove_set(one);
    result.outcome = RemovalOutcome::kDirect;
    result.tets_removed = 1;
  }

  // 3.5 (or the wide search): a set of neighbours, no mesh change until it is removed.
  std::span<const TetId> searched_path;  // 3.5's shortest path, which 3.7 refines along
  if (result.outcome == RemovalOutcome::kUnresolved && options_.strategy != RemovalStrategy::kBasic) {
    bool found = false;
    if (options_.strategy == RemovalStrategy::kWide) {
      const TetId one[1] = {t};
      found = w.wide.find(mesh, w.set_test, one, first, w.limits, w.set);
    } else {
      found = w.neighbours.find(mesh, w.set_test, t, first, options_.max_path_depth, options_.max_set_size, w.set,
                                options_.neighbour_set == NeighbourSetChoice::kFirst);
      searched_path = w.neighbours.path();
      result.edge_search = w.neighbours.edge_configuration();
    }
    if (found && ctx.may_remove(w.set)) {
      result.selected_removed = count_selected(w.set);
      ctx.remove_set(w.set);
      result.outcome = RemovalOutcome::kNeighbours;
      result.tets_removed = static_cast<std::uint32_t>(w.set.size());
    }
  }

  // 3.7 (combined, wide) or 3.4 (basic): refine, then remove the paper's set if it is removable.
  if (result.outcome == RemovalOutcome::kUnresolved && options_.strategy != RemovalStrategy::kNeighbours &&
      !limits.search_only) {
    const bool optimized = options_.strategy != RemovalStrategy::kBasic;
    const std::uint32_t n = optimized ? w.refinement.optimized(ctx, t, first, w.limits, searched_path)
                                      : w.refinement.basic(ctx, t);
    if (n > 0) {
      result.outcome = RemovalOutcome::kRefinement;
      result.optimized_refinement = optimized;
      result.tets_removed = n;
    } else if (!ctx.over_budget) {
      ++report_.attempts_undone;
    }
  }

  // The construction with a proof (docs/removal-proof.md).
  if (result.outcome == RemovalOutcome::kUnresolved && options_.strategy != RemovalStrategy::kNeighbours &&
      !limits.search_only && !ctx.over_budget) {
    if (const std::uint32_t n = w.fallback.remove(ctx, t)) {
      result.outcome = RemovalOutcome::kFallback;
      result.tets_removed = n;
    } else if (!ctx.over_budget) {
      ++report_.fallback_refused;
    }
  }

  result.over_budget = ctx.over_budget && result.outcome == RemovalOutcome::kUnresolved;
  result.edges_split = static_cast<std::uint32_t>(mesh.vertices_made_since(start).size());
  mesh.changes_since(start, w.net_removed, w.net_created);
  result.tets_created = static_cast<std::uint32_t>(w.net_created.size());
  for (TetId c : w.net_created)
    if (mesh.boundary_face_count(c) > 0) w.exposed.push_back(c);
  if (own_transaction) mesh.commit();

  count_request(report_, limits.counts, result, limits.search_only);
  // Whether x was put off (and is no longer).
  auto take_off = [&w](TetId x) {
    if (w.put_off_count == 0 || !w.put_off.contains(x)) return false;
    w.put_off.erase(x);
    --w.put_off_count;
    return true;
  };
  if (result.outcome == RemovalOutcome::kUnresolved) {
    w.met_unresolved.insert(t);
    if (!limits.search_only) {
      take_off(t);  // given up: it stays counted unresolved
    } else if (w.put_off.insert(t)) {
      ++w.put_off_count;
    }
  } else {
    take_off(t);  // its own repeat was counted above
    for (TetId r : w.net_removed) {
      // A put-off tet that went with this set (or was split by it) is no longer unresolved.
      if (take_off(r)) --report_.unresolved;
      w.met_unresolved.erase(r);
    }
  }
  for (TetId c : w.net_created) w.met_unresolved.erase(c);
  return result;
}

}  // namespace tetcut
