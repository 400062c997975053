#include "cut/cut_transaction.hpp"

#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut::detail {

void CutTransaction::reserve() {
  // The working size of a cut's change; a larger cut grows them once (allocations per cut are
  // gated by ci/bench).
  constexpr std::size_t kCutScratch = 16384;
  for (auto* list : {&net_removed_, &net_created_, &rewired_, &changes_.removed, &changes_.parents}) reserve_touched(*list, kCutScratch);
  reserve_touched(changes_.created, kCutScratch);
  reserve_touched(changes_.vertices, kCutScratch);
  reserve_touched(changes_.removed_vertices, kCutScratch);
  reserve_touched(changes_.moved, kCutScratch / 16);
  reserve_touched(moved_, kCutScratch / 16);
  reserve_touched(net_moved_, kCutScratch / 16);
}

void CutTransaction::begin(TetMesh& mesh, const Remover& remover) {
  mesh.begin_transaction();
  start_ = mesh.savepoint();
  removal_at_start_ = remover.report();
}

void CutTransaction::roll_back(TetMesh& mesh, Remover& remover) {
  mesh.rollback();
  remover.restore_report(removal_at_start_);
  forget();
}

std::uint32_t CutTransaction::commit(TetMesh& mesh, UncuttableTets& uncuttable, WalkingLocator& locator, ChangeLog* log,
                                     const NetChange* known, TetMesh::TransactionRecord* keep) {
  uncuttable.before_commit(mesh, start_);
  rewired_.clear();
  mesh.rewired_tets(rewired_);  // before the commit hands the journal to `keep`
  if (log) {
    changes_.clear();
    mesh.commit(&changes_, keep);
    net_removed_.assign(changes_.removed.begin(), changes_.removed.end());
    net_created_.clear();
    for (const CreatedTet& c : changes_.created) net_created_.push_back(c.tet);
    keep_moved(changes_.moved);
    append(*log, changes_);
  } else {
    // Nobody reads the parents and origins: the ids alone, for the index, and the moves, for
    // the checker.
    if (known) {
      net_removed_.assign(known->removed.begin(), known->removed.end());
      net_created_.assign(known->created.begin(), known->created.end());
    } else {
      mesh.transaction_changes(net_removed_, net_created_);
    }
    mesh.moved_vertices(moved_);
    keep_moved(moved_);
    mesh.commit(nullptr, keep);
  }
  uncuttable.after_commit(mesh);
  locator.update(mesh, net_removed_, net_created_, rewired_);
  return static_cast<std::uint32_t>(net_created_.size());
}

void CutTransaction::keep_moved(std::span<const MovedVertex> moved) {
  net_moved_.clear();
  for (const MovedVertex& m : moved) net_moved_.push_back(raw_moved(m));
}

}  // namespace tetcut::detail
