// What every removal strategy works with during one request: the mesh (inside a transaction),
// the set test's workspace, the splitter, the request's history and its tet budget. The two
// mutations a strategy makes go through here, so that the history, the budget and the tets
// exposed to the tool stay right whichever strategy made them.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "refine/edge_split.hpp"
#include "remove/removal.hpp"
#include "remove/set_removal.hpp"
#include "tetcut/change_log.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::detail {

struct RemovalContext {
  TetMesh& mesh;
  SetRemovalWorkspace& ws;
  EdgeSplitter& splitter;
  ChangeLog& log;                   // the request's history (what survives of it)
  std::vector<TetId>& exposed;      // live tets that came to the surface
  std::uint32_t budget;             // tets the request may still create
  const Selection* selection = nullptr;  // the caller's selected tets, if any
  bool over_budget = false;         // a split was refused for the budget
  std::uint32_t tets_created = 0;   // by the splits that survive
  std::uint32_t edges_split = 0;

  // Where an attempt can come back to: the mesh's savepoint and the history's length.
  struct Mark {
    TetMesh::Savepoint mesh;
    std::size_t removed = 0, created = 0, vertices = 0;
    std::uint32_t tets_created = 0, edges_split = 0;
  };
  [[nodiscard]] Mark mark();
  // Undoes everything since `m`: the mesh bit for bit, the history, the counts.
  void rollback_to(const Mark& m);

  // Splits `edges` (templates), recording the split in the history and in `split_log`.
  // False, the mesh untouched, if the splitter refuses (degenerate child, over budget).
  bool split(std::span<const Edge> edges, ChangeLog& split_log);
  // Removes a set that set_removable() accepted, recording it and the tets it exposes.
  void remove_set(std::span<const TetId> set);

  // After a split: `set` plus every child of a selected parent not in it yet, into `out`; false
  // when there is none to add. A selected parent was to go whole, so its children, all of them,
  // are the same tissue: taking them in the same request spares the cut as many requests, each
  // of which would refine again (3.4's cascade of ever smaller tets).
  bool with_selected_children(std::span<const TetId> set, const ChangeLog& split_log, std::vector<TetId>& out);
};

}  // namespace tetcut::detail
