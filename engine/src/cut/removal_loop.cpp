#include "cut/removal_loop.hpp"

#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut::detail {

void RemovalLoop::reserve(std::uint32_t tets) {
  tried_.reserve(tets);
  queued_.reserve(tets);
  reserve_touched(work_, 16384);
}

bool RemovalLoop::pending(const Context& ctx, TetId t) const {
  return ctx.mesh.is_live(t) && ctx.selection.selected().contains(t) && !tried_.contains(t);
}

void RemovalLoop::enqueue(const Context& ctx, TetId t) {
  if (!pending(ctx, t) || !queued_.insert(t)) return;
  work_.push_back(t);
}

TetId RemovalLoop::next_pending(const Context& ctx) const {
  for (TetId t : ctx.selection.removal())
    if (pending(ctx, t) && ctx.mesh.boundary_face_count(t) > 0) return t;
  for (TetId t : ctx.selection.removal())
    if (pending(ctx, t)) return t;
  return kNoTet;
}

TetId RemovalLoop::next_to_revisit(const Context& ctx, bool put_off_too) const {
  auto waiting = [&](TetId t) {
    return ctx.mesh.is_live(t) && ctx.selection.selected().contains(t) && !given_up_.contains(t) &&
           (put_off_too || !put_off_.contains(t));
  };
  for (TetId t : ctx.selection.removal())
    if (waiting(t) && ctx.mesh.boundary_face_count(t) > 0) return t;
  for (TetId t : ctx.selection.removal())
    if (waiting(t)) return t;
  return kNoTet;
}

bool RemovalLoop::revisit(const Context& ctx, CutReport& report) {
  put_off_.clear();
  given_up_.clear();
  for (;;) {
    TetId t = next_to_revisit(ctx, false);
    const bool whole = !t.valid();  // every waiting tet is put off: the first goes to the strategy
    if (whole) t = next_to_revisit(ctx, true);
    if (!t.valid()) return true;
    if (whole) given_up_.insert(t);
    if (!request(ctx, t, removability(ctx.mesh, t), true, report, !whole)) return false;
    // Removal exposes tets and only ever makes others removable: after one, every put-off tet is
    // met again. A search-only request that left t (a refused set, a failed search) puts it off.
    if (!whole && ctx.mesh.is_live(t) && ctx.selection.selected().contains(t))
      put_off_.insert(t);
    else
      put_off_.clear();
  }
}

bool RemovalLoop::request(const Context& ctx, TetId t, const Removability& first, bool pieces, CutReport& report,
                          bool search_only) {
  tried_.insert(t);
  const std::uint32_t made = ctx.mesh.net_tets_made_since(ctx.start);
  RequestLimits limits;
  limits.max_tets_created = ctx.params.max_tets_created > made ? ctx.params.max_tets_created - made : 0;
  limits.selection = &ctx.selection.selected();
  limits.uncuttable = &ctx.uncuttable;
  limits.tissue = &ctx.tissue;
  limits.counts = &report;
  limits.search_only = search_only;
  const std::size_t selected_before = ctx.selection.removal().size();
  const TetMesh::Savepoint before_request = ctx.mesh.savepoint();
  const RemovalResult r = ctx.remover.remove(ctx.mesh, t, first, limits);
  if (pieces) {
    ctx.selection.follow(ctx.mesh, before_request);
    for (std::size_t i = selected_before; i < ctx.selection.removal().size(); ++i) enqueue(ctx, ctx.selection.removal()[i]);
    for (TetId e : ctx.remover.last_exposed()) enqueue(ctx, e);
  }
  return !r.over_budget && ctx.mesh.net_tets_made_since(ctx.start) <= ctx.params.max_tets_created;
}

bool RemovalLoop::run(const Context& ctx, CutReport& report) {
  tried_.clear();
  queued_.clear();
  const std::vector<TetId>& removal = ctx.selection.removal();
  if (ctx.selection.tool() && removal.size() == ctx.mesh.num_tets()) {
    // The tool holds every tet (each selected one is live and counted once): removing the whole
    // mesh leaves nothing that could pinch, so it goes at once, in O(#T), instead of tet by tet.
    ctx.tissue.remove(ctx.mesh, removal);
    report.requested = report.tets_removed = static_cast<std::uint32_t>(removal.size());
    return true;
  }
  work_.clear();
  std::size_t head = 0;
  for (TetId t : removal) enqueue(ctx, t);
  if (ctx.params.order == RemovalOrder::kSurfaceFirstById) {
    for (TetId t = next_pending(ctx); t.valid(); t = next_pending(ctx))
      if (!request(ctx, t, removability(ctx.mesh, t), true, report)) return false;
    work_.clear();
  } else if (ctx.params.order == RemovalOrder::kRevisit) {
    if (!revisit(ctx, report)) return false;
    work_.clear();
  }
  for (;;) {
    while (head < work_.size()) {
      const TetId t = work_[head++];
      queued_.erase(t);
      if (!pending(ctx, t)) continue;
      const Removability first = removability(ctx.mesh, t);
      if (!first.removable()) continue;
      if (!request(ctx, t, first, true, report)) return false;
    }
    const TetId stuck = next_pending(ctx);
    if (!stuck.valid()) break;
    if (!request(ctx, stuck, removability(ctx.mesh, stuck), true, report)) return false;
  }
  report.requested = static_cast<std::uint32_t>(removal.size());
  if (!ctx.selection.tool()) return true;

  // The pieces in rounds: a piece's request may split kept tets again, leaving smaller pieces in
  // the tool, which the next round requests. A few rounds empty the tool in practice; the bound
  // keeps a pathological cut from cascading (what stays is counted by the audit).
  // Basic (3.4) splits every kept neighbour around a piece's singularity again: its later rounds
  // only cut slivers the improvement pass cannot lift, so it requests its pieces once.
  const int rounds = ctx.params.strategy == RemovalStrategy::kBasic ? 1 : kPieceRounds;
  TetMesh::Savepoint made_from = ctx.start;
  for (int round = 0; round < rounds; ++round) {
    const TetMesh::Savepoint next = ctx.mesh.savepoint();
    work_.clear();
    for (const TetMesh::TetBirth& birth : ctx.mesh.tets_made_since(made_from))
      if (!tried_.contains(birth.tet) && ctx.selection.piece_in_tool(ctx.mesh, birth.tet, ctx.uncuttable))
        work_.push_back(birth.tet);
    if (work_.empty()) break;
    for (TetId t : work_) {
      if (!ctx.mesh.is_live(t) || tried_.contains(t)) continue;
      ++report.kept_pieces_requested;
      // A piece whose removal would need more tets than the cut has left stays, and the audit
      // counts it: the tool's selection is gone, and refusing the whole cut for a piece would
      // leave more. Only a cut already past its budget is refused.
      if (!request(ctx, t, removability(ctx.mesh, t), false, report))
        return ctx.mesh.net_tets_made_since(ctx.start) <= ctx.params.max_tets_created;
    }
    made_from = next;
  }
  return true;
}

}  // namespace tetcut::detail
