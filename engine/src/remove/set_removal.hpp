// Can a *set* of tetrahedra be removed at once without making the mesh non-manifold?
// (paper 3.5: the neighbour strategy removes T together with some of its neighbours, and the
// set has to be tested as a whole; the one-tet cases of removability.hpp do not compose.)
//
// After the set goes, every vertex it touches must keep either no tet at all, or one
// face-connected shell whose link is a disk; every edge it touches must keep either no tet or
// one contiguous run of tets around it. One walk per vertex answers both: in the vertex's link,
// the kept region must be empty or a disk, i.e. the interface between kept and removed tets one
// simple closed curve; a link vertex the curve passes twice is an edge with two runs of kept
// tets, and is reported as that edge (set_removal.cpp and docs/removal-proof.md say why). The
// walk starts from the set's own faces, so it costs what the set touches, not whole shells.
//
// Everything is local: O(the set's faces + the interface's turns), no scan of the mesh, no
// allocation once the workspace has grown (stamped marks, cleared in O(1)).
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "refine/edge_split.hpp"
#include "remove/removability.hpp"
#include "tetcut/detail/stamped_property.hpp"
#include "tetcut/ids.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut {

// What an earlier test tells the test of a set that begins with the same tets, in the same
// order: the verdict at a vertex depends only on the set's tets at it, so a vertex that passed
// then and that none of the added tets contains passes again, and is not walked twice.
struct TestedPrefix {
  std::uint32_t tets = 0;      // the set begins with the tets of the set tested before
  std::uint32_t vertices = 0;  // that test's vertices_passed
};

// Caller-owned scratch for set_removable() and for the searches of the removal strategies,
// which ask questions about "the mesh once the marked set is gone". Reuse one per thread.
class SetRemovalWorkspace {
 public:
  // Stamps `set` as the tets about to go (a tet listed twice counts once). Every query below
  // is about the mesh without the marked tets, until the next mark().
  void mark(const TetMesh& mesh, std::span<const TetId> set);
  [[nodiscard]] bool marked(TetId t) const { return marked_.contains(t); }

  // The test on `set` (marks it first), vertex by vertex in the order the set first names them;
  // the first vertex whose link fails names the offence: that vertex, or the edge at it with two
  // runs of kept tets.
  Removability check(const TetMesh& mesh, std::span<const TetId> set, TestedPrefix prefix = {});

  // The same test at one vertex v only (marks the set first): the verdict check() would give
  // at v, with the same offence when it fails. What a refinement that isolates v's corner
  // tets needs to know before it splits (refinement_strategies.hpp).
  Removability check_at(const TetMesh& mesh, std::span<const TetId> set, VertId v);

  // The unmarked tets around v, split into face-connected components (connected through faces
  // containing v): appended to `tets` component after component, each size appended to
  // `sizes`. `seed` is any tet containing v (marked or not).
  void remaining_components(const TetMesh& mesh, VertId v, TetId seed, std::vector<TetId>& tets,
                            std::vector<std::uint32_t>& sizes);

  // The pieces the marked set leaves at a failing test's offence, appended as by the two
  // above: the components of the offending vertex's remaining shell, or the runs of kept tets
  // around the offending edge. Nothing for a passing test. What every search extends by.
  void remaining_pieces(const TetMesh& mesh, const Removability& offence, std::vector<TetId>& tets,
                        std::vector<std::uint32_t>& sizes);

  // Paper 3.5, figure 4: breadth-first from the marked tets around v, through unmarked tets
  // around v, to the nearest unmarked tet with a boundary face containing v (the shell's
  // border). Appends that path (without the marked start) to `out`, nearest-to-the-set first.
  // False when no path of at most `max_depth` tets exists; true with nothing appended when a
  // marked tet already has a boundary face through v.
  bool path_to_border(const TetMesh& mesh, VertId v, TetId seed, int max_depth, std::vector<TetId>& out);

  // Paper 3.5 as written ("if no smaller removable set is determined"): the same breadth-first
  // search carried on past the first border tet, to every tet with a border face through v
  // within `max_depth` tets; a border tet is an end, not walked through (a path through it is
  // longer than the one ending there). The ends into `ends` in the order met, so by path
  // length; border_path() gives each end's path. False when there is none; true with `ends`
  // empty when a marked tet already has a border face through v.
  bool border_paths(const TetMesh& mesh, VertId v, TetId seed, int max_depth, std::vector<TetId>& ends);
  // The path of the last border_paths() to one of its ends (marked start excluded, nearest to
  // the set first), appended to `out`. Valid until the next path search: the set tests and the
  // component walks in between leave it alone.
  void border_path(TetId end, std::vector<TetId>& out) const;

  // The unmarked tets around the edge (seed, local_edge) in rotation order, split into maximal
  // runs of consecutive tets: appended to `tets` run after run, sizes to `sizes`.
  void remaining_runs(const TetMesh& mesh, TetId seed, int local_edge, std::vector<TetId>& tets,
                      std::vector<std::uint32_t>& sizes);

  // Sizes the per-tet and per-vertex scratch for meshes up to these capacities now, rather
  // than in the middle of the first operation that needs it.
  void reserve(std::uint32_t tets, std::uint32_t vertices);

 private:
  // The whole shell of v into shell_ (and in_shell_).
  void collect_shell(const TetMesh& mesh, VertId v, TetId seed);
  // The breadth-first search of path_to_border() and border_paths() (set_removal.cpp).
  template <class AtBorder>
  bool search_to_border(const TetMesh& mesh, VertId v, TetId seed, int max_depth, AtBorder&& at_border);
  // The breadth-first step both shell walks take: each unmarked neighbour of `cur` across a face
  // through v not visited yet is marked visited and handed to `visit`.
  template <class Visit>
  void visit_fresh_shell_neighbours(const TetMesh& mesh, VertId v, TetId cur, Visit&& visit);
  // The set's tets at v are `removed_at_v` (marked, distinct). Not ok with `pinched` valid:
  // the edge (v, pinched) keeps two runs of tets; with `pinched` invalid: v itself is singular.
  struct VertexVerdict {
    bool ok;
    VertId pinched;
  };
  VertexVerdict vertex_ok(const TetMesh& mesh, VertId v, std::span<const TetId> removed_at_v);
  // The offence a failing verdict at v names, from the set's tets at v.
  static Removability offence(const TetMesh& mesh, VertId v, std::span<const TetId> removed_at_v,
                                 const VertexVerdict& verdict);

  StampedSet<TetId> marked_;     // the set about to go
  StampedSet<TetId> in_shell_;   // collect_shell()'s tets
  StampedSet<TetId> visited_;    // the current breadth-first walk's
  StampedMap<TetId, TetId> bfs_parent_;  // path_to_border(): where each visited tet was reached from
  StampedSet<VertId> walked_;    // vertex_ok(): link vertices the walk passed

  std::vector<TetId> shell_;
  std::vector<TetId> queue_;
  std::vector<std::uint8_t> depth_;
  std::vector<TetId> ring_;
  // The set's tets grouped by vertex (check): the set without repeats, its vertices in order of
  // first appearance, and for each the range of at_vertex_ holding its tets.
  std::vector<TetId> distinct_;
  std::vector<VertId> set_vertices_;
  std::vector<std::uint32_t> vertex_begin_;
  std::vector<std::uint8_t> vertex_changed_;  // per set vertex: a tet beyond the tested prefix has it
  std::vector<TetId> at_vertex_;
  StampedMap<VertId, std::uint32_t> vertex_slot_;  // check(): a set vertex's index in set_vertices_
};

// Convenience: the test with a given workspace.
inline Removability set_removable(const TetMesh& mesh, std::span<const TetId> set, SetRemovalWorkspace& ws) {
  return ws.check(mesh, set);
}

}  // namespace tetcut
