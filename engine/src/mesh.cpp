#include "tetcut/mesh.hpp"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cstring>

#include "detail/reserve_touched.hpp"
#include "tetcut/local_tables.hpp"
#include "tetcut/predicates.hpp"

namespace tetcut {
namespace {

std::array<std::uint32_t, 3> sorted_face_key(const std::array<std::uint32_t, 4>& v, int face) {
  std::array<std::uint32_t, 3> k = {v[kFaceVerts[face][0]], v[kFaceVerts[face][1]], v[kFaceVerts[face][2]]};
  if (k[0] > k[1]) std::swap(k[0], k[1]);
  if (k[1] > k[2]) std::swap(k[1], k[2]);
  if (k[0] > k[1]) std::swap(k[0], k[1]);
  return k;
}

bool contains(const std::vector<TetId>& tets, TetId t) {
  return std::find(tets.begin(), tets.end(), t) != tets.end();
}

}  // namespace

// Rotation about an edge (style: CGAL's next_around_edge). We enter a tet through one of the two
// faces containing the edge; we leave through the other one.
namespace {
struct EdgeWalker {
  const std::vector<std::array<std::uint32_t, 4>>& verts;
  const std::vector<std::array<std::uint32_t, 4>>& adj;
  std::uint32_t a, b;

  // The face of t, other than `entered`, that contains edge (a, b).
  int exit_face(std::uint32_t t, int entered) const {
    int la = 0, lb = 0;
    for (int i = 0; i < 4; ++i) {
      if (verts[t][i] == a) la = i;
      if (verts[t][i] == b) lb = i;
    }
    const std::uint8_t e = kEdgeIndex[la][lb];
    return kEdgeFaces[e][0] == entered ? kEdgeFaces[e][1] : kEdgeFaces[e][0];
  }
};
}  // namespace

bool TetMesh::is_boundary_edge(TetId t, int local_edge) const {
  EdgeWalker walk{tet_verts_, tet_adj_, tet_verts_[t.value][kEdgeVerts[local_edge][0]],
                  tet_verts_[t.value][kEdgeVerts[local_edge][1]]};
  std::uint32_t cur = t.value;
  int face = kEdgeFaces[local_edge][0];
  // A manifold edge shell closes or ends; the bound only guards against corrupted adjacency.
  for (std::uint32_t steps = 0; steps <= tet_capacity(); ++steps) {
    const std::uint32_t adj = tet_adj_[cur][face];
    if (adj == kNoNeighbour) return true;
    cur = adj >> 2;
    if (cur == t.value) return false;
    face = walk.exit_face(cur, static_cast<int>(adj & 3u));
  }
  assert(false && "edge walk did not terminate: corrupted adjacency");
  return true;
}

bool TetMesh::edge_shell(TetId t, int local_edge, std::vector<TetId>& out) const {
  out.clear();
  EdgeWalker walk{tet_verts_, tet_adj_, tet_verts_[t.value][kEdgeVerts[local_edge][0]],
                  tet_verts_[t.value][kEdgeVerts[local_edge][1]]};
  // First direction: out of face kEdgeFaces[e][1]; collected backwards, then reversed, so that
  // the result reads from one end (boundary face) through t to the other.
  std::uint32_t cur = t.value;
  int face = kEdgeFaces[local_edge][1];
  bool open = false;
  for (std::uint32_t steps = 0; steps <= tet_capacity(); ++steps) {
    const std::uint32_t adj = tet_adj_[cur][face];
    if (adj == kNoNeighbour) {
      open = true;
      break;
    }
    cur = adj >> 2;
    if (cur == t.value) break;
    out.push_back(TetId{cur});
    face = walk.exit_face(cur, static_cast<int>(adj & 3u));
  }
  if (!open) {
    // Closed ring: t first, then the ring in the direction walked.
    out.insert(out.begin(), t);
    return false;
  }
  std::reverse(out.begin(), out.end());
  out.push_back(t);
  cur = t.value;
  face = kEdgeFaces[local_edge][0];
  for (std::uint32_t steps = 0; steps <= tet_capacity(); ++steps) {
    const std::uint32_t adj = tet_adj_[cur][face];
    if (adj == kNoNeighbour) break;
    cur = adj >> 2;
    out.push_back(TetId{cur});
    face = walk.exit_face(cur, static_cast<int>(adj & 3u));
  }
  return true;
}

void TetMesh::vertex_shell(VertId v, std::vector<TetId>& out) const {
  out.clear();
  const TetId seed = vert_tet_[v.value];
  if (!seed.valid()) return;
  out.push_back(seed);
  // Breadth-first through the faces that contain v: in a manifold mesh they connect the shell.
  for (std::size_t i = 0; i < out.size(); ++i) {
    const TetId cur = out[i];
    const int lv = local_index(cur, v);
    for (int f = 0; f < 4; ++f) {
      if (f == lv) continue;
      const std::uint32_t adj = tet_adj_[cur.value][f];
      if (adj == kNoNeighbour) continue;
      const TetId next{adj >> 2};
      if (!contains(out, next)) out.push_back(next);
    }
  }
}

void TetMesh::vertex_neighbours(VertId v, std::vector<VertId>& out, std::vector<TetId>& shell_scratch) const {
  vertex_shell(v, shell_scratch);
  out.clear();
  for (TetId t : shell_scratch)
    for (std::uint32_t w : tet_verts_[t.value])
      if (w != v.value && std::find(out.begin(), out.end(), VertId{w}) == out.end()) out.push_back(VertId{w});
}

void TetMesh::boundary_faces(std::vector<FaceRef>& out) const {
  out.clear();
  for (std::uint32_t t = 0; t < tet_capacity(); ++t) {
    if (tet_verts_[t][0] == kDeadTetMarker) continue;
    for (int f = 0; f < 4; ++f)
      if (tet_adj_[t][f] == kNoNeighbour) out.push_back({TetId{t}, static_cast<std::uint8_t>(f)});
  }
}

Vec3 TetMesh::boundary_normal(VertId v) const {
  std::vector<TetId> shell;
  return boundary_normal(v, shell);
}

Vec3 TetMesh::boundary_normal(VertId v, std::vector<TetId>& shell_scratch) const {
  if (!is_live(v) || !is_boundary_vertex(v)) return {};
  vertex_shell(v, shell_scratch);
  Vec3 sum{};
  for (TetId t : shell_scratch) {
    const int lv = local_index(t, v);
    const auto& verts = tet_verts_[t.value];
    for (int f = 0; f < 4; ++f) {
      if (f == lv || tet_adj_[t.value][f] != kNoNeighbour) continue;
      const Vec3& p = positions_[verts[kFaceVerts[f][0]]];
      const Vec3& q = positions_[verts[kFaceVerts[f][1]]];
      const Vec3& r = positions_[verts[kFaceVerts[f][2]]];
      sum = sum + cross(q - p, r - p);  // twice the area times the outward unit normal
    }
  }
  const double len = norm(sum);
  return len > 0.0 ? (1.0 / len) * sum : Vec3{};
}

double TetMesh::volume(TetId t) const {
  const auto& v = tet_verts_[t.value];
  return signed_volume(positions_[v[0]], positions_[v[1]], positions_[v[2]], positions_[v[3]]);
}

double TetMesh::mean_edge_length() const {
  double sum = 0.0;
  std::uint64_t n = 0;
  for (std::uint32_t t = 0; t < tet_capacity(); ++t) {
    if (!is_live(TetId{t})) continue;
    for (int e = 0; e < 6; ++e) {
      sum += norm(position(vertex(TetId{t}, kEdgeVerts[e][1])) - position(vertex(TetId{t}, kEdgeVerts[e][0])));
      ++n;
    }
  }
  return n > 0 && sum > 0 ? sum / static_cast<double>(n) : 1.0;
}

double TetMesh::total_volume() const {
  double sum = 0.0;
  for (std::uint32_t t = 0; t < tet_capacity(); ++t)
    if (tet_verts_[t][0] != kDeadTetMarker) sum += volume(TetId{t});
  return sum;
}

// ---- mutation -----------------------------------------------------------------------------

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
      for (double& x : attributes_.value(c, v.value)) x = 0.0;
  } else {
    v = VertId{vertex_capacity()};
    positions_.push_back(p);
    vert_tet_.push_back(kNoTet);
    vert_boundary_faces_.push_back(0);
    free_vert_next_.push_back(kNoVert);
    attributes_.resize(vertex_capacity());
  }
  return v;
}

VertId TetMesh::add_vertex_on_edge(VertId a, VertId b, double t) {
  const Vec3 p = (1.0 - t) * positions_[a.value] + t * positions_[b.value];
  const VertId v = add_vertex(p);
  note(Array::kAttributes, v.value);
  attributes_.interpolate(v.value, a.value, b.value, t);
  return v;
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
  if (vert_stamp_[v] == stamp_) return;
  vert_stamp_[v] = stamp_;
  note(Array::kVertTet, v);
  note(Array::kBoundary, v);
}

void TetMesh::replace_tets(std::span<const TetId> removed, std::span<const TetVerts> added,
                           std::vector<TetId>* created) {
  // Stamp the removed tets so that "is this neighbour also going?" is O(1).
  if (tet_stamp_.size() < tet_capacity()) tet_stamp_.resize(tet_capacity(), 0);
  if (++stamp_ == 0) {
    std::fill(tet_stamp_.begin(), tet_stamp_.end(), 0);
    std::fill(vert_stamp_.begin(), vert_stamp_.end(), 0);
    stamp_ = 1;
  }
  for (TetId r : removed) {
    assert(is_live(r));
    tet_stamp_[r.value] = stamp_;
  }
  if (vert_stamp_.size() < vertex_capacity()) vert_stamp_.resize(vertex_capacity(), 0);

  scratch_faces_.clear();
  scratch_verts_.clear();

  // 1. The cavity's outer faces; boundary faces that disappear; vertices losing their seed.
  for (TetId r : removed) {
    const auto verts = tet_verts_[r.value];
    for (int f = 0; f < 4; ++f) {
      const std::uint32_t adj = tet_adj_[r.value][f];
      if (adj == kNoNeighbour) {
        for (int k = 0; k < 3; ++k) {
          touch_vertex(verts[kFaceVerts[f][k]]);
          --vert_boundary_faces_[verts[kFaceVerts[f][k]]];
        }
      } else if (tet_stamp_[adj >> 2] != stamp_) {
        scratch_faces_.push_back({sorted_face_key(verts, f), adj, kNoSlot, 1});
      }
    }
    for (std::uint32_t v : verts) {
      const TetId seed = vert_tet_[v];
      if (seed.valid() && seed != kReseed && tet_stamp_[seed.value] == stamp_) {
        touch_vertex(v);
        vert_tet_[v] = kReseed;
        scratch_verts_.push_back(VertId{v});
      }
    }
  }
  for (TetId r : removed) free_tet(r);

  // 2. The new tets, unglued for now.
  for (const TetVerts& tv : added) {
    const TetId t = allocate_tet();
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

  // 3. Glue faces with equal vertex triples, matched through a small open-addressing table of
  // slot indices (reused scratch: no allocation once grown). The pairs do not depend on the
  // table's order, and everything below walks the slots in the order they were made, so the
  // result is deterministic. (A sort did the same in O(n log n) and was a quarter of a split.)
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
      if (scratch_faces_[other].key == k) {
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

  // 4. Vertices that lost their seed and got none from a new tet: any outer tet that contains
  // them will do (in a manifold shell the remaining tets touch the removed ones through a face
  // containing the vertex); none means the vertex has no tets left and goes too.
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

  live_tets_ = live_tets_ - static_cast<std::uint32_t>(removed.size()) + static_cast<std::uint32_t>(added.size());
}

void TetMesh::reserve(std::uint32_t tets, std::uint32_t vertices) {
  using detail::reserve_touched;
  reserve_touched(tet_verts_, tets);
  reserve_touched(tet_adj_, tets);
  reserve_touched(tet_stamp_, tets);
  reserve_touched(vert_stamp_, vertices);
  reserve_touched(positions_, vertices);
  reserve_touched(vert_tet_, vertices);
  reserve_touched(vert_boundary_faces_, vertices);
  reserve_touched(free_vert_next_, vertices);
  attributes_.reserve(vertices);
  // The working size of one operation: its journal and the faces replace_tets() glues. A larger
  // operation grows them once.
  reserve_touched(journal_.entries, kJournalWorkingSize);
  reserve_touched(scratch_faces_, 4096);
  reserve_touched(face_table_, 8192);
  reserve_touched(scratch_verts_, 1024);
}

Renumbering TetMesh::compact() {
  assert(!journal_.active && "compact() inside a transaction");
  Renumbering map;
  map.tet_old_to_new.assign(tet_capacity(), kNoTet);
  map.vert_old_to_new.assign(vertex_capacity(), kNoVert);
  std::uint32_t nt = 0, nv = 0;
  for (std::uint32_t t = 0; t < tet_capacity(); ++t)
    if (tet_verts_[t][0] != kDeadTetMarker) map.tet_old_to_new[t] = TetId{nt++};
  std::vector<std::uint32_t> vert_new_to_old;
  vert_new_to_old.reserve(live_vertices_);
  for (std::uint32_t v = 0; v < vertex_capacity(); ++v)
    if (vert_tet_[v].valid()) {
      map.vert_old_to_new[v] = VertId{nv++};
      vert_new_to_old.push_back(v);
    }

  std::vector<std::array<std::uint32_t, 4>> verts(nt), adj(nt);
  for (std::uint32_t t = 0; t < tet_capacity(); ++t) {
    const TetId n = map.tet_old_to_new[t];
    if (!n.valid()) continue;
    for (int i = 0; i < 4; ++i) {
      verts[n.value][i] = map.vert_old_to_new[tet_verts_[t][i]].value;
      const std::uint32_t a = tet_adj_[t][i];
      adj[n.value][i] = a == kNoNeighbour ? kNoNeighbour : pack(map.tet_old_to_new[a >> 2], static_cast<int>(a & 3u));
    }
  }
  std::vector<Vec3> positions(nv);
  std::vector<TetId> vert_tet(nv);
  std::vector<std::uint32_t> boundary(nv);
  for (std::uint32_t n = 0; n < nv; ++n) {
    const std::uint32_t old = vert_new_to_old[n];
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
  tet_stamp_.assign(nt, 0);
  stamp_ = 0;
  return map;
}

// ---- transactions ---------------------------------------------------------------------------

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
        for (double x : attributes_.value(c, index)) journal_.attribute_values.push_back(x);
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
          for (double& x : attributes_.value(c, e.index)) x = journal_.attribute_values[k++];
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

RawMesh TetMesh::to_raw() const {
  RawMesh raw;
  std::vector<std::uint32_t> new_id(vertex_capacity(), kDeadTetMarker);
  raw.positions.reserve(live_vertices_);
  for (std::uint32_t v = 0; v < vertex_capacity(); ++v)
    if (vert_tet_[v].valid()) {
      new_id[v] = static_cast<std::uint32_t>(raw.positions.size());
      raw.positions.push_back(positions_[v]);
    }
  raw.tets.reserve(live_tets_);
  for (const auto& t : tet_verts_)
    if (t[0] != kDeadTetMarker) raw.tets.push_back({new_id[t[0]], new_id[t[1]], new_id[t[2]], new_id[t[3]]});
  return raw;
}

std::size_t TetMesh::memory_bytes() const {
  return tet_verts_.capacity() * sizeof(tet_verts_[0]) + tet_adj_.capacity() * sizeof(tet_adj_[0]) +
         positions_.capacity() * sizeof(Vec3) + vert_tet_.capacity() * sizeof(TetId) +
         vert_boundary_faces_.capacity() * sizeof(std::uint32_t) + free_vert_next_.capacity() * sizeof(VertId);
}

}  // namespace tetcut
