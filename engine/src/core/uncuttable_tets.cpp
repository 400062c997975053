#include "core/uncuttable_tets.hpp"

#include <algorithm>

#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut::detail {

void UncuttableTets::reserve(std::uint32_t tets) {
  if (marked_.size() < tets) marked_.resize(tets, 0);
  reserve_touched(made_, 4096);
  reserve_touched(ancestors_, 64);
}

void UncuttableTets::assign(const TetMesh& mesh, std::span<const TetId> tets) {
  std::fill(marked_.begin(), marked_.end(), std::uint8_t{0});
  if (marked_.size() < mesh.tet_capacity()) marked_.resize(mesh.tet_capacity(), 0);
  for (TetId t : tets) marked_[t.value] = 1;
  active_ = !tets.empty();
}

void UncuttableTets::clear() {
  std::fill(marked_.begin(), marked_.end(), std::uint8_t{0});
  active_ = false;
}

bool UncuttableTets::marked(TetMesh& mesh, TetId t) const {
  if (!mesh.in_transaction() || !mesh.made_in_transaction(t)) return t.value < marked_.size() && marked_[t.value] != 0;
  // Made in the transaction: from its ancestors at the start (one, for a split's child).
  ancestors_.clear();
  mesh.ancestors_at_start(t, ancestors_);
  return std::any_of(ancestors_.begin(), ancestors_.end(), [&](TetId a) { return marked_[a.value] != 0; });
}

bool UncuttableTets::any_marked(TetMesh& mesh, std::span<const TetId> tets) const {
  return std::any_of(tets.begin(), tets.end(), [&](TetId t) { return marked(mesh, t); });
}

bool UncuttableTets::all_of(TetMesh& mesh, std::span<const TetId> tets) const {
  return active_ && std::all_of(tets.begin(), tets.end(), [&](TetId t) { return contains(mesh, t); });
}

void UncuttableTets::before_commit(TetMesh& mesh, const TetMesh::Savepoint& start) {
  made_.clear();
  if (!active_) return;
  for (const TetMesh::TetBirth& birth : mesh.tets_made_since(start))
    if (mesh.is_live(birth.tet)) made_.emplace_back(birth.tet, contains(mesh, birth.tet));
}

void UncuttableTets::after_commit(const TetMesh& mesh) {
  if (!active_) return;
  // Every made tet is written, 0 or 1: its id may be one an earlier transaction freed, whose
  // mark is stale (inside a transaction a made tet's mark comes from its ancestors, never from
  // here).
  if (marked_.size() < mesh.tet_capacity()) marked_.resize(mesh.tet_capacity(), 0);
  for (const auto& [t, uncuttable] : made_) marked_[t.value] = uncuttable ? 1 : 0;
  made_.clear();
}

void UncuttableTets::renumber(const Renumbering& map) {
  if (!active_) return;
  std::vector<std::uint8_t> renumbered(marked_.size(), 0);
  for (std::size_t old = 0; old < map.tet_old_to_new.size() && old < marked_.size(); ++old)
    if (marked_[old] != 0 && map.tet_old_to_new[old].valid()) renumbered[map.tet_old_to_new[old].value] = 1;
  marked_ = std::move(renumbered);
}

}  // namespace tetcut::detail
