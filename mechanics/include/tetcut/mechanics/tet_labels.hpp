// Per-tet labels (regions, materials: RawMesh::labels as a file gives them) that follow a mesh
// through its operations' change logs, for a consumer that needs the labels and not the elastic
// model: the command line writes them back after `tetcut cut`, `tetcut remove`, a scenario. The
// tets a cut creates take their parent's label by the rule of label_rule.hpp, which the elastic
// model follows too (TensorMassModel::label): the same function.
//
// Why beside the engine and not in it: the labels are the user's data, like the model's
// material, and the change log is the one record of what a cut did (change_log.hpp); the engine's
// transaction, undo and compaction stay as they are, and a mesh without labels pays nothing.
//
// Cost: apply() is O(entries of the log) and allocates nothing once reserve() made room for the
// tet ids the mesh will reach (the Cutter's prepare() room).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "tetcut/change_log.hpp"
#include "tetcut/ids.hpp"
#include "tetcut/mechanics/label_rule.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::mechanics {

class TetLabels {
 public:
  TetLabels() = default;
  // `labels` by TetId of `mesh` (at least tet_capacity() long, read for live tets only).
  TetLabels(const TetMesh& mesh, std::span<const std::uint32_t> labels);

  void reserve(std::uint32_t tets);

  // The operation's net change, on the mesh as it is after it (the pre-cut vertices the parents
  // use are still where they were: a cut moves only the vertices it creates). Returns the number
  // of created tets none of whose parents this tracker had (0 for the mesh's own log): they get
  // kNoLabel.
  // An undo's log (ChangeLog::undo) gives its restored tets the labels the operation it takes
  // back found them with, from the history below; with none kept for it, they get kNoLabel and
  // count as orphans.
  std::uint32_t apply(const TetMesh& mesh, const ChangeLog& log);
  // How many applied logs keep the labels of the tets they removed, for their undo (newest
  // first; CutParams::undo_history, the Cutter's). 0, the default: none.
  void keep_history(std::uint32_t logs);
  // After TetMesh::compact() (or Cutter::compact()): the labels follow their tets.
  void renumber(const Renumbering& renumbering);

  // kNoLabel for an id the tracker has no live tet for.
  [[nodiscard]] std::uint32_t label(TetId t) const { return t.value < labels_.size() ? labels_[t.value] : kNoLabel; }
  // By TetId, tet_capacity() long at least after apply() (what io's write_mesh takes).
  [[nodiscard]] std::span<const std::uint32_t> by_tet() const { return labels_; }

 private:
  static constexpr std::uint32_t kDead = 0xFFFFFFFFu;
  std::uint32_t restore(const TetMesh& mesh, const ChangeLog& log);  // apply() of an undo's log
  [[nodiscard]] bool has(TetId t) const { return t.value < tets_.size() && tets_[t.value][0] != kDead; }

  std::vector<std::array<std::uint32_t, 4>> tets_;  // the vertices of each tet it has (kDead: none)
  std::vector<std::uint32_t> labels_;
  std::vector<std::uint32_t> created_labels_;      // scratch
  // A ring of history_limit_ entries, kept_ of them in use, the newest at newest_: per applied
  // log, the tets it removed with their labels, sorted by id.
  std::vector<std::vector<std::pair<TetId, std::uint32_t>>> history_;
  std::uint32_t history_limit_ = 0, kept_ = 0, newest_ = 0;
};

}  // namespace tetcut::mechanics
