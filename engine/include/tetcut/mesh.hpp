// TetMesh: the manifold tetrahedral mesh every tetcut operation works on.
//
// Storage is index based and struct-of-arrays (style: geogram's cell_to_v / cell_to_cell):
//   tet_verts_  #T by 4 vertex ids, positively oriented, face i opposite vertex i;
//   tet_adj_    #T by 4 packed neighbour references (4 * tet + mirror face), kNoNeighbour on the
//               boundary, so crossing a face also tells which face of the neighbour we entered by;
//   vert_tet_   one incident live tet per vertex (the seed of every shell walk);
//   vert_boundary_faces_  number of boundary faces around each vertex, so "is this vertex on the
//               surface?" (paper 3.3, removability) is O(1).
// Removed tets and vertices stay as tombstones on free lists until compact() renumbers.
//
// Boundary classification is O(1) for faces and vertices and O(edge shell) for edges; shells are
// walked from vert_tet_ through the adjacency. Nothing here scans the mesh except compact(),
// boundary_faces() (an enumeration of the whole surface) and the canonical hash.
//
// A TetMesh is obtained from build_mesh() (mesh_builder.hpp), which validates its input. After
// that, mutation goes through replace_tets(), the one local primitive every operation uses.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "tetcut/attributes.hpp"
#include "tetcut/change_log.hpp"
#include "tetcut/detail/local_tables.hpp"
#include "tetcut/detail/stamped_property.hpp"
#include "tetcut/ids.hpp"
#include "tetcut/raw_mesh.hpp"
#include "tetcut/raw_mesh_view.hpp"
#include "tetcut/thread_contract.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut {

// The order of the ids compact() gives.
enum class IdOrder : std::uint8_t {
  // Sorted along the Morton curve of the live vertices' box (space_filling_curve.hpp): tets by
  // their centroid, vertices by their position; equal keys keep their relative order.
  kAlongCurve,
  // The relative order they had.
  kKept,
};

// Where each old id went in compact(): kNoTet / kNoVert for tombstones.
struct Renumbering {
  std::vector<TetId> tet_old_to_new;
  std::vector<VertId> vert_old_to_new;
};

namespace detail {
struct MeshInternals;  // engine/src/core/mesh_internals.hpp: the builder's and the checker tests' way in
}  // namespace detail

// Tets are addressed by 30 bits in packed neighbour references: about 1.07e9 tets at most.
inline constexpr std::uint32_t kMaxTets = (1u << 30) - 1;

class TetMesh {
 public:
  using TetVerts = std::array<VertId, 4>;

  TetMesh() = default;

  // ---- sizes ------------------------------------------------------------------------------
  [[nodiscard]] std::uint32_t tet_capacity() const { return static_cast<std::uint32_t>(tet_verts_.size()); }
  [[nodiscard]] std::uint32_t vertex_capacity() const { return static_cast<std::uint32_t>(positions_.size()); }
  [[nodiscard]] std::uint32_t num_tets() const { return live_tets_; }
  [[nodiscard]] std::uint32_t num_vertices() const { return live_vertices_; }
  [[nodiscard]] bool is_live(TetId t) const { return t.value < tet_capacity() && tet_verts_[t.value][0] != kDeadTetMarker; }
  [[nodiscard]] bool is_live(VertId v) const { return v.value < vertex_capacity() && vert_tet_[v.value].valid(); }

  // ---- elements ---------------------------------------------------------------------------
  [[nodiscard]] TetVerts tet(TetId t) const {
    const auto& v = tet_verts_[t.value];
    return {VertId{v[0]}, VertId{v[1]}, VertId{v[2]}, VertId{v[3]}};
  }
  [[nodiscard]] VertId vertex(TetId t, int local) const { return VertId{tet_verts_[t.value][local]}; }
  [[nodiscard]] const Vec3& position(VertId v) const { return positions_[v.value]; }
  // Local index (0..3) of v in t, or -1. Inline: every shell walk calls it per step.
  [[nodiscard]] int local_index(TetId t, VertId v) const {
    const auto& verts = tet_verts_[t.value];
    for (int i = 0; i < 4; ++i)
      if (verts[i] == v.value) return i;
    return -1;
  }

  // The neighbour across face `face` of t and the face of the neighbour we enter by; an invalid
  // FaceRef on the boundary.
  [[nodiscard]] FaceRef neighbour(TetId t, int face) const {
    const std::uint32_t adj = tet_adj_[t.value][face];
    if (adj == kNoNeighbour) return {};
    return {TetId{adj >> 2}, static_cast<std::uint8_t>(adj & 3u)};
  }
  [[nodiscard]] TetId vertex_tet(VertId v) const { return vert_tet_[v.value]; }

  // ---- boundary classification (paper 3.3 needs these in O(1)) ----------------------------
  [[nodiscard]] bool is_boundary_face(TetId t, int face) const { return tet_adj_[t.value][face] == kNoNeighbour; }
  [[nodiscard]] bool is_boundary_vertex(VertId v) const { return vert_boundary_faces_[v.value] != 0; }
  [[nodiscard]] std::uint32_t boundary_face_count(VertId v) const { return vert_boundary_faces_[v.value]; }
  [[nodiscard]] int boundary_face_count(TetId t) const {
    int n = 0;
    for (std::uint32_t adj : tet_adj_[t.value]) n += adj == kNoNeighbour;
    return n;
  }
  // O(edge shell): walks around the edge until it closes or meets the boundary.
  [[nodiscard]] bool is_boundary_edge(TetId t, int local_edge) const;

  // ---- edges ------------------------------------------------------------------------------
  // The local edge (0..5) joining a and b in t, or -1 when t does not have both. Inline: the
  // splitter and the refinement ask it for every tet of every shell they walk.
  [[nodiscard]] int local_edge(TetId t, VertId a, VertId b) const {
    const int la = local_index(t, a), lb = local_index(t, b);
    if (la < 0 || lb < 0 || la == lb) return -1;
    return kEdgeIndex[la][lb];
  }
  // The edge (a, b) as (a tet that has it, its local edge) (style: CGAL's is_edge): from `hint`
  // when the hint has both ends, else from a walk of a's shell (into `shell_scratch`). Invalid
  // when a and b are not joined. O(1) with a good hint, O(shell of a) otherwise.
  EdgeRef find_edge(VertId a, VertId b, TetId hint, std::vector<TetId>& shell_scratch) const;

  // ---- shells -----------------------------------------------------------------------------
  // The tets around v, face-connected walk from vertex_tet(v). `out` is cleared first. Cost
  // O(shell^2) in the worst case through a linear membership test, which beats hashing for the
  // shells of a few dozen tets that real meshes have.
  void vertex_shell(VertId v, std::vector<TetId>& out) const;
  // The vertices joined to v by an edge, in shell order then first-seen order.
  void vertex_neighbours(VertId v, std::vector<VertId>& out, std::vector<TetId>& shell_scratch) const;

  // The tets around an edge, ordered by rotation about it. For a boundary edge the walk starts
  // at a tet with a boundary face on the edge and ends at the other; returns true in that case.
  bool edge_shell(TetId t, int local_edge, std::vector<TetId>& out) const;

  // Every boundary face (an enumeration of the surface: O(#T)).
  void boundary_faces(std::vector<FaceRef>& out) const;

  // Area-weighted unit normal of the boundary surface at a boundary vertex (zero vector for an
  // interior vertex). O(shell).
  [[nodiscard]] Vec3 boundary_normal(VertId v) const;
  Vec3 boundary_normal(VertId v, std::vector<TetId>& shell_scratch) const;

  [[nodiscard]] double volume(TetId t) const;
  [[nodiscard]] double total_volume() const;  // O(#T)
  // Mean length of the live tets' edges (an edge counted once per tet), 1 when there are none:
  // a length scale, e.g. the spatial index's cell. O(#T).
  [[nodiscard]] double mean_edge_length() const;

  // ---- attributes -------------------------------------------------------------------------
  VertexAttributes& attributes() { return attributes_; }
  [[nodiscard]] const VertexAttributes& attributes() const { return attributes_; }

  // ---- mutation ---------------------------------------------------------------------------
  // A new vertex, not yet used by any tet (it becomes live when a tet references it); attribute
  // channels are zero.
  VertId add_vertex(const Vec3& p);
  // A new vertex at (1 - t) * a + t * b with every attribute channel interpolated the same way
  // (paper 3.2: texture and mechanical data follow the split).
  VertId add_vertex_on_edge(VertId a, VertId b, double t);
  // Moves a vertex inside the open transaction (smoothing). Its origin becomes barycentric
  // coordinates in the tet that was there before the transaction and contains its new position
  // (at the positions of then: position_at_start()), so a consumer still sees one combination of
  // old values. A vertex the transaction made has its attribute channels interpolated now; a
  // vertex that was there before (ChangeLog::moved) keeps them until commit(), which
  // interpolates every vertex the log names from the values at the start, so that no value is
  // read after it changed. The tets around it are made anew (new ids appended to `created`),
  // each with all of them as parents: moving v reshapes its star within the same polytope, so
  // every tet of it lies in the star's old tets, not in its own parent alone.
  void move_vertex(VertId v, const Vec3& p, std::vector<TetId>* created = nullptr);
  // Where v was when the open transaction began: its position now unless the transaction moved
  // it (a vertex it made: where it was made or last moved to, which is where it is). O(1).
  [[nodiscard]] const Vec3& position_at_start(VertId v) const {
    if (journal_.vertex_moves.empty()) return positions_[v.value];
    const VertexMove* move = current_move(v);
    return move ? move->start : positions_[v.value];
  }
  // Whether the open transaction moved v, a vertex that was there before it.
  [[nodiscard]] bool moved_in_transaction(VertId v) const { return current_move(v) != nullptr; }

  // The one local mutation primitive: removes `removed` and inserts `added`, gluing the new tets
  // to each other and to the faces the removed ones shared with the rest of the mesh (matched by
  // vertex triple); every other face of a new tet is boundary. Adjacency, boundary counts and
  // vertex-to-tet references are updated locally (cost O(#removed + #added) plus the shells
  // needed to re-seed vertex_tet). A vertex left without tets is removed. Ids of new tets are
  // appended to `created` (may reuse ids of removed tets).
  //
  // `parent_of`, for the record of change: the one removed tet each added tet comes from (a
  // split: one entry per added tet); empty when every removed tet is a parent of every added
  // one (a flip).
  //
  // Preconditions (asserted in debug builds, the caller's plan guarantees them): removed tets
  // are live and distinct, added tets are positively oriented over live or newly added
  // vertices, and no face ends up shared by more than two tets.
  void replace_tets(std::span<const TetId> removed, std::span<const TetVerts> added,
                    std::vector<TetId>* created = nullptr, std::span<const TetId> parent_of = {});
  void remove_tets(std::span<const TetId> removed) { replace_tets(removed, {}, nullptr); }

  // Reserves room for this many tet and vertex ids (scratch and the journal's working size
  // included), so that operations growing the mesh up to there never reallocate: the way to no
  // allocation per cut. The memory is touched too, so that no operation pays its page faults.
  void reserve(std::uint32_t tets, std::uint32_t vertices);

  // Renumbers live tets and vertices densely; attributes follow. By default the new ids run along
  // a space-filling curve (IdOrder): tets near each other in space get ids near each other, and
  // so do their data, whatever order the edits left. O(#T log #T). Not allowed inside a
  // transaction. A Cutter holding this mesh must do it (Cutter::compact()): its index would hold
  // the old ids, so it refuses to cut a mesh compacted behind its back.
  Renumbering compact(IdOrder order = IdOrder::kAlongCurve);
  // Moves on at compact() and at every assignment to this object, and differs between mesh
  // objects (see IdEpoch below): a Cutter compares it with the value it indexed.
  [[nodiscard]] std::uint64_t id_epoch() const { return id_epoch_.value(); }

  // ---- transactions: atomic operations (design: a cut completes or leaves no trace) --------
  // Between begin_transaction() and commit(), every write to the mesh's arrays is journaled
  // (old value first), so that rollback() restores the mesh bit for bit: same ids, same free
  // lists, same capacities in use. The journal is reused: no allocation once warm.
  //
  // Inside a transaction no id is reused: a tet or vertex freed there joins the free lists only
  // at commit(). So an id is created or removed at most once per transaction, and what a
  // transaction did is a plain set difference (the net ChangeLog of a cut, the checker's region).
  //
  // The journal is also the one record of what changed: every tet made is recorded with its
  // parents, every vertex with its origin (its edge, or the tet it was moved into), and
  // commit(&log) derives the net ChangeLog from that (change_log.hpp). Nothing else keeps one.
  void begin_transaction();
  // Ends the transaction; with `log`, first appends its net change (change_log.hpp): the tets
  // live before and gone now, those live now and not before with their parents among the
  // former, the vertices made and still used with their origin among the vertices there before,
  // and the vertices gone. O(journal).
  //
  // With `keep`, the transaction is also kept for undo(): see TransactionRecord below.
  class TransactionRecord;
  void commit(ChangeLog* log = nullptr, TransactionRecord* keep = nullptr);
  void rollback();
  [[nodiscard]] bool in_transaction() const { return journal_.active; }

  // ---- undo of committed transactions (Cutter::undo) -----------------------------------------
  // A state of the mesh: every change gives it a value it never had (a transaction that wrote
  // something, a write outside one, compact()); an undo gives it back the value from before the
  // transaction it takes back. What tells a kept transaction from one changed behind its back.
  [[nodiscard]] std::uint64_t version() const { return version_; }
  // Whether `record` keeps the last change made to this mesh (version() is the one its commit
  // gave), so that undo() can take it back.
  [[nodiscard]] bool is_last_change(const TransactionRecord& record) const;
  // Takes back the transaction `record` kept, which must be the last change (is_last_change();
  // outside a transaction): the arrays, free lists and counts bit for bit as before it began,
  // the vertex attributes it wrote included; version() as it was then. The record is spent.
  // With `log`, appends the undo's net change (change_log.hpp): removed and removed_vertices the
  // tets and vertices the transaction made; created and vertices those it removed, restored
  // under their ids, each with no parents and count 0 (restored: its values are those it had
  // before the transaction, which per-id consumers still hold, since no later change can have
  // reused an id freed by the last one); moved the vertices it moved, back where they were, each
  // with count 0 too and `before` where the transaction had put them. O(the transaction's
  // journal).
  void undo(TransactionRecord& record, ChangeLog* log = nullptr);

  // A point inside the open transaction to come back to: an attempt that does not pan out is
  // undone by rollback_to() (the removal strategies' one undo), everything done since is gone
  // bit for bit, the record of change included, and the transaction stays open. Savepoints
  // nest: rolling back to one invalidates those taken after it.
  struct Savepoint {
    std::uint32_t entries = 0, attribute_values = 0;
    std::uint32_t tets = 0, vertices = 0;  // array sizes
    std::uint32_t live_tets = 0, live_vertices = 0;
    std::uint32_t tet_births = 0, parents = 0, vertex_births = 0, vertex_moves = 0, births_removed = 0;
    TetId free_tet_head, pending_tet_head, pending_tet_tail;
    VertId free_vert_head, pending_vert_head, pending_vert_tail;
  };
  [[nodiscard]] Savepoint savepoint();
  void rollback_to(const Savepoint& point);

  // ---- the record of change, as it is being written ------------------------------------------
  // A tet made by replace_tets() inside the open transaction, with the tets that call removed
  // that it comes from (parents()).
  struct TetBirth {
    TetId tet;
    std::uint32_t parents_begin = 0, parents_count = 0;
  };
  // A vertex made inside the open transaction: on edge (a, b) at t, or (a invalid) by
  // add_vertex(). `origin`: where it is now, over vertices there before the transaction (count
  // 0 while unknown: located when the log is derived).
  struct VertexBirth {
    VertId vertex;
    VertId a, b;
    double t = 0.0;
    CreatedVertex origin;
  };
  // A vertex that was there before the open transaction and moved in it: where it was, and where
  // it is now over vertices there before (their positions at the start).
  struct VertexMove {
    VertId vertex;
    Vec3 start;
    CreatedVertex origin;
  };
  // What the open transaction made since `point`, in the order it was made: raw, not net (a tet
  // made and split again since is listed, and so is its child). A split's children and
  // midpoints are exactly what it made since a savepoint taken before it. O(1); the spans are
  // valid until the next mutation.
  [[nodiscard]] std::span<const TetBirth> tets_made_since(const Savepoint& point) const {
    return std::span<const TetBirth>(journal_.tet_births).subspan(point.tet_births);
  }
  [[nodiscard]] std::span<const VertexBirth> vertices_made_since(const Savepoint& point) const {
    return std::span<const VertexBirth>(journal_.vertex_births).subspan(point.vertex_births);
  }
  [[nodiscard]] std::span<const TetId> parents(const TetBirth& birth) const {
    return std::span<const TetId>(journal_.parents).subspan(birth.parents_begin, birth.parents_count);
  }
  // Tets the open transaction made since `point` that are still live: made minus made and
  // removed again. O(1): what a per-cut tet budget counts.
  [[nodiscard]] std::uint32_t net_tets_made_since(const Savepoint& point) const {
    return static_cast<std::uint32_t>(journal_.tet_births.size()) - point.tet_births -
           (journal_.births_removed - point.births_removed);
  }
  // The tets live at begin_transaction() that tet t descends from (t itself if it was live
  // then), appended sorted: what the ChangeLog names as its parents.
  void ancestors_at_start(TetId t, std::vector<TetId>& out);
  // The index of live tet t's birth in the open transaction (its place in tets_made_since() from
  // the start), kNoBirth if t was there at begin_transaction(). A birth is unique within the
  // transaction (a reused id is born again at another index; rolled back births are gone), and so
  // is its tet's shape: a move is a new birth of every tet around the vertex. O(1).
  static constexpr std::uint32_t kNoBirth = 0xFFFFFFFFu;
  [[nodiscard]] std::uint32_t birth_index(TetId t) const {
    const std::uint32_t* slot = journal_.birth_of.find(t);
    return slot && *slot < journal_.tet_births.size() && journal_.tet_births[*slot].tet == t ? *slot : kNoBirth;
  }
  // The vertices tet t had at begin_transaction() (t live then, dead or alive now).
  [[nodiscard]] TetVerts tet_at_start(TetId t);
  // True when the open transaction made t (t live or not).
  [[nodiscard]] bool made_in_transaction(TetId t) const { return journal_.birth_of.contains(t); }
  [[nodiscard]] bool made_in_transaction(VertId v) const { return journal_.vertex_birth_of.contains(v); }

  // The net effect since `point` (a savepoint of the open transaction), sorted by id: `removed`
  // gets the ids live then and dead now, `created` the ids live now and dead then. O(tets made
  // and freed since the point), from the births and the freed ids, not the journal.
  void changes_since(const Savepoint& point, std::vector<TetId>& removed, std::vector<TetId>& created);
  // The vertices there before the open transaction that it moved and that are still used and not
  // back where they were, by id, with their origins (ChangeLog::moved). O(moves).
  void moved_vertices(std::vector<MovedVertex>& out) const;
  // The same since begin_transaction(): what the local checker needs, whatever mix of
  // operations ran.
  void transaction_changes(std::vector<TetId>& removed, std::vector<TetId>& created) {
    changes_since(journal_.start, removed, created);
  }
  // The tets whose neighbours the open transaction rewrote and that it did not make (a tet it made
  // is in its `created`, or gone), appended in the journal's order, repeats and all, live or not:
  // with the tets it made, the only tets whose boundary faces it can have changed. What the
  // walking locator's index of boundary tets re-examines (cut/walking_locator.hpp). O(journal).
  void rewired_tets(std::vector<TetId>& out) const;
  // The same for a kept transaction: the tets undo(record) gives their neighbours back.
  static void rewired_tets(const TransactionRecord& record, std::vector<TetId>& out);

  // ---- raw views, for the independent checker and writers ----------------------------------
  // #capacity by 4; a tombstone has kDeadTetMarker in its first entry.
  [[nodiscard]] std::span<const std::array<std::uint32_t, 4>> raw_tets() const { return tet_verts_; }
  [[nodiscard]] std::span<const Vec3> positions() const { return positions_; }
  // Everything above plus the adjacency, vertex->tet references, boundary counts and counts,
  // as the arrays the independent checker reads (raw_mesh_view.hpp). O(1).
  [[nodiscard]] RawMeshView raw_view() const {
    static_assert(kNoNeighbour == kNoRawRef && kNoTet.value == kNoRawRef);  // pack() matches: tests/invariants
    return {positions_, tet_verts_, true,
            EngineRecordsView{tet_adj_, vert_tet_, vert_boundary_faces_, live_tets_, live_vertices_, attributes_.size()}};
  }
  // Live tets and live vertices, renumbered densely (vertices in id order).
  [[nodiscard]] RawMesh to_raw() const;

  // Memory held by the topology and positions, in bytes (capacity, not size).
  [[nodiscard]] std::size_t memory_bytes() const;

  static constexpr std::uint32_t kNoNeighbour = 0xFFFFFFFFu;

  // Who uses the mesh now, for the threading contract's check (thread_contract.hpp): taken by
  // MeshWriteScope and MeshReadScope. A copy of the mesh starts unused.
  [[nodiscard]] const detail::MeshUse& use() const { return use_; }

 private:
  detail::MeshUse use_;
  // The one seam under this interface, for the builder and for the checker's tests (who need the
  // arrays themselves); declared in an internal header, so no user of this class can name it.
  friend struct detail::MeshInternals;

  static constexpr std::uint32_t pack(TetId t, int face) { return (t.value << 2) | static_cast<std::uint32_t>(face); }

  TetId allocate_tet();
  void free_tet(TetId t);
  void free_vertex(VertId v);
  // vert_tet_ value of a vertex whose seed tet is being removed inside replace_tets().
  static constexpr TetId kReseed{0xFFFFFFFEu};

  std::vector<std::array<std::uint32_t, 4>> tet_verts_;  // kDeadTetMarker in [0] when dead
  std::vector<std::array<std::uint32_t, 4>> tet_adj_;
  std::vector<Vec3> positions_;
  std::vector<TetId> vert_tet_;
  std::vector<std::uint32_t> vert_boundary_faces_;
  VertexAttributes attributes_;
  // Names the numbering of a mesh object's ids: a value no other mesh object and no other state
  // of this one has had in this process (a process-wide count). It moves on at the events after
  // which the ids no longer mean what they meant to whoever indexed them (a Cutter: compact(),
  // assigning another mesh into the object), and a new object (a copy included) starts with a
  // value of its own, so a consumer that kept another mesh's state (SnapshotPublisher's buffers)
  // sees that it did.
  class IdEpoch {
   public:
    IdEpoch() : value_(next()) {}
    IdEpoch(const IdEpoch&) : value_(next()) {}
    IdEpoch& operator=(const IdEpoch&) {
      value_ = next();
      return *this;
    }
    ~IdEpoch() = default;
    void advance() { value_ = next(); }
    [[nodiscard]] std::uint64_t value() const { return value_; }

   private:
    static std::uint64_t next();  // mesh_mutation.cpp
    std::uint64_t value_;
  };
  IdEpoch id_epoch_;
  // version(): the state's value, and the last value given.
  std::uint64_t version_ = 0, last_version_ = 0;
  void new_version() { version_ = ++last_version_; }

  std::uint32_t live_tets_ = 0;
  std::uint32_t live_vertices_ = 0;
  // Free lists, threaded through tombstones: a dead tet keeps the next free id in
  // tet_verts_[t][1]; a dead vertex in free_vert_next_.
  TetId free_tet_head_ = kNoTet;
  std::vector<VertId> free_vert_next_;
  VertId free_vert_head_ = kNoVert;
  // Ids freed inside the open transaction, threaded the same way; spliced onto the free lists
  // by commit() (no reuse inside a transaction).
  TetId pending_tet_head_ = kNoTet, pending_tet_tail_ = kNoTet;
  VertId pending_vert_head_ = kNoVert, pending_vert_tail_ = kNoVert;

  // Scratch for replace_tets, reused so that steady-state operations do not allocate.
  struct FaceSlot {
    std::array<std::uint32_t, 3> key;  // sorted vertex ids
    std::uint32_t ref;                 // packed (tet, face)
    std::uint32_t partner;             // the slot with the same key, or kNoSlot
    std::uint8_t is_outer;             // a face of the untouched mesh facing the cavity
  };
  static constexpr std::uint32_t kNoSlot = 0xFFFFFFFFu;
  // Transaction journal.
  enum class Array : std::uint8_t { kTetVerts, kTetAdj, kPositions, kVertTet, kBoundary, kFreeVertNext, kAttributes };
  struct JournalEntry {
    Array array;
    std::uint32_t index;
    std::array<std::uint32_t, 6> old;  // raw bytes of the old element (attributes: offset)
  };
  struct Journal {
    bool active = false;
    Savepoint start;                       // the state at begin_transaction()
    std::uint64_t start_version = 0;       // version() then
    // Elements below these indices existed at the newest savepoint: their old values are
    // recorded; elements appended since are simply truncated by a rollback.
    std::uint32_t recorded_tets = 0, recorded_vertices = 0;
    std::vector<JournalEntry> entries;
    std::vector<double> attribute_values;
    // The record of change: births in order, their parents flat, and per id its birth's index.
    std::vector<TetBirth> tet_births;
    std::vector<TetId> parents;
    std::vector<VertexBirth> vertex_births;
    std::vector<VertexMove> vertex_moves;
    std::uint32_t births_removed = 0;      // tets made in the transaction and removed again
    StampedMap<TetId, std::uint32_t> birth_of;
    StampedMap<VertId, std::uint32_t> vertex_birth_of;
    StampedMap<VertId, std::uint32_t> vertex_move_of;
    // Per tet id noted: its first kTetVerts entry (the tet's vertices at begin_transaction()),
    // indexed up to entry first_verts_indexed.
    StampedMap<TetId, std::uint32_t> first_verts_entry;
    std::size_t first_verts_indexed = 0;
  };
  // Journals the old value of array[index], unless no transaction is open or the element was
  // appended in it (rollback truncates those): inline, since most elements a cut writes are new.
  void note(Array array, std::uint32_t index) {
    if (!journal_.active) {
      new_version();  // a write outside a transaction: no undo can come back across it
      return;
    }
    const bool is_tet = array == Array::kTetVerts || array == Array::kTetAdj;
    if (index >= (is_tet ? journal_.recorded_tets : journal_.recorded_vertices)) return;
    record_old_value(array, index);
  }
  void record_old_value(Array array, std::uint32_t index);
  // rewired_tets() of a journal's entries.
  static void append_rewired(std::span<const JournalEntry> entries, std::vector<TetId>& out);
  // Writes back the old values of `entries`, newest first, then truncates the arrays and sets the
  // counts and list heads as `point` has them: rollback_to() and undo().
  void restore(std::span<const JournalEntry> entries, std::span<const double> attribute_values, const Savepoint& point);
  // undo()'s log: the ids the transaction touched, with whether each is live after it.
  std::vector<std::pair<std::uint32_t, bool>> undo_tets_, undo_vertices_;
  // A vertex the transaction moved, where it is before the undo, and a tet around it then with
  // its corners' positions: where the undo puts it back is given as a combination of those.
  struct UndoMove {
    VertId vertex;
    Vec3 after;
    TetId tet;
    TetVerts corners;
    std::array<Vec3, 4> at;
  };
  std::vector<UndoMove> undo_moved_;
  // Origins of vertices made in the transaction (ChangeLog::vertices): composed along the edges
  // they were put on, or located in an old tet (mesh_journal.cpp).
  void compose_origin(VertId a, VertId b, double t, CreatedVertex& out) const;
  void locate_origin(VertId v, CreatedVertex& out);
  // The move of v in the open transaction, if it was there before and moved.
  [[nodiscard]] const VertexMove* current_move(VertId v) const;
  // At commit, when the transaction moved vertices that were there before: every vertex the log
  // names (made or moved) gets its attribute channels from its origin's values at the start.
  void interpolate_attributes_at_commit();
  std::vector<double> attribute_scratch_;
  std::vector<MovedVertex> moved_scratch_;
  void append_change_log(ChangeLog& log);
  std::vector<TetId> ancestor_stack_, locate_scratch_, net_removed_scratch_, net_created_scratch_, move_star_;
  std::vector<TetVerts> move_tets_;
  StampedSet<TetId> ancestor_seen_;
  StampedSet<VertId> vertex_seen_;
  Journal journal_;
  static constexpr std::size_t kJournalWorkingSize = 16384;  // entries reserve() makes room for

  std::vector<FaceSlot> scratch_faces_;
  std::vector<std::uint32_t> face_table_;  // open addressing over scratch_faces_ indices
  std::vector<VertId> scratch_verts_;
  StampedSet<TetId> removing_;      // replace_tets(): the tets this call removes
  StampedSet<VertId> vertex_noted_;  // replace_tets(): vertex journaled in this call
  void touch_vertex(std::uint32_t v);
  // replace_tets() in its steps (mesh_mutation.cpp): the cavity opened, the new tets added
  // unglued, their faces glued, the vertices that lost their seed reseeded.
  void open_cavity(std::span<const TetId> removed);
  void add_unglued(std::span<const TetId> removed, std::span<const TetVerts> added, std::vector<TetId>* created,
                   std::span<const TetId> parent_of);
  void glue_faces();
  void reseed_vertices();
};

// What TetMesh::commit(log, &record) keeps of a transaction for TetMesh::undo(): the old value of
// every slot it wrote and the state it began from. It takes the journal's own buffers, and gives
// the journal its previous ones in exchange (a swap, not a copy): keeping a transaction costs
// O(1), and records reserved once are reused with no allocation (Cutter's history of cuts).
class TetMesh::TransactionRecord {
 public:
  // Room for this many journal entries, touched (the journal's working size by default).
  void reserve(std::size_t entries = kJournalWorkingSize);
  // Kept by a commit and not yet spent by an undo.
  [[nodiscard]] bool kept() const { return kept_; }
  void clear() { kept_ = false; }

 private:
  friend class TetMesh;
  bool kept_ = false;
  Savepoint start_;
  std::uint64_t version_before_ = 0, version_after_ = 0;
  std::vector<JournalEntry> entries_;
  std::vector<double> attribute_values_;
};

}  // namespace tetcut
