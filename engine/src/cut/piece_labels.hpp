// Which face-connected piece of the mesh each tet is in, kept up to date by every cut without a
// mesh scan: labelled once when the Cutter indexes the mesh (O(#T)), then each committed cut
// gives its made tets their ancestors' label (a split child lies in its parent, a flip's tets in
// adjacent parents: one piece), drops its removed tets from their label's count, and moves the
// pieces it detached (fragment_search.hpp) to labels of their own. Cutter::pieces() is the number
// of labels with a tet.
//
// The label is what tells a piece the cut detached from a piece that was apart already: two
// pieces the cut's surface bounds were one before the cut exactly when they carry one label.
// A search stopped at its bound resolves nothing it did not finish: those pieces keep their
// label and the count may be short until the next reset() (CutReport::fragment_search_bounded).
//
// Empty of choices in the common case: while every live tet carries one label, a made tet's
// label is that one, with no look at its ancestors.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "tetcut/ids.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::detail {

class PieceLabels {
 public:
  // Room for tet ids up to `tets` (Cutter::prepare()).
  void reserve(std::uint32_t tets);
  // Labels every live tet by its piece (O(#T), outside a transaction).
  void build(const TetMesh& mesh);

  // The label of t: live outside the transaction, or made in the open one (its ancestors' at the
  // transaction's start).
  [[nodiscard]] std::uint32_t label(TetMesh& mesh, TetId t) const;
  [[nodiscard]] std::uint32_t pieces() const { return pieces_; }

  // Around a commit, as UncuttableTets: before it, the label of each tet the transaction made
  // since `start` and still has (`replaced`: the tets live at the start and gone, among which
  // every made tet's ancestors are: when they carry one label, so does every made tet, with no
  // look at ancestors); after it, those labels written, the removed tets dropped from their
  // labels' counts, and then each detached piece (its tets, live) moved to a new label.
  void before_commit(TetMesh& mesh, const TetMesh::Savepoint& start, std::span<const TetId> replaced);
  void after_commit(std::span<const TetId> removed);

  // What a committed transaction changed here, for Cutter::undo(): the counts before it and the
  // label each detached tet had.
  struct Undo {
    std::uint32_t pieces = 0, sole = 0, labels = 0;
    std::vector<std::pair<TetId, std::uint32_t>> relabelled;
  };
  // Before a commit that may be undone: the counts as they are.
  void keep(Undo& undo) const;
  // Moves a detached piece to a label of its own; with `undo`, notes the labels it had.
  void detach(std::span<const TetId> piece, Undo* undo = nullptr);
  // Takes back the committed transaction `undo` kept, while its made tets (`made`) are still
  // live and before the tets it removed (`restored`, whose labels are still here) are back.
  void take_back(const Undo& undo, std::span<const TetId> restored, std::span<const TetId> made);

 private:
  void count(std::uint32_t label, int delta);

  std::vector<std::uint32_t> label_;      // by tet id, for tets live outside a transaction
  std::vector<std::uint32_t> tets_of_;    // by label: its live tets
  std::uint32_t pieces_ = 0;              // labels with a tet
  std::uint32_t sole_ = 0;                // the one label in use, when pieces_ == 1
  std::vector<std::pair<TetId, std::uint32_t>> made_;  // before_commit(): each made tet's label
  mutable std::vector<TetId> ancestors_;
};

}  // namespace tetcut::detail
