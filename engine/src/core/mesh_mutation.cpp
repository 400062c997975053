// TetMesh's mutations (the mesh itself: include/tetcut/mesh.hpp): vertices and tets allocated
// and freed, replace_tets() (the one way tets change: remove some, add some, glue the faces),
// reserve() and compact() (ids along a space-filling curve). Every write goes through note(), so
// that a transaction can roll it back (mesh_journal.cpp).
#include <algorithm>
#include <atomic>
#include <cassert>
#include <cstring>

#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/reserve_touched.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/space_filling_curve.hpp"

namespace tetcut {
namespace {

std::array<std::uint32_t, 3> sorted_face_key(const std::array<std::uint32_t, 4>& v, int face) {
  std::array<std::uint32_t, 3> k = {v[kFaceVerts[face][0]], v[kFaceVerts[face][1]], v[kFaceVerts[face][2]]};
  if (k[0] > k[1]) std::swap(k[0], k[1]);
  if (k[1] > k[2]) std::swap(k[1], k[2]);
  if (k[0] > k[1]) std::swap(k[0], k[1]);
  return k;
}

}  // namespace

VertId TetMesh::add_vertex(const Vec3& p) {
  VertId v;
  if (free_vert_head_.valid()) {
    v = free_vert_head_;
    note(Array::kFreeVertNext, v.value);
    note(Array::kPositions, v.value);
    note(Array::kAttributes, v.value);
    free_vert_head_ = free_vert_next_[v.value];
    free_vert_next_[v.value] = kNoVert;
    positions_[v.value] = p;
    for (std::uint32_t c = 0; c < attributes_.channel_count(); ++c)
      for (double& x : attributes_.value(c, v)) x = 0.0;
  } else {
    v = VertId{vertex_capacity()};
    positions_.push_back(p);
    vert_tet_.push_back(kNoTet);
    vert_boundary_faces_.push_back(0);
    free_vert_next_.push_back(kNoVert);
    attributes_.resize(vertex_capacity());
  }
  if (journal_.active) {
    journal_.vertex_birth_of.set(v, static_cast<std::uint32_t>(journal_.vertex_births.size()));
    journal_.vertex_births.push_back({v, kNoVert, kNoVert, 0.0, {}});
  }
  return v;
}

VertId TetMesh::add_vertex_on_edge(VertId a, VertId b, double t) {
  const Vec3 p = (1.0 - t) * positions_[a.value] + t * positions_[b.value];
  const VertId v = add_vertex(p);
  note(Array::kAttributes, v.value);
  attributes_.interpolate(v, a, b, t);
  if (journal_.active) {
    VertexBirth& birth = journal_.vertex_births.back();
    birth.a = a;
    birth.b = b;
    birth.t = t;
    compose_origin(a, b, t, birth.origin);
  }
  return v;
}

void TetMesh::move_vertex(VertId v, const Vec3& p, std::vector<TetId>* created) {
  assert(journal_.active && "a vertex moves inside a transaction, which records where it was");
  const std::uint32_t* birth_slot = journal_.vertex_birth_of.find(v);
  const bool made = birth_slot && *birth_slot < journal_.vertex_births.size() && journal_.vertex_births[*birth_slot].vertex == v;
  // A vertex there before: its first move records where it was (position_at_start()).
  if (!made && !current_move(v)) {
    journal_.vertex_move_of.set(v, static_cast<std::uint32_t>(journal_.vertex_moves.size()));
    journal_.vertex_moves.push_back({v, positions_[v.value], {}});
  }
  note(Array::kPositions, v.value);
  positions_[v.value] = p;
  vertex_shell(v, move_star_);
  move_tets_.clear();
  for (TetId t : move_star_) move_tets_.push_back(tet(t));
  replace_tets(move_star_, move_tets_, created);
  CreatedVertex& origin = made ? journal_.vertex_births[*birth_slot].origin
                               : journal_.vertex_moves[*journal_.vertex_move_of.find(v)].origin;
  locate_origin(v, origin);
  origin.vertex = v;
  if (!made) return;  // its channels at commit (interpolate_attributes_at_commit)
  note(Array::kAttributes, v.value);
  attributes_.combine(v, std::span<const VertId>(origin.from.data(), origin.count),
                      std::span<const double>(origin.weight.data(), origin.count));
}

TetId TetMesh::allocate_tet() {
  if (free_tet_head_.valid()) {
    const TetId t = free_tet_head_;
    free_tet_head_ = TetId{tet_verts_[t.value][1]};
    return t;
  }
  assert(tet_capacity() < kMaxTets);
  tet_verts_.push_back({kDeadTetMarker, kDeadTetMarker, kDeadTetMarker, kDeadTetMarker});
  tet_adj_.push_back({kNoNeighbour, kNoNeighbour, kNoNeighbour, kNoNeighbour});
  return TetId{tet_capacity() - 1};
}

void TetMesh::free_tet(TetId t) {
  note(Array::kTetVerts, t.value);
  note(Array::kTetAdj, t.value);
  // In a transaction the id waits on the pending list until commit(): never reused inside it.
  TetId& head = journal_.active ? pending_tet_head_ : free_tet_head_;
  if (journal_.active && !pending_tet_tail_.valid()) pending_tet_tail_ = t;
  tet_verts_[t.value] = {kDeadTetMarker, head.value, kDeadTetMarker, kDeadTetMarker};
  tet_adj_[t.value] = {kNoNeighbour, kNoNeighbour, kNoNeighbour, kNoNeighbour};
  head = t;
}

void TetMesh::free_vertex(VertId v) {
  assert(vert_boundary_faces_[v.value] == 0);
  note(Array::kVertTet, v.value);
  note(Array::kFreeVertNext, v.value);
  VertId& head = journal_.active ? pending_vert_head_ : free_vert_head_;
  if (journal_.active && !pending_vert_tail_.valid()) pending_vert_tail_ = v;
  vert_tet_[v.value] = kNoTet;
  free_vert_next_[v.value] = head;
  head = v;
}

// Journals a vertex's seed and boundary count once per replace_tets() call, however many of its
// faces and tets the call touches (the first record is the one a rollback keeps).
void TetMesh::touch_vertex(std::uint32_t v) {
  if (!vertex_noted_.insert(VertId{v})) return;
  note(Array::kVertTet, v);
  note(Array::kBoundary, v);
}

void TetMesh::replace_tets(std::span<const TetId> removed, std::span<const TetVerts> added,
                           std::vector<TetId>* created, std::span<const TetId> parent_of) {
  assert(parent_of.empty() || parent_of.size() == added.size());
  // Mark the removed tets so that "is this neighbour also going?" is O(1).
  removing_.clear();
  vertex_noted_.clear();
  for (TetId r : removed) {
    assert(is_live(r));
    removing_.insert(r);
    if (journal_.active && journal_.birth_of.contains(r)) ++journal_.births_removed;
  }

  scratch_faces_.clear();
  scratch_verts_.clear();
  open_cavity(removed);
  add_unglued(removed, added, created, parent_of);
  glue_faces();
  reseed_vertices();
  live_tets_ = live_tets_ - static_cast<std::uint32_t>(removed.size()) + static_cast<std::uint32_t>(added.size());
}

// 1. The cavity's outer faces; boundary faces that disappear; vertices losing their seed.
void TetMesh::open_cavity(std::span<const TetId> removed) {
  for (TetId r : removed) {
    const auto verts = tet_verts_[r.value];
    for (int f = 0; f < 4; ++f) {
      const std::uint32_t adj = tet_adj_[r.value][f];
      if (adj == kNoNeighbour) {
        for (int k = 0; k < 3; ++k) {
          touch_vertex(verts[kFaceVerts[f][k]]);
          --vert_boundary_faces_[verts[kFaceVerts[f][k]]];
        }
      } else if (!removing_.contains(TetId{adj >> 2})) {
        scratch_faces_.push_back({sorted_face_key(verts, f), adj, kNoSlot, 1});
      }
    }
    for (std::uint32_t v : verts) {
      const TetId seed = vert_tet_[v];
      if (seed.valid() && seed != kReseed && removing_.contains(seed)) {
        touch_vertex(v);
        vert_tet_[v] = kReseed;
        scratch_verts_.push_back(VertId{v});
      }
    }
  }
  for (TetId r : removed) free_tet(r);
}

// 2. The new tets, unglued for now, and their births.
void TetMesh::add_unglued(std::span<const TetId> removed, std::span<const TetVerts> added, std::vector<TetId>* created,
                          std::span<const TetId> parent_of) {
  for (std::size_t k = 0; k < added.size(); ++k) {
    const TetVerts& tv = added[k];
    const TetId t = allocate_tet();
    if (journal_.active) {
      const auto parents_begin = static_cast<std::uint32_t>(journal_.parents.size());
      if (parent_of.empty()) {
        journal_.parents.insert(journal_.parents.end(), removed.begin(), removed.end());
      } else {
        journal_.parents.push_back(parent_of[k]);
      }
      journal_.birth_of.set(t, static_cast<std::uint32_t>(journal_.tet_births.size()));
      journal_.tet_births.push_back({t, parents_begin, static_cast<std::uint32_t>(journal_.parents.size()) - parents_begin});
    }
    note(Array::kTetVerts, t.value);
    note(Array::kTetAdj, t.value);
    auto& verts = tet_verts_[t.value];
    for (int i = 0; i < 4; ++i) verts[i] = tv[i].value;
    tet_adj_[t.value] = {kNoNeighbour, kNoNeighbour, kNoNeighbour, kNoNeighbour};
    for (int f = 0; f < 4; ++f) scratch_faces_.push_back({sorted_face_key(verts, f), pack(t, f), kNoSlot, 0});
    for (std::uint32_t v : verts) {
      const TetId seed = vert_tet_[v];
      if (seed == kReseed || !seed.valid()) touch_vertex(v);
      if (seed == kReseed) {
        vert_tet_[v] = t;
      } else if (!seed.valid()) {  // a vertex made by add_vertex, used for the first time
        vert_tet_[v] = t;
        ++live_vertices_;
      }
    }
    if (created) created->push_back(t);
  }
}

// 3. Glue faces with equal vertex triples, matched through a small open-addressing table of
// slot indices (reused scratch: no allocation once grown). The pairs do not depend on the
// table's order, and everything below walks the slots in the order they were made, so the
// result is deterministic (a sort would do the same in O(n log n), about a quarter of a split).
void TetMesh::glue_faces() {
  const std::size_t n = scratch_faces_.size();
  std::size_t size = 16;
  while (size < 2 * n) size *= 2;
  if (face_table_.size() < size) face_table_.resize(size);
  std::fill(face_table_.begin(), face_table_.begin() + static_cast<std::ptrdiff_t>(size), kNoSlot);
  const std::size_t mask = size - 1;
  for (std::uint32_t i = 0; i < n; ++i) {
    FaceSlot& slot = scratch_faces_[i];
    slot.partner = kNoSlot;
    const auto& k = slot.key;
    std::size_t h = (k[0] * 0x9E3779B1u ^ k[1] * 0x85EBCA77u ^ k[2] * 0xC2B2AE3Du) & mask;
    for (;; h = (h + 1) & mask) {
      const std::uint32_t other = face_table_[h];
      if (other == kNoSlot) {
        face_table_[h] = i;
        break;
      }
      const auto& o = scratch_faces_[other].key;
      if (o[0] == k[0] && o[1] == k[1] && o[2] == k[2]) {  // not std::array's ==: a memcmp call
        assert(scratch_faces_[other].partner == kNoSlot && "a face would be shared by more than two tets");
        scratch_faces_[other].partner = i;
        slot.partner = other;
        break;
      }
    }
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    const FaceSlot& s = scratch_faces_[i];
    if (s.partner != kNoSlot) {
      if (s.partner < i) continue;  // glued from the first of the pair
      const std::uint32_t x = s.ref, y = scratch_faces_[s.partner].ref;
      // New tets were journaled when allocated; an outer tet is journaled per glued face.
      if (s.is_outer) note(Array::kTetAdj, x >> 2);
      if (scratch_faces_[s.partner].is_outer) note(Array::kTetAdj, y >> 2);
      tet_adj_[x >> 2][x & 3u] = y;
      tet_adj_[y >> 2][y & 3u] = x;
    } else {
      // Unmatched: a new boundary face (an outer face of the cavity left uncovered, or a face of
      // a new tet on the surface).
      if (s.is_outer) {
        note(Array::kTetAdj, s.ref >> 2);
        tet_adj_[s.ref >> 2][s.ref & 3u] = kNoNeighbour;
      }
      for (std::uint32_t v : s.key) {
        touch_vertex(v);
        ++vert_boundary_faces_[v];
      }
    }
  }
}

// 4. Vertices that lost their seed and got none from a new tet: any outer tet that contains
// them will do (in a manifold shell the remaining tets touch the removed ones through a face
// containing the vertex); none means the vertex has no tets left and goes too.
void TetMesh::reseed_vertices() {
  for (VertId v : scratch_verts_) {
    if (vert_tet_[v.value] != kReseed) continue;
    TetId seed = kNoTet;
    for (const FaceSlot& s : scratch_faces_) {
      if (!s.is_outer) continue;
      if (s.key[0] == v.value || s.key[1] == v.value || s.key[2] == v.value) {
        seed = TetId{s.ref >> 2};
        break;
      }
    }
    if (seed.valid()) {
      vert_tet_[v.value] = seed;  // journaled when it lost its seed
    } else {
      free_vertex(v);
      --live_vertices_;
    }
  }
}

void TetMesh::reserve(std::uint32_t tets, std::uint32_t vertices) {
  using detail::reserve_touched;
  reserve_touched(tet_verts_, tets);
  reserve_touched(tet_adj_, tets);
  removing_.reserve(tets);
  ancestor_seen_.reserve(tets);
  vertex_noted_.reserve(vertices);
  vertex_seen_.reserve(vertices);
  journal_.birth_of.reserve(tets);
  journal_.vertex_birth_of.reserve(vertices);
  journal_.vertex_move_of.reserve(vertices);
  journal_.first_verts_entry.reserve(tets);
  reserve_touched(positions_, vertices);
  reserve_touched(vert_tet_, vertices);
  reserve_touched(vert_boundary_faces_, vertices);
  reserve_touched(free_vert_next_, vertices);
  attributes_.reserve(vertices);
  // The working size of one operation: its journal and the faces replace_tets() glues. A larger
  // operation grows them once.
  reserve_touched(journal_.entries, kJournalWorkingSize);
  reserve_touched(journal_.tet_births, kJournalWorkingSize / 4);
  reserve_touched(journal_.parents, kJournalWorkingSize / 4);
  reserve_touched(journal_.vertex_births, kJournalWorkingSize / 16);
  // undo()'s scratch: the slots one operation wrote.
  undo_tets_.reserve(kJournalWorkingSize / 4);
  undo_vertices_.reserve(kJournalWorkingSize / 16);
  undo_moved_.reserve(kJournalWorkingSize / 16);
  reserve_touched(journal_.vertex_moves, kJournalWorkingSize / 64);
  reserve_touched(ancestor_stack_, 64);
  reserve_touched(move_star_, 128);
  reserve_touched(move_tets_, 128);
  reserve_touched(locate_scratch_, 64);
  reserve_touched(net_removed_scratch_, kJournalWorkingSize / 4);
  reserve_touched(net_created_scratch_, kJournalWorkingSize / 4);
  reserve_touched(scratch_faces_, 4096);
  reserve_touched(face_table_, 8192);
  reserve_touched(scratch_verts_, 1024);
}

Renumbering TetMesh::compact(IdOrder order) {
  const MeshWriteScope writing(*this, "TetMesh::compact()");
  assert(!journal_.active && "compact() inside a transaction");
  new_version();  // every id may mean another tet now: no undo comes back across this
  std::vector<TetId> tet_new_to_old;
  std::vector<VertId> vert_new_to_old;
  tet_new_to_old.reserve(live_tets_);
  vert_new_to_old.reserve(live_vertices_);
  for (std::uint32_t t = 0; t < tet_capacity(); ++t)
    if (tet_verts_[t][0] != kDeadTetMarker) tet_new_to_old.push_back(TetId{t});
  for (std::uint32_t v = 0; v < vertex_capacity(); ++v)
    if (vert_tet_[v].valid()) vert_new_to_old.push_back(VertId{v});
  if (order == IdOrder::kAlongCurve) {
    // Tets by their centroid's key, vertices by their own; ties keep the ids' order.
    BoundingBox box;
    for (VertId v : vert_new_to_old) box.add(positions_[v.value]);
    const MortonKey key(box);
    std::vector<std::uint64_t> keys;
    const auto sort_by_keys = [&keys](auto& ids) {
      const std::vector<std::uint32_t> by_key = order_by_key(keys);
      auto sorted = ids;
      for (std::size_t k = 0; k < ids.size(); ++k) sorted[k] = ids[by_key[k]];
      ids = std::move(sorted);
    };
    keys.reserve(tet_new_to_old.size());
    for (TetId t : tet_new_to_old) {
      const auto& tv = tet_verts_[t.value];
      keys.push_back(key(0.25 * (positions_[tv[0]] + positions_[tv[1]] + positions_[tv[2]] + positions_[tv[3]])));
    }
    sort_by_keys(tet_new_to_old);
    keys.clear();
    for (VertId v : vert_new_to_old) keys.push_back(key(positions_[v.value]));
    sort_by_keys(vert_new_to_old);
  }
  Renumbering map;
  map.tet_old_to_new.assign(tet_capacity(), kNoTet);
  map.vert_old_to_new.assign(vertex_capacity(), kNoVert);
  const auto nt = static_cast<std::uint32_t>(tet_new_to_old.size());
  const auto nv = static_cast<std::uint32_t>(vert_new_to_old.size());
  for (std::uint32_t n = 0; n < nt; ++n) map.tet_old_to_new[tet_new_to_old[n].value] = TetId{n};
  for (std::uint32_t n = 0; n < nv; ++n) map.vert_old_to_new[vert_new_to_old[n].value] = VertId{n};

  std::vector<std::array<std::uint32_t, 4>> verts(nt), adj(nt);
  for (std::uint32_t n = 0; n < nt; ++n) {
    const std::uint32_t t = tet_new_to_old[n].value;
    for (int i = 0; i < 4; ++i) {
      verts[n][i] = map.vert_old_to_new[tet_verts_[t][i]].value;
      const std::uint32_t a = tet_adj_[t][i];
      adj[n][i] = a == kNoNeighbour ? kNoNeighbour : pack(map.tet_old_to_new[a >> 2], static_cast<int>(a & 3u));
    }
  }
  std::vector<Vec3> positions(nv);
  std::vector<TetId> vert_tet(nv);
  std::vector<std::uint32_t> boundary(nv);
  for (std::uint32_t n = 0; n < nv; ++n) {
    const std::uint32_t old = vert_new_to_old[n].value;
    positions[n] = positions_[old];
    vert_tet[n] = map.tet_old_to_new[vert_tet_[old].value];
    boundary[n] = vert_boundary_faces_[old];
  }
  attributes_.permute(vert_new_to_old);

  tet_verts_ = std::move(verts);
  tet_adj_ = std::move(adj);
  positions_ = std::move(positions);
  vert_tet_ = std::move(vert_tet);
  vert_boundary_faces_ = std::move(boundary);
  free_vert_next_.assign(nv, kNoVert);
  free_tet_head_ = kNoTet;
  free_vert_head_ = kNoVert;
  id_epoch_.advance();
  return map;
}

std::uint64_t TetMesh::IdEpoch::next() {
  static std::atomic<std::uint64_t> count{0};
  return count.fetch_add(1, std::memory_order_relaxed) + 1;
}

}  // namespace tetcut
