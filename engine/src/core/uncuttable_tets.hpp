// Tissue a cut must leave (the paper's Fig. 7 frees the portal vein from the resected liver): a
// set of tets no removal may take, which the tets later made from them join. A cut's removal
// decisions are the engine's (selection, 3.5's neighbour sets, the pieces 3.4 / 3.7 and the
// fallback remove, the improvement pass), so the set is asked inside the transaction, for tets
// the cut itself made too: a tet made in the open transaction is uncuttable when one of its
// ancestors at the transaction's start is (the journal's record of parents). The improvement
// pass keeps the set's region exactly: it flips only among tets of one kind and never moves or
// collapses a vertex of an uncuttable tet (improver.cpp), so a split child, the one way the cut
// makes uncuttable tets, lies in its uncuttable parent.
//
// Empty (nothing ever marked), every query is false at the cost of one test: an unprotected cut
// is the same cut, bit for bit.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "tetcut/mesh.hpp"

namespace tetcut::detail {

class UncuttableTets {
 public:
  // Room for tet ids up to `tets`, so that bringing the set up to date after a cut does not
  // allocate (Cutter::prepare()).
  void reserve(std::uint32_t tets);
  // Replaces the set: these live tets (outside a transaction). Empty: none.
  void assign(const TetMesh& mesh, std::span<const TetId> tets);
  void clear();
  [[nodiscard]] bool empty() const { return !active_; }

  // Whether t is uncuttable; t live, or made in the open transaction. Inline up to the empty
  // set's answer: a cut asks it of every tet it selects and every piece it makes.
  [[nodiscard]] bool contains(TetMesh& mesh, TetId t) const { return active_ && marked(mesh, t); }
  // Whether any of `tets` is; whether all of them are.
  [[nodiscard]] bool any_of(TetMesh& mesh, std::span<const TetId> tets) const { return active_ && any_marked(mesh, tets); }
  [[nodiscard]] bool all_of(TetMesh& mesh, std::span<const TetId> tets) const;

  // Around a commit: before it, what each tet the transaction made since `start` and still has
  // is; after it, those become the set's own record (their ids are the mesh's now).
  void before_commit(TetMesh& mesh, const TetMesh::Savepoint& start);
  void after_commit(const TetMesh& mesh);

  // After TetMesh::compact(): the same tets under their new ids.
  void renumber(const Renumbering& map);

 private:
  [[nodiscard]] bool marked(TetMesh& mesh, TetId t) const;
  [[nodiscard]] bool any_marked(TetMesh& mesh, std::span<const TetId> tets) const;

  bool active_ = false;
  std::vector<std::uint8_t> marked_;  // by tet id, for tets live outside a transaction
  std::vector<std::pair<TetId, bool>> made_;  // before_commit(): each made tet, uncuttable or not
  mutable std::vector<TetId> ancestors_;
};

}  // namespace tetcut::detail
