// The pieces a cut detached (the pipeline's last stage, inside the cut's transaction): a walk
// over face neighbours from the cut's new surface, one group per seed, all groups advancing in
// lockstep (one tet each per round) and merging where they meet. A group that runs out of tets
// to visit is a whole piece; the search stops when, among the groups that carry one piece label
// (piece_labels.hpp: the groups were one piece before the cut), at most one is still walking and
// it has visited more volume than every finished one: that one is the organ, the finished ones
// are the pieces the cut detached. So the work grows with the small pieces, not the organ:
// about (groups) x (the small pieces' tets). When the two sides stay joined by a bridge far from
// the cut, both keep walking until the bound on tets visited, and the search says it stopped
// there (bounded): the pieces it could not tell apart are not reported.
//
// Seeds: every tet the cut made and still has, and the tet each surviving corner of a removed
// tet names (TetMesh::vertex_tet): around a vertex the mesh is manifold, so its tets are one
// face-connected star, and every survivor the cut touched shares a corner with what it removed.
// For the same reason seeds that share a vertex start as one group: a cut that detaches nothing
// usually has one group before any walk.
//
// The marks (a visited tet's group and its successor in the group's queue; a seed vertex's group)
// live in an open-addressing table sized by the bound, not by the mesh, cleared entry by entry
// after each search; groups in a union-find, each group's queue threaded through the marks:
// nothing allocates once reserved, and the memory does not grow with the mesh. What only a
// detaching cut needs is computed only then: a group's label when two groups are left to tell
// apart, volumes from the first group that finishes on (most cuts end with one group walking
// and none finished, and measure nothing).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "cut/piece_labels.hpp"
#include "tetcut/ids.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut::detail {

class FragmentSearch {
 public:
  struct Piece {
    std::uint32_t first = 0, count = 0;  // its tets: tets()[first, first + count), sorted by id
    double volume = 0.0;
    Vec3 centroid{};
    TetId organ;  // a tet of the piece it came away from: the largest of its label
  };

  // Room for a search of `bound` tets on a mesh of up to `tets` tet ids.
  void reserve(std::uint32_t tets, std::uint32_t bound);

  // Finds the pieces the open transaction (from `start`) detached. `removed`: the tets live at
  // the start and gone now; `created`: the tets made and still live.
  void run(TetMesh& mesh, const PieceLabels& labels, std::span<const TetId> removed, std::span<const TetId> created,
           std::uint32_t bound);

  [[nodiscard]] std::span<const Piece> pieces() const { return pieces_; }
  [[nodiscard]] std::span<const TetId> tets() const { return tets_; }
  [[nodiscard]] std::span<const TetId> tets_of(const Piece& p) const { return std::span<const TetId>(tets_).subspan(p.first, p.count); }
  [[nodiscard]] bool bounded() const { return bounded_; }
  [[nodiscard]] std::uint32_t visited() const { return static_cast<std::uint32_t>(visited_.size()); }

 private:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  static constexpr std::uint32_t kVertexKey = 0x80000000u;  // a vertex's mark: its id with the top bit
  struct Mark {
    std::uint32_t key = kNone;  // a tet id, or a vertex id | kVertexKey
    std::uint32_t group = 0;
    std::uint32_t next = 0;     // the mark of a tet's successor in its group's queue
  };
  struct Group {
    std::uint32_t parent;      // union-find
    std::uint32_t head, tail;  // its queue of tets to expand: marks, threaded through Mark::next
    std::uint32_t tets;        // visited
    std::uint32_t label;       // the piece label its seed carried, one for every tet it reaches (kNone: not asked yet)
    std::uint32_t round;       // the last list_roots() that listed it
    std::uint32_t piece;       // its index in pieces_, when it is one (collect())
    std::uint32_t seed;        // the tet it started from
    double volume;
    Vec3 moment;               // sum of volume x centroid
  };

  // The entry of `key`, or the free one where it goes.
  [[nodiscard]] std::uint32_t probe(std::uint32_t key) const;
  // The table is half full: the search stops (bounded) rather than let it fill.
  [[nodiscard]] bool full() const;
  void seed(TetId t);
  // Group g's piece label (a root's), found from its seed on first use.
  std::uint32_t label(std::uint32_t g);
  // From now on volumes are summed: those of the tets visited so far, then each tet as visited.
  void start_measuring(const TetMesh& mesh);
  void measure(const TetMesh& mesh, TetId t, Group& group);
  // t joins group g, its mark at the free entry `slot`.
  void visit(const TetMesh& mesh, TetId t, std::uint32_t g, std::uint32_t slot);
  std::uint32_t find(std::uint32_t g) {  // inline: every neighbour and shared vertex asks it
    while (groups_[g].parent != g) {
      groups_[g].parent = groups_[groups_[g].parent].parent;  // path halving
      g = groups_[g].parent;
    }
    return g;
  }
  std::uint32_t unite(std::uint32_t g, std::uint32_t h);
  // One tet of group g's queue expanded: its unvisited neighbours join g, a neighbour of
  // another group merges the two. Returns g's root after.
  std::uint32_t expand(const TetMesh& mesh, std::uint32_t g);
  // Unites the seeds' groups that share a vertex.
  void unite_by_shared_vertices(const TetMesh& mesh);
  // walking_: each root with tets to expand, once; the others to finished_.
  void list_roots();
  // Whether the walking groups have told every label's pieces apart (the header's rule).
  [[nodiscard]] bool resolved();
  void collect();

  TetMesh* mesh_ = nullptr;              // the search's, for label()
  const PieceLabels* labels_ = nullptr;
  bool measuring_ = false;
  bool overflow_ = false;  // the marks filled in the middle of a round
  std::vector<Mark> marks_;                 // a power of two
  std::vector<std::uint32_t> marks_used_;   // the entries in use, for clearing
  std::uint32_t listing_ = 0;
  std::vector<Group> groups_;
  std::vector<std::uint32_t> walking_, finished_;  // root groups with tets to expand, and without
  std::vector<std::uint32_t> visited_;  // the visited tets' marks, in visit order
  std::vector<Piece> pieces_;
  std::vector<TetId> tets_;
  bool bounded_ = false;
};

}  // namespace tetcut::detail
