// What an operation did to the mesh, net, for a simulator to apply to its own arrays (design: the
// ChangeLog; a FEM model, the rendered surface). Derived from the mesh's journal when the
// operation commits (TetMesh::commit, Cutter::cut), so it is the one record there is:
//
//   removed           tets live before and gone after, sorted by id;
//   created           tets live after and not before, sorted by id, each with its parents: the
//                     tets live before that it lies in (one for a split's child, several for a
//                     flip's), listed in `parents`;
//   vertices          vertices made and still used, sorted by id, each a convex combination of
//                     vertices live before (an edge midpoint: two; a vertex smoothing moved off
//                     its edge: barycentric coordinates in the tet it moved into);
//   moved             vertices live before and after that the operation moved (the improvement
//                     pass smooths vertices within a cut's reach: improve/smoothing.hpp), sorted
//                     by id, each with its new position as a combination of vertices live
//                     before, as `vertices` has them; every tet around one is in `removed` and
//                     `created` (a tet's shape changed, so it is a new tet);
//   removed_vertices  vertices live before and gone after (no tet uses them any more).
//
// An undo (Cutter::undo(), TetMesh::undo()) gives a log with `undo` set: it takes back the last
// operation that changed the mesh. Its removed tets and vertices are those the operation made;
// its created tets (no parents) and vertices (count 0) are those it removed, restored under the
// same ids with the same vertices and positions; its moved vertices are back where they were
// (`before`: where the operation had put them; `from`/`weight`: where they are now, in a tet
// around them before the undo, some weights possibly negative). A restored entity's values are those it had
// before the undone operation: a consumer that keeps per-entity values keeps, per operation it
// applied, what that operation took away, and gives it back on the undo (newest first, as the
// Cutter takes cuts back; mechanics::TetLabels does so for labels).
//
// Net means intermediate steps are invisible: a tet a refinement made and a later step split or
// removed again appears nowhere, and its children's parents are the tets that were there before.
// Apply removals first, then creations. Compute the values of created and moved vertices from
// the values before the operation, all of them before writing any: a moved vertex may be an
// origin of another. Ids of removed tets and vertices may be reused by
// created ones in a later operation, never within one.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "tetcut/ids.hpp"
#include "tetcut/raw_mesh_view.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut {

struct CreatedTet {
  TetId tet;
  // Its parents are ChangeLog::parents[parents_begin .. parents_begin + parents_count), sorted
  // by id; `parent` is the first of them, the only one for a split's child.
  TetId parent;
  std::uint32_t parents_begin = 0, parents_count = 0;
};

struct CreatedVertex {
  VertId vertex;
  // Position and every attribute channel: sum over i < count of weight[i] * (the value of from[i]
  // before the operation), to rounding (the mesh's own position is the reference). Weights sum to
  // 1 and are positive, but for a vertex smoothing moved just outside the region the operation
  // started with (the organ's surface within the cut's reach may move outward by up to 5 % of an
  // edge: improve/smoothing.hpp): its coordinates in the nearest old tet, one or more slightly
  // negative, extrapolate. count 2: on the old edge (from[0], from[1]) at t = weight[1].
  std::array<VertId, 4> from{};
  std::array<double, 4> weight{};
  std::uint8_t count = 0;

  [[nodiscard]] bool on_edge() const { return count == 2; }
};

// A vertex there before the operation that it moved: where it is now, as a created vertex's
// record says it (`vertex` an old id, usually one of its own origins: it moves within its old
// star), and where it was, for a consumer that needs the old tets' shapes (which old tet holds a
// created tet's centroid) without a copy of its own.
struct MovedVertex : CreatedVertex {
  Vec3 before{};
};

// The move as plain numbers, the way the independent checker reads it (CheckOptions::moved).
inline RawMovedVertex raw_moved(const MovedVertex& m) {
  RawMovedVertex raw{m.vertex.value, {}, m.weight, m.count};
  for (std::size_t i = 0; i < m.count; ++i) raw.from[i] = m.from[i].value;
  return raw;
}

struct ChangeLog {
  std::vector<TetId> removed;
  std::vector<CreatedTet> created;
  std::vector<TetId> parents;
  std::vector<CreatedVertex> vertices;
  std::vector<MovedVertex> moved;
  std::vector<VertId> removed_vertices;
  bool undo = false;  // takes back the last operation: restored entities (see above)

  [[nodiscard]] std::span<const TetId> parents_of(const CreatedTet& c) const {
    return std::span<const TetId>(parents).subspan(c.parents_begin, c.parents_count);
  }

  // Room for this many entries of each kind (a caller that must not allocate per operation).
  void reserve(std::size_t n) {
    removed.reserve(n);
    created.reserve(n);
    parents.reserve(2 * n);
    vertices.reserve(n);
    moved.reserve(n);
    removed_vertices.reserve(n);
  }

  void clear() {
    removed.clear();
    created.clear();
    parents.clear();
    vertices.clear();
    moved.clear();
    removed_vertices.clear();
    undo = false;
  }
};

// Appends `from` to `to` (the log of several operations, in order).
inline void append(ChangeLog& to, const ChangeLog& from) {
  const auto offset = static_cast<std::uint32_t>(to.parents.size());
  to.removed.insert(to.removed.end(), from.removed.begin(), from.removed.end());
  for (CreatedTet c : from.created) {
    c.parents_begin += offset;
    to.created.push_back(c);
  }
  to.parents.insert(to.parents.end(), from.parents.begin(), from.parents.end());
  to.vertices.insert(to.vertices.end(), from.vertices.begin(), from.vertices.end());
  to.moved.insert(to.moved.end(), from.moved.begin(), from.moved.end());
  to.removed_vertices.insert(to.removed_vertices.end(), from.removed_vertices.begin(), from.removed_vertices.end());
  to.undo = to.undo || from.undo;
}

}  // namespace tetcut
