// TetMesh's journal (include/tetcut/mesh.hpp): transactions, nested savepoints and rollback, and
// the record of change. Each write of a mutation is noted once per array slot per transaction,
// with the slot's old value, so that rollback_to() restores the mesh bit for bit and
// changes_since() gives a savepoint's net change: what lets a failed cut, or an undone removal
// attempt, leave no trace. Each tet and vertex made is recorded with where it comes from, so that
// commit() derives the net ChangeLog a consumer applies.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>

#include "tetcut/mesh.hpp"

#include "core/host_location.hpp"
#include "tetcut/detail/reserve_touched.hpp"

namespace tetcut {

TetMesh::Savepoint TetMesh::savepoint() {
  Savepoint p;
  p.entries = static_cast<std::uint32_t>(journal_.entries.size());
  p.attribute_values = static_cast<std::uint32_t>(journal_.attribute_values.size());
  p.tets = tet_capacity();
  p.vertices = vertex_capacity();
  p.live_tets = live_tets_;
  p.live_vertices = live_vertices_;
  p.tet_births = static_cast<std::uint32_t>(journal_.tet_births.size());
  p.parents = static_cast<std::uint32_t>(journal_.parents.size());
  p.vertex_births = static_cast<std::uint32_t>(journal_.vertex_births.size());
  p.vertex_moves = static_cast<std::uint32_t>(journal_.vertex_moves.size());
  p.births_removed = journal_.births_removed;
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
  journal_.tet_births.clear();
  journal_.parents.clear();
  journal_.vertex_births.clear();
  journal_.births_removed = 0;
  journal_.birth_of.clear();
  journal_.vertex_birth_of.clear();
  journal_.vertex_moves.clear();
  journal_.vertex_move_of.clear();
  journal_.first_verts_entry.clear();
  journal_.first_verts_indexed = 0;
  journal_.start = savepoint();
  journal_.start_version = version_;
  journal_.active = true;
}

void TetMesh::commit(ChangeLog* log, TransactionRecord* keep) {
  if (journal_.active && !journal_.vertex_moves.empty() && attributes_.channel_count() > 0) interpolate_attributes_at_commit();
  if (log && journal_.active) append_change_log(*log);
  if (journal_.active) {
    // Nothing written and nothing appended (a rolled-back transaction, a cut that met nothing to
    // change): the state is the one it began from.
    const Savepoint& s = journal_.start;
    const bool changed = !journal_.entries.empty() || tet_capacity() != s.tets || vertex_capacity() != s.vertices ||
                         pending_tet_head_.valid() || pending_vert_head_.valid();
    if (changed) new_version();
    if (keep) {
      keep->kept_ = true;
      keep->start_ = s;
      keep->version_before_ = journal_.start_version;
      keep->version_after_ = version_;
      std::swap(keep->entries_, journal_.entries);
      std::swap(keep->attribute_values_, journal_.attribute_values);
    }
  }
  journal_.active = false;
  journal_.vertex_moves.clear();
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
void TetMesh::record_old_value(Array array, std::uint32_t index) {
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

void TetMesh::restore(std::span<const JournalEntry> entries, std::span<const double> attribute_values, const Savepoint& p) {
  for (std::size_t i = entries.size(); i-- > 0;) {
    const JournalEntry& e = entries[i];
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
          for (double& x : attributes_.value(c, VertId{e.index})) x = attribute_values[k++];
        break;
      }
    }
  }
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
}

void TetMesh::rollback_to(const Savepoint& p) {
  assert(journal_.active && p.entries <= journal_.entries.size());
  restore(std::span<const JournalEntry>(journal_.entries).subspan(p.entries), journal_.attribute_values, p);
  journal_.entries.resize(p.entries);
  journal_.attribute_values.resize(p.attribute_values);
  // Births since p are undone with the tets and vertices they name; their ids' slots in
  // birth_of go stale (a lookup checks the birth still names the id).
  journal_.tet_births.resize(p.tet_births);
  journal_.parents.resize(p.parents);
  journal_.vertex_births.resize(p.vertex_births);
  journal_.vertex_moves.resize(p.vertex_moves);  // their slots go stale like the births'
  journal_.births_removed = p.births_removed;
  // Entries past p are gone: their first-entry records too (rare: only after a locate).
  if (journal_.first_verts_indexed > p.entries) {
    journal_.first_verts_entry.clear();
    journal_.first_verts_indexed = 0;
  }
  journal_.recorded_tets = p.tets;
  journal_.recorded_vertices = p.vertices;
}

void TetMesh::rollback() {
  assert(journal_.active);
  rollback_to(journal_.start);
  commit();  // nothing is pending any more: the start had no pending ids
}

// ---- undo of a committed transaction ----------------------------------------------------------

void TetMesh::TransactionRecord::reserve(std::size_t entries) {
  detail::reserve_touched(entries_, entries);
  detail::reserve_touched(attribute_values_, entries);
}

bool TetMesh::is_last_change(const TransactionRecord& record) const {
  return record.kept_ && !journal_.active && version_ == record.version_after_;
}

void TetMesh::undo(TransactionRecord& record, ChangeLog* log) {
  assert(is_last_change(record));
  if (!is_last_change(record)) return;
  const Savepoint& start = record.start_;
  if (log) {
    // What the ids the transaction touched are after it: the slots it wrote that were there
    // before, and every slot it appended. Which of them are live once it is undone is read below.
    undo_tets_.clear();
    undo_vertices_.clear();
    undo_moved_.clear();
    ancestor_seen_.clear();
    vertex_seen_.clear();
    vertex_noted_.clear();  // replace_tets()' scratch, free between operations: the moved, once each
    for (const JournalEntry& e : record.entries_) {
      if (e.array == Array::kTetVerts && ancestor_seen_.insert(TetId{e.index}))
        undo_tets_.emplace_back(e.index, is_live(TetId{e.index}));
      if (e.array == Array::kVertTet && vertex_seen_.insert(VertId{e.index}))
        undo_vertices_.emplace_back(e.index, is_live(VertId{e.index}));
      if (e.array == Array::kPositions && is_live(VertId{e.index}) && vertex_noted_.insert(VertId{e.index})) {
        const TetId around = vertex_tet(VertId{e.index});
        UndoMove m{VertId{e.index}, positions_[e.index], around, tet(around), {}};
        for (int i = 0; i < 4; ++i) m.at[i] = positions_[m.corners[i].value];
        undo_moved_.push_back(m);
      }
    }
    for (std::uint32_t t = start.tets; t < tet_capacity(); ++t) undo_tets_.emplace_back(t, is_live(TetId{t}));
    for (std::uint32_t v = start.vertices; v < vertex_capacity(); ++v) undo_vertices_.emplace_back(v, is_live(VertId{v}));
  }
  restore(record.entries_, record.attribute_values_, start);
  version_ = record.version_before_;
  record.kept_ = false;
  if (!log) return;
  log->undo = true;
  const auto first_created = static_cast<std::ptrdiff_t>(log->created.size());
  const auto first_removed = static_cast<std::ptrdiff_t>(log->removed.size());
  for (const auto& [id, live_after] : undo_tets_) {
    const TetId t{id};
    const bool live_before = is_live(t);
    if (live_after && !live_before) log->removed.push_back(t);
    if (!live_after && live_before)
      log->created.push_back(CreatedTet{t, kNoTet, static_cast<std::uint32_t>(log->parents.size()), 0});
  }
  std::sort(log->removed.begin() + first_removed, log->removed.end());
  std::sort(log->created.begin() + first_created, log->created.end(),
            [](const CreatedTet& x, const CreatedTet& y) { return x.tet < y.tet; });
  const auto first_vertex = static_cast<std::ptrdiff_t>(log->vertices.size());
  const auto first_gone = static_cast<std::ptrdiff_t>(log->removed_vertices.size());
  for (const auto& [id, live_after] : undo_vertices_) {
    const VertId v{id};
    const bool live_before = is_live(v);
    if (live_after && !live_before) log->removed_vertices.push_back(v);
    if (!live_after && live_before) log->vertices.push_back(CreatedVertex{v, {}, {}, 0});
  }
  std::sort(log->vertices.begin() + first_vertex, log->vertices.end(),
            [](const CreatedVertex& x, const CreatedVertex& y) { return x.vertex < y.vertex; });
  std::sort(log->removed_vertices.begin() + first_gone, log->removed_vertices.end());
  // A slot written several times is listed once per write: the position after is the same.
  const auto first_moved = static_cast<std::ptrdiff_t>(log->moved.size());
  // Where a vertex goes back to, as barycentric coordinates in a tet around it before the undo
  // (its corners there then, all live before the undo): possibly outside it, so some weights may
  // be negative, but the combination is exact, which is what the checker's I8 holds it to.
  for (const UndoMove& u : undo_moved_) {
    if (!is_live(u.vertex) || positions_[u.vertex.value] == u.after) continue;
    MovedVertex m;
    m.vertex = u.vertex;
    m.before = u.after;
    detail::DeepestTet back(positions_[u.vertex.value]);
    back.offer(u.tet, u.corners, u.at);
    if (back.found()) {  // a live tet is positively oriented: always
      m.from = u.corners;
      m.weight = back.weights();
      m.count = 4;
    }
    log->moved.push_back(m);
  }
  std::sort(log->moved.begin() + first_moved, log->moved.end(),
            [](const MovedVertex& x, const MovedVertex& y) { return x.vertex < y.vertex; });
}

// ---- the record of change -------------------------------------------------------------------

TetMesh::TetVerts TetMesh::tet_at_start(TetId t) {
  // The index of first entries is brought up to date here, on the rare call (a vertex moved or
  // located), rather than in note(), which every write of every operation goes through.
  for (auto& i = journal_.first_verts_indexed; i < journal_.entries.size(); ++i) {
    const JournalEntry& e = journal_.entries[i];
    if (e.array == Array::kTetVerts && e.index < journal_.start.tets && !journal_.first_verts_entry.contains(TetId{e.index}))
      journal_.first_verts_entry.set(TetId{e.index}, static_cast<std::uint32_t>(i));
  }
  if (const std::uint32_t* entry = journal_.first_verts_entry.find(t)) {
    const JournalEntry& e = journal_.entries[*entry];
    return {VertId{e.old[0]}, VertId{e.old[1]}, VertId{e.old[2]}, VertId{e.old[3]}};
  }
  return tet(t);  // never written in the transaction: as it was
}

namespace {

// The birth a per-id slot points to, if that birth still names the id (a rollback leaves the
// slots of undone births behind).
template <class Births, class Id>
const typename Births::value_type* current_birth(const Births& births, const std::uint32_t* slot, Id id) {
  if (!slot || *slot >= births.size()) return nullptr;
  const auto& b = births[*slot];
  if constexpr (requires { b.tet; }) {
    return b.tet == id ? &b : nullptr;
  } else {
    return b.vertex == id ? &b : nullptr;
  }
}

}  // namespace

const TetMesh::VertexMove* TetMesh::current_move(VertId v) const {
  return current_birth(journal_.vertex_moves, journal_.vertex_move_of.find(v), v);
}

void TetMesh::moved_vertices(std::vector<MovedVertex>& out) const {
  out.clear();
  if (!journal_.active) return;
  for (const VertexMove& m : journal_.vertex_moves) {
    // Moved back exactly where it was (a rollback past its move truncated the record instead):
    // nothing a consumer must hear of.
    if (!is_live(m.vertex) || positions_[m.vertex.value] == m.start) continue;
    out.push_back(MovedVertex{m.origin, m.start});
  }
  std::sort(out.begin(), out.end(), [](const MovedVertex& x, const MovedVertex& y) { return x.vertex < y.vertex; });
}

// Every vertex the log names gets sum of weight * (its origin's value at the start), computed for
// all of them before any is written: an origin may be a vertex that moved, whose channels still
// hold their start values until now (move_vertex() leaves them), and a made vertex interpolated
// on an edge to such a vertex read its start values, not those of where it had moved.
void TetMesh::interpolate_attributes_at_commit() {
  attribute_scratch_.clear();
  // (A birth's origin names no vertex until the log is derived: the vertex is passed apart.)
  auto each_named = [&](auto&& visit) {
    for (const VertexMove& m : journal_.vertex_moves)
      if (is_live(m.vertex)) visit(m.vertex, m.origin);
    for (VertexBirth& b : journal_.vertex_births) {
      if (!is_live(b.vertex)) continue;
      if (b.origin.count == 0) {
        locate_origin(b.vertex, b.origin);
        b.origin.vertex = b.vertex;
      }
      visit(b.vertex, b.origin);
    }
  };
  each_named([&](VertId, const CreatedVertex& o) {
    for (std::uint32_t c = 0; c < attributes_.channel_count(); ++c) {
      const std::size_t width = attributes_.channel(c).width;
      for (std::size_t k = 0; k < width; ++k) {
        double sum = 0.0;
        for (std::size_t i = 0; i < o.count; ++i) sum += o.weight[i] * attributes_.value(c, o.from[i])[k];
        attribute_scratch_.push_back(sum);
      }
    }
  });
  std::size_t next = 0;
  each_named([&](VertId v, const CreatedVertex&) {
    note(Array::kAttributes, v.value);
    for (std::uint32_t c = 0; c < attributes_.channel_count(); ++c)
      for (double& x : attributes_.value(c, v)) x = attribute_scratch_[next++];
  });
}

// From the births and the pending list, not the journal's entries (several per tet made or
// removed, and every neighbour glued): inside a transaction an id freed waits on the pending list
// until commit(), so each id is made at most once, and only by replace_tets(), which records the
// birth. So the ids live now and dead at p are the births since p still live, and the ids live at
// p and dead now are those freed since p (the pending list down to its head at p) not made since
// p. No mutation changes a live tet's vertices in place.
void TetMesh::changes_since(const Savepoint& p, std::vector<TetId>& removed, std::vector<TetId>& created) {
  removed.clear();
  created.clear();
  if (!journal_.active) return;
  for (std::size_t i = p.tet_births; i < journal_.tet_births.size(); ++i)
    if (is_live(journal_.tet_births[i].tet)) created.push_back(journal_.tet_births[i].tet);
  for (TetId t = pending_tet_head_; t != p.pending_tet_head; t = TetId{tet_verts_[t.value][1]}) {
    const TetBirth* birth = current_birth(journal_.tet_births, journal_.birth_of.find(t), t);
    if (!birth || birth < journal_.tet_births.data() + p.tet_births) removed.push_back(t);
  }
  std::sort(removed.begin(), removed.end());
  std::sort(created.begin(), created.end());
}

void TetMesh::append_rewired(std::span<const JournalEntry> entries, std::vector<TetId>& out) {
  for (const JournalEntry& e : entries)
    if (e.array == Array::kTetAdj) out.push_back(TetId{e.index});
}

void TetMesh::rewired_tets(std::vector<TetId>& out) const { append_rewired(journal_.entries, out); }

void TetMesh::rewired_tets(const TransactionRecord& record, std::vector<TetId>& out) {
  append_rewired(record.entries_, out);
}

void TetMesh::ancestors_at_start(TetId t, std::vector<TetId>& out) {
  // A split's child has one parent, and so usually has its whole line: follow it without the
  // walk's bookkeeping until it ends or forks.
  const TetBirth* birth = current_birth(journal_.tet_births, journal_.birth_of.find(t), t);
  while (birth && birth->parents_count == 1) {
    t = journal_.parents[birth->parents_begin];
    birth = current_birth(journal_.tet_births, journal_.birth_of.find(t), t);
  }
  if (!birth) {
    out.push_back(t);  // there at begin_transaction()
    return;
  }
  // Several parents (a flip): every line, each tet once.
  const std::size_t first = out.size();
  ancestor_seen_.clear();
  ancestor_stack_.assign(1, t);
  while (!ancestor_stack_.empty()) {
    const TetId u = ancestor_stack_.back();
    ancestor_stack_.pop_back();
    const TetBirth* b = current_birth(journal_.tet_births, journal_.birth_of.find(u), u);
    if (!b) {
      out.push_back(u);
      continue;
    }
    for (TetId parent : parents(*b))
      if (ancestor_seen_.insert(parent)) ancestor_stack_.push_back(parent);
  }
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
}

// Barycentric coordinates of v's position in a tet live at begin_transaction() that contains it,
// for a vertex move_vertex() moved, or one whose edge joins vertices of different old tets (a
// split after a flip). First among the ancestors of a tet around v: every tet lies in its
// ancestors while v stays inside the region the transaction started with. Smoothing may move a
// vertex of the cut's own surface off its faces' planes (improve/smoothing.hpp, by at most 5 % of
// an edge), into the cavity: there v lies in a tet the cut removed, an ancestor of no tet around
// v. So when v is outside every ancestor, the search widens to every tet live at the start that
// the transaction changed (the journal's first entries: O(journal), on this rare path only).
// Among the tets searched, the one where v is deepest inside; coordinates within rounding of 0
// are dropped. A vertex of the organ's own surface within the cut's reach may also move outward,
// off the region the transaction started with (by at most 5 % of an edge): it is then in no tet
// searched, and its coordinates in the nearest one have a small negative entry (an extrapolation
// that reproduces its position; change_log.hpp says so).
void TetMesh::locate_origin(VertId v, CreatedVertex& out) {
  // Barycentric coordinates are relative to the tet's size: below this, outside by rounding only.
  constexpr double kOutsideRounding = 1e-12;
  locate_scratch_.clear();
  ancestors_at_start(vert_tet_[v.value], locate_scratch_);
  detail::DeepestTet host = detail::deepest_at_start(*this, locate_scratch_, positions_[v.value]);
  if (host.depth() < -kOutsideRounding) {
    for (const JournalEntry& e : journal_.entries)
      if (e.array == Array::kTetVerts && e.index < journal_.start.tets) {
        const TetVerts c = tet_at_start(TetId{e.index});
        if (c[0].value == kDeadTetMarker) continue;
        host.offer(TetId{e.index}, c, {position_at_start(c[0]), position_at_start(c[1]), position_at_start(c[2]), position_at_start(c[3])});
      }
  }
  assert(host.found() && "a vertex made in the transaction lies in no tet that was there before it");
  if (!host.found()) return;
  // Inside to within rounding: coordinates clamped at 0. Outside (v moved off the region the
  // transaction started with): the coordinates as they are, one or more slightly negative, so
  // that they still reproduce v's position.
  const bool inside = host.depth() >= -kOutsideRounding;
  std::array<double, 4> w = host.weights();
  double sum = 0.0;
  for (double& wi : w) sum += wi = inside ? std::max(wi, 0.0) : wi;
  out.count = 0;
  for (int i = 0; i < 4; ++i) {
    if (std::abs(w[i] / sum) <= 1e-12) continue;
    out.from[out.count] = host.corners()[i];
    out.weight[out.count++] = w[i] / sum;
  }
}

// out := (1 - t) * origin(a) + t * origin(b), over vertices live at begin_transaction(); count 0
// when that takes more than four of them (the caller locates the vertex instead).
void TetMesh::compose_origin(VertId a, VertId b, double t, CreatedVertex& out) const {
  out.count = 0;
  auto add = [&](VertId x, double w) {
    if (w == 0.0) return true;
    const VertexBirth* birth = current_birth(journal_.vertex_births, journal_.vertex_birth_of.find(x), x);
    const CreatedVertex single{x, {x}, {1.0}, 1};
    const VertexMove* move = birth ? nullptr : current_move(x);
    const CreatedVertex& o = birth ? birth->origin : move ? move->origin : single;
    if (o.count == 0) return false;
    for (int i = 0; i < o.count; ++i) {
      int k = 0;
      while (k < out.count && out.from[k] != o.from[i]) ++k;
      if (k == out.count) {
        if (out.count == 4) return false;
        out.from[k] = o.from[i];
        out.weight[k] = 0.0;
        ++out.count;
      }
      out.weight[k] += w * o.weight[i];
    }
    return true;
  };
  if (!add(a, 1.0 - t) || !add(b, t)) out.count = 0;
}

void TetMesh::append_change_log(ChangeLog& log) {
  changes_since(journal_.start, net_removed_scratch_, net_created_scratch_);
  log.removed.insert(log.removed.end(), net_removed_scratch_.begin(), net_removed_scratch_.end());
  for (TetId t : net_created_scratch_) {
    CreatedTet c{t, kNoTet, static_cast<std::uint32_t>(log.parents.size()), 0};
    ancestors_at_start(t, log.parents);
    c.parents_count = static_cast<std::uint32_t>(log.parents.size()) - c.parents_begin;
    if (c.parents_count > 0) c.parent = log.parents[c.parents_begin];
    log.created.push_back(c);
  }
  // Vertices made and still used, in id order; vertices there before and used no more.
  const std::size_t first_vertex = log.vertices.size();
  for (const VertexBirth& b : journal_.vertex_births) {
    if (!is_live(b.vertex)) continue;
    CreatedVertex v = b.origin;
    v.vertex = b.vertex;
    if (v.count == 0) locate_origin(b.vertex, v);
    log.vertices.push_back(v);
  }
  std::sort(log.vertices.begin() + static_cast<std::ptrdiff_t>(first_vertex), log.vertices.end(),
            [](const CreatedVertex& x, const CreatedVertex& y) { return x.vertex < y.vertex; });
  // Vertices there before that moved, in id order.
  if (!journal_.vertex_moves.empty()) {
    moved_vertices(moved_scratch_);
    log.moved.insert(log.moved.end(), moved_scratch_.begin(), moved_scratch_.end());
  }
  const std::size_t first_removed = log.removed_vertices.size();
  vertex_seen_.clear();
  for (const JournalEntry& e : journal_.entries) {
    // The first entry of a vertex holds its seed at begin_transaction().
    if (e.array != Array::kVertTet || e.index >= journal_.start.vertices || !vertex_seen_.insert(VertId{e.index})) continue;
    if (TetId{e.old[0]}.valid() && !vert_tet_[e.index].valid()) log.removed_vertices.push_back(VertId{e.index});
  }
  std::sort(log.removed_vertices.begin() + static_cast<std::ptrdiff_t>(first_removed), log.removed_vertices.end());
}

}  // namespace tetcut
