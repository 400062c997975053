#include "cut/piece_labels.hpp"

#include <algorithm>

#include "core/pieces.hpp"
#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut::detail {

void PieceLabels::reserve(std::uint32_t tets) {
  if (label_.size() < tets) label_.resize(tets, 0);
  reserve_touched(made_, 16384);
  reserve_touched(ancestors_, 64);
  reserve_touched(tets_of_, 1024);
}

void PieceLabels::build(const TetMesh& mesh) {
  const Pieces pieces = face_connected_pieces(mesh);
  if (label_.size() < pieces.of_tet.size()) label_.resize(pieces.of_tet.size(), 0);
  std::fill(label_.begin(), label_.end(), 0u);
  tets_of_.assign(pieces.count, 0);
  for (std::size_t t = 0; t < pieces.of_tet.size(); ++t) {
    if (pieces.of_tet[t] == kNoPiece) continue;
    label_[t] = pieces.of_tet[t];
    ++tets_of_[pieces.of_tet[t]];
  }
  pieces_ = pieces.count;
  sole_ = 0;
}

std::uint32_t PieceLabels::label(TetMesh& mesh, TetId t) const {
  if (pieces_ == 1) return sole_;
  if (!mesh.in_transaction() || !mesh.made_in_transaction(t)) return label_[t.value];
  ancestors_.clear();
  mesh.ancestors_at_start(t, ancestors_);
  return ancestors_.empty() ? sole_ : label_[ancestors_.front().value];
}

void PieceLabels::before_commit(TetMesh& mesh, const TetMesh::Savepoint& start, std::span<const TetId> replaced) {
  made_.clear();
  const bool one_label =
      pieces_ == 1 || std::all_of(replaced.begin(), replaced.end(), [&](TetId t) { return label_[t.value] == label_[replaced.front().value]; });
  const std::uint32_t shared = pieces_ == 1 || replaced.empty() ? sole_ : label_[replaced.front().value];
  for (const TetMesh::TetBirth& birth : mesh.tets_made_since(start))
    if (mesh.is_live(birth.tet)) made_.emplace_back(birth.tet, one_label ? shared : label(mesh, birth.tet));
}

void PieceLabels::after_commit(std::span<const TetId> removed) {
  // The removed ids were live before and are not reused inside the transaction: their labels
  // are still here.
  for (TetId t : removed) count(label_[t.value], -1);
  for (const auto& [t, l] : made_) {
    if (label_.size() <= t.value) label_.resize(t.value + 1 + label_.size() / 2, 0);
    label_[t.value] = l;
    count(l, +1);
  }
  made_.clear();
}

void PieceLabels::keep(Undo& undo) const {
  undo.pieces = pieces_;
  undo.sole = sole_;
  undo.labels = static_cast<std::uint32_t>(tets_of_.size());
  undo.relabelled.clear();
}

void PieceLabels::take_back(const Undo& undo, std::span<const TetId> restored, std::span<const TetId> made) {
  for (auto it = undo.relabelled.rbegin(); it != undo.relabelled.rend(); ++it) {
    count(label_[it->first.value], -1);
    label_[it->first.value] = it->second;
    count(it->second, +1);
  }
  for (TetId t : made) count(label_[t.value], -1);
  for (TetId t : restored) count(label_[t.value], +1);
  // The labels the transaction opened are empty again: gone, and the counts as they were.
  tets_of_.resize(undo.labels);
  pieces_ = undo.pieces;
  sole_ = undo.sole;
}

void PieceLabels::detach(std::span<const TetId> piece, Undo* undo) {
  const auto fresh = static_cast<std::uint32_t>(tets_of_.size());
  tets_of_.push_back(0);
  for (TetId t : piece) {
    if (undo) undo->relabelled.emplace_back(t, label_[t.value]);
    count(label_[t.value], -1);
    label_[t.value] = fresh;
    count(fresh, +1);
  }
}

void PieceLabels::count(std::uint32_t label, int delta) {
  std::uint32_t& n = tets_of_[label];
  if (delta > 0 && n++ == 0) ++pieces_;
  if (delta < 0 && --n == 0) --pieces_;
  if (pieces_ == 1 && n > 0) sole_ = label;
  else if (pieces_ == 1 && n == 0) sole_ = static_cast<std::uint32_t>(
      std::find_if(tets_of_.begin(), tets_of_.end(), [](std::uint32_t k) { return k > 0; }) - tets_of_.begin());
}

}  // namespace tetcut::detail
