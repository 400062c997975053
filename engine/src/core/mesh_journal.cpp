// TetMesh's journal (include/tetcut/mesh.hpp): transactions, nested savepoints and rollback. Each
// write of a mutation is noted once per array slot per transaction, with the slot's old value, so
// that rollback_to() restores the mesh bit for bit and changes_since() gives a savepoint's net
// change: what lets a failed cut, or an undone removal attempt, leave no trace.
#include <algorithm>
#include <cassert>
#include <cstring>

#include "tetcut/mesh.hpp"

namespace tetcut {

TetMesh::Savepoint TetMesh::savepoint() {
  Savepoint p;
  p.entries = static_cast<std::uint32_t>(journal_.entries.size());
  p.attribute_values = static_cast<std::uint32_t>(journal_.attribute_values.size());
  p.tets = tet_capacity();
  p.vertices = vertex_capacity();
  p.live_tets = live_tets_;
  p.live_vertices = live_vertices_;
  p.free_tet_head = free_tet_head_;
  p.pending_tet_head = pending_tet_head_;
  p.pending_tet_tail = pending_tet_tail_;
  p.free_vert_head = free_vert_head_;
  p.pending_vert_head = pending_vert_head_;
  p.pending_vert_tail = pending_vert_tail_;
  // From here on, rows appended before this point are recorded too (rollback_to(p) cannot
  // simply truncate them).
  journal_.recorded_tets = p.tets;
  journal_.recorded_vertices = p.vertices;
  return p;
}

void TetMesh::begin_transaction() {
  assert(!journal_.active && "transactions do not nest");
  journal_.entries.clear();
  journal_.attribute_values.clear();
  journal_.start = savepoint();
  journal_.active = true;
}

void TetMesh::commit() {
  journal_.active = false;
  journal_.entries.clear();
  journal_.attribute_values.clear();
  // The ids freed by the transaction become reusable now.
  if (pending_tet_head_.valid()) {
    tet_verts_[pending_tet_tail_.value][1] = free_tet_head_.value;
    free_tet_head_ = pending_tet_head_;
  }
  if (pending_vert_head_.valid()) {
    free_vert_next_[pending_vert_tail_.value] = free_vert_head_;
    free_vert_head_ = pending_vert_head_;
  }
  pending_tet_head_ = pending_tet_tail_ = kNoTet;
  pending_vert_head_ = pending_vert_tail_ = kNoVert;
}

// Records the old value of one element before it is written. Elements appended after the newest
// savepoint need no record: a rollback truncates the arrays to their old sizes.
void TetMesh::note(Array array, std::uint32_t index) {
  if (!journal_.active) return;
  const bool is_tet = array == Array::kTetVerts || array == Array::kTetAdj;
  if (index >= (is_tet ? journal_.recorded_tets : journal_.recorded_vertices)) return;
  JournalEntry e{array, index, {}};
  switch (array) {
    case Array::kTetVerts: std::memcpy(e.old.data(), tet_verts_[index].data(), 16); break;
    case Array::kTetAdj: std::memcpy(e.old.data(), tet_adj_[index].data(), 16); break;
    case Array::kPositions: e.old = std::bit_cast<std::array<std::uint32_t, 6>>(positions_[index]); break;
    case Array::kVertTet: e.old[0] = vert_tet_[index].value; break;
    case Array::kBoundary: e.old[0] = vert_boundary_faces_[index]; break;
    case Array::kFreeVertNext: e.old[0] = free_vert_next_[index].value; break;
    case Array::kAttributes:
      e.old[0] = static_cast<std::uint32_t>(journal_.attribute_values.size());
      for (std::uint32_t c = 0; c < attributes_.channel_count(); ++c)
        for (double x : attributes_.value(c, VertId{index})) journal_.attribute_values.push_back(x);
      break;
  }
  journal_.entries.push_back(e);
}

void TetMesh::rollback_to(const Savepoint& p) {
  assert(journal_.active && p.entries <= journal_.entries.size());
  for (std::size_t i = journal_.entries.size(); i-- > p.entries;) {
    const JournalEntry& e = journal_.entries[i];
    switch (e.array) {
      case Array::kTetVerts: std::memcpy(tet_verts_[e.index].data(), e.old.data(), 16); break;
      case Array::kTetAdj: std::memcpy(tet_adj_[e.index].data(), e.old.data(), 16); break;
      case Array::kPositions: positions_[e.index] = std::bit_cast<Vec3>(e.old); break;
      case Array::kVertTet: vert_tet_[e.index] = TetId{e.old[0]}; break;
      case Array::kBoundary: vert_boundary_faces_[e.index] = e.old[0]; break;
      case Array::kFreeVertNext: free_vert_next_[e.index] = VertId{e.old[0]}; break;
      case Array::kAttributes: {
        std::size_t k = e.old[0];
        for (std::uint32_t c = 0; c < attributes_.channel_count(); ++c)
          for (double& x : attributes_.value(c, VertId{e.index})) x = journal_.attribute_values[k++];
        break;
      }
    }
  }
  journal_.entries.resize(p.entries);
  journal_.attribute_values.resize(p.attribute_values);
  tet_verts_.resize(p.tets);
  tet_adj_.resize(p.tets);
  positions_.resize(p.vertices);
  vert_tet_.resize(p.vertices);
  vert_boundary_faces_.resize(p.vertices);
  free_vert_next_.resize(p.vertices);
  attributes_.resize(p.vertices);
  live_tets_ = p.live_tets;
  live_vertices_ = p.live_vertices;
  free_tet_head_ = p.free_tet_head;
  pending_tet_head_ = p.pending_tet_head;
  pending_tet_tail_ = p.pending_tet_tail;
  free_vert_head_ = p.free_vert_head;
  pending_vert_head_ = p.pending_vert_head;
  pending_vert_tail_ = p.pending_vert_tail;
  journal_.recorded_tets = p.tets;
  journal_.recorded_vertices = p.vertices;
}

void TetMesh::rollback() {
  assert(journal_.active);
  rollback_to(journal_.start);
  commit();  // nothing is pending any more: the start had no pending ids
}

void TetMesh::changes_since(const Savepoint& p, std::vector<TetId>& removed, std::vector<TetId>& created) {
  removed.clear();
  created.clear();
  if (!journal_.active) return;
  if (tet_stamp_.size() < tet_capacity()) tet_stamp_.resize(tet_capacity(), 0);
  if (++stamp_ == 0) {
    std::fill(tet_stamp_.begin(), tet_stamp_.end(), 0);
    std::fill(vert_stamp_.begin(), vert_stamp_.end(), 0);
    stamp_ = 1;
  }
  // The first entry after p of a row that existed at p holds its state at p.
  for (std::size_t i = p.entries; i < journal_.entries.size(); ++i) {
    const JournalEntry& e = journal_.entries[i];
    if (e.array != Array::kTetVerts || e.index >= p.tets || tet_stamp_[e.index] == stamp_) continue;
    tet_stamp_[e.index] = stamp_;
    std::array<std::uint32_t, 4> old;
    std::memcpy(old.data(), e.old.data(), 16);
    const bool was_live = old[0] != kDeadTetMarker;
    const bool is_live = tet_verts_[e.index][0] != kDeadTetMarker;
    const bool same = was_live && is_live && old == tet_verts_[e.index];
    if (same) continue;
    if (was_live) removed.push_back(TetId{e.index});
    if (is_live) created.push_back(TetId{e.index});
  }
  for (std::uint32_t t = p.tets; t < tet_capacity(); ++t)
    if (tet_verts_[t][0] != kDeadTetMarker) created.push_back(TetId{t});
  std::sort(removed.begin(), removed.end());
  std::sort(created.begin(), created.end());
}

}  // namespace tetcut
