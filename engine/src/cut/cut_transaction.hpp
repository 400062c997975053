// The transaction a cut or a removal request is: opened before its first change, then either
// rolled back (the mesh bit for bit as before, the removal statistics as they were, so that a
// refused cut counts none of its requests) or committed (the uncuttable set brought up to date,
// the locator told what went and what came, the net change handed to the caller as the
// mesh's journal derives it: change_log.hpp).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/uncuttable_tets.hpp"
#include "cut/walking_locator.hpp"
#include "remove/removal.hpp"
#include "tetcut/change_log.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/removal_report.hpp"

namespace tetcut::detail {

class CutTransaction {
 public:
  void reserve();

  void begin(TetMesh& mesh, const Remover& remover);
  void roll_back(TetMesh& mesh, Remover& remover);
  // Commits; appends the net change to `log` when given. Returns the net tets created.
  // `known`: the net change as TetMesh::changes_since(start()) gave it just before (the search
  // for pieces asked it), when nothing changed since: not derived again.
  struct NetChange {
    std::span<const TetId> removed, created;
  };
  // `keep`: the mesh's record of the transaction, for an undo (TetMesh::commit).
  std::uint32_t commit(TetMesh& mesh, UncuttableTets& uncuttable, WalkingLocator& locator, ChangeLog* log,
                       const NetChange* known = nullptr, TetMesh::TransactionRecord* keep = nullptr);
  // An undo's net change, as the last one's (Cutter::last_removed(), last_created(), last_moved()).
  void undone(std::span<const TetId> removed, std::span<const TetId> created, std::span<const MovedVertex> moved) {
    forget();
    net_removed_.assign(removed.begin(), removed.end());
    net_created_.assign(created.begin(), created.end());
    keep_moved(moved);
  }
  // The Remover's statistics when the open (or last) transaction began.
  [[nodiscard]] const RemovalReport& removal_at_start() const { return removal_at_start_; }
  // A new call: no net change yet (a refused or empty cut reports none).
  void forget() {
    net_removed_.clear();
    net_created_.clear();
    net_moved_.clear();
  }

  [[nodiscard]] const TetMesh::Savepoint& start() const { return start_; }
  // The last committed transaction's net change: the ids live before and gone after, the ids
  // live after and not before.
  [[nodiscard]] const std::vector<TetId>& net_removed() const { return net_removed_; }
  [[nodiscard]] const std::vector<TetId>& net_created() const { return net_created_; }
  // And the vertices there before that it moved (ChangeLog::moved), as the checker reads them.
  [[nodiscard]] std::span<const RawMovedVertex> net_moved() const { return net_moved_; }

 private:
  TetMesh::Savepoint start_;
  RemovalReport removal_at_start_;  // the Remover's statistics when the transaction began
  ChangeLog changes_;               // the net change, derived by the journal at commit
  std::vector<TetId> net_removed_, net_created_;
  std::vector<TetId> rewired_;  // the tets whose neighbours it rewrote, for the locator
  std::vector<MovedVertex> moved_;       // the journal's, when no log is asked for
  std::vector<RawMovedVertex> net_moved_;
  void keep_moved(std::span<const MovedVertex> moved);
};

}  // namespace tetcut::detail
