// What every removal strategy works with during one request: the mesh (inside a transaction),
// the set test's workspace, the splitter and the request's tet budget. The two mutations a
// strategy makes go through here, so that the budget and the tets exposed to the tool stay right
// whichever strategy made them. What a split made, and every undo, come from the mesh's journal:
// a strategy takes a savepoint, splits, reads the split's children there, and rolls back to it.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/uncuttable_tets.hpp"
#include "refine/edge_split.hpp"
#include "remove/selection.hpp"
#include "remove/set_removal.hpp"
#include "remove/tissue_removal.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::detail {

struct RemovalContext {
  TetMesh& mesh;
  SetRemovalWorkspace& ws;
  EdgeSplitter& splitter;
  std::vector<TetId>& exposed;      // live tets that came to the surface
  TetMesh::Savepoint start;         // the request's start: its budget counts what it made since
  std::uint32_t budget;             // tets the request may create
  const Selection* selection = nullptr;  // the caller's selected tets, if any
  bool over_budget = false;         // a split was refused for the budget
  const UncuttableTets* uncuttable = nullptr;  // tets no set may take, if any
  TissueRemoval* tissue = nullptr;             // the one removal path (tissue_removal.hpp)

  // Whether `set` may go: it holds no uncuttable tet and lies within the cut's reach
  // (tissue_removal.hpp). Asked with the removability test, before every removal (plan, then
  // apply).
  [[nodiscard]] bool may_remove(std::span<const TetId> set) const {
    return may_remove_beyond_reach(set) && tissue->within_reach(mesh, set);
  }
  // The fallback's test: no uncuttable tet, wherever the set reaches. Its proof (docs/
  // removal-proof.md) needs the pieces it builds around T, which only a neighbourhood of coarse
  // tets puts beyond the reach; such a removal is counted (CutReport::tets_removed_beyond_reach).
  [[nodiscard]] bool may_remove_beyond_reach(std::span<const TetId> set) const {
    return !uncuttable || !uncuttable->any_of(mesh, set);
  }

  // Splits `edges` (templates). False, the mesh untouched, if the splitter refuses (degenerate
  // child, over budget). Its children and midpoints are what the mesh made since a savepoint
  // taken before the call (TetMesh::tets_made_since). `point`: where the new vertices go (the
  // fallback, whose proof holds for any point inside each edge, lets the splitter move them).
  bool split(std::span<const Edge> edges, SplitPoint point = SplitPoint::kMidpoint);
  // Removes a set that set_removable() and may_remove() accepted, through the one removal path,
  // recording the tets it exposes.
  void remove_set(std::span<const TetId> set);

  // After a split made `children`: `set` plus every child of a selected parent not in it yet,
  // into `out`; false when there is none to add. A selected parent was to go whole, so its
  // children, all of them, are the same tissue: taking them in the same request spares the cut
  // as many requests, each of which would refine again (3.4's cascade of ever smaller tets).
  bool with_selected_children(std::span<const TetId> set, std::span<const TetMesh::TetBirth> children,
                              std::vector<TetId>& out);
};

}  // namespace tetcut::detail
