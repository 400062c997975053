// Removing tetrahedra one by one without ever breaking the manifold (paper 3.3-3.7).
//
// A request names one tet T. If the O(1) test of removability.hpp accepts it, T goes alone
// ("direct"). Otherwise removing T alone would make a vertex or an edge singular, and a
// strategy finds a larger set to remove instead:
//   neighbours (3.5)  remove T with a few of its neighbours: for a vertex singularity the
//                     shortest path of tets from T to the border of the vertex's shell
//                     (breadth-first, depth <= 10), then that path extended by one of the two
//                     components it splits a vertex's shell into; for an edge singularity the
//                     tets on the left of T around the edge, on the right, then all of them.
//                     A candidate with a singularity of its own is repaired the same way, for
//                     a bounded number of rounds. May fail.
//   basic (3.4)       split every edge at the singular vertex (or touching the singular edge),
//                     then remove the small tets around it together with T's children.
//   combined (3.7)    neighbours; if that fails, the optimized local refinement: split only the
//                     edges along the stored shortest path (vertex) or of the smaller side
//                     (edge), then remove the small tets on that path with T's children; if
//                     that fails, basic. The default.
// After a refinement the set to remove is searched again from the small tets with the same
// neighbour search, because the paper's sets are not always removable as they stand: when T has
// another vertex a on the surface and the edge from a to the singular vertex is a boundary edge,
// removing T's children still pinches the new edge from a to its midpoint. If the search fails,
// the refinement escalates at the vertex it stumbled on (every edge there is split too and its
// small tets join the set; at most 5 splits per attempt), then the corners of every boundary
// vertex of T are refined at once, and as a last resort (basic and combined) T's set is grown by
// the whole shell of whatever still pinches until it is removable ("flood", reported apart).
// Measured: 100 % of the requests removed on the bundled meshes and on boxes
// (tests/engine/removal_random_test.cpp).
//
// Guarantees. Every set is tested by set_removable() before anything is removed, so the mesh is
// a valid manifold after every request whatever happens. A request is atomic: if it ends
// unresolved the mesh holds the same tets over the same positions as before (a refinement
// that did not lead to a removable set is undone by putting the original tets back; their ids
// may differ, the canonical hash does not). Removal order inside a request and the searches are
// deterministic (ids and face order only).
//
// Cost: local. The searches are bounded (path depth, rounds, evaluations, set size); nothing
// scans the mesh and, once the Remover's workspaces have grown, nothing allocates.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "tetcut/change_log.hpp"
#include "tetcut/edge_key_set.hpp"
#include "tetcut/edge_split.hpp"
#include "tetcut/ids.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/random.hpp"
#include "tetcut/removability.hpp"
#include "tetcut/set_removal.hpp"

namespace tetcut {

enum class RemovalStrategy : std::uint8_t { kBasic, kNeighbours, kCombined };

const char* to_string(RemovalStrategy strategy);
// "basic", "neighbours" (or "neighbors"), "combined".
std::optional<RemovalStrategy> parse_removal_strategy(std::string_view text);

struct RemovalOptions {
  RemovalStrategy strategy = RemovalStrategy::kCombined;
  int max_path_depth = 10;            // paper 3.5: breadth-first search limited to depth 10
  int max_rounds = 3;                 // repairs of a candidate that has a singularity of its own
  int max_evaluations = 32;           // set_removable() calls per search
  std::uint32_t max_set_size = 64;    // tets in a candidate set
  // Also run set_removable() on tets the O(1) test accepts (the two must agree; tests use it).
  bool verify_direct = false;
};

enum class RemovalOutcome : std::uint8_t {
  kDirect,      // removable on its own (paper 3.3)
  kNeighbours,  // removed with neighbours (paper 3.5)
  kRefinement,  // removed after a local refinement (paper 3.4 / 3.7)
  kFlood,       // removed with its neighbourhood grown until removable (our last resort)
  kUnresolved,  // left in place; the mesh is as before
};

const char* to_string(RemovalOutcome outcome);

struct RemovalResult {
  RemovalOutcome outcome = RemovalOutcome::kUnresolved;
  Removability first;                 // the O(1) test on the requested tet
  std::uint32_t tets_removed = 0;     // cardinality of the removed set
  std::uint32_t tets_created = 0;     // by refinement
  std::uint32_t edges_split = 0;
  bool optimized_refinement = false;  // kRefinement: by 3.7's path/side rather than 3.4's
};

// The paper's Tables 1 and 2. Counted per distinct tet: a tet requested again after being left
// unresolved is not counted again (its final fate replaces the first one).
struct RemovalReport {
  std::uint64_t requested = 0;             // distinct tets requested
  std::uint64_t repeated_requests = 0;     // requests for a tet already left unresolved
  std::uint64_t removed = 0;               // requested tets that went (by any way)
  std::uint64_t unresolved = 0;
  std::uint64_t direct = 0;
  std::uint64_t vertex_singularities = 0;
  std::uint64_t edge_singularities = 0;
  std::uint64_t resolved_by_neighbours = 0;
  std::uint64_t vertex_resolved_by_neighbours = 0;
  std::uint64_t edge_resolved_by_neighbours = 0;
  std::uint64_t resolved_by_refinement = 0;
  std::uint64_t resolved_by_optimized_refinement = 0;
  std::uint64_t resolved_by_flood = 0;          // the last resort, after every refinement failed
  std::uint64_t neighbour_set_tets = 0;         // sum of the sets removed by neighbours
  std::uint64_t vertex_neighbour_set_tets = 0;
  std::uint64_t edge_neighbour_set_tets = 0;
  std::uint64_t tets_removed = 0;               // all tets removed, refined children included
  std::uint64_t tets_created = 0;               // by refinement
  std::uint64_t edges_split = 0;
  std::uint64_t refinements_undone = 0;

  // Paper's "average cardinality", over the requests removed without refinement: tets removed
  // per request (1 for a direct removal). 0 when there are none.
  [[nodiscard]] double mean_cardinality() const;
  bool operator==(const RemovalReport&) const = default;
  // Adds another run's counts (a scenario that reloads or compacts its mesh has several).
  RemovalReport& operator+=(const RemovalReport& other);
};

// Removes requested tets with one strategy and keeps the statistics. Holds all scratch memory:
// keep one per mesh (or per thread) and reuse it.
class Remover {
 public:
  explicit Remover(RemovalOptions options = {});

  // Removes t (live) or leaves the mesh as it was. Appends what happened to `log` if given.
  RemovalResult remove(TetMesh& mesh, TetId t, ChangeLog* log = nullptr);

  [[nodiscard]] const RemovalReport& report() const { return report_; }
  // Sizes all per-tet and per-vertex scratch for meshes up to these capacities (see Cutter).
  void reserve(std::uint32_t tets, std::uint32_t vertices);
  void reset_report() { report_ = {}; }
  [[nodiscard]] const RemovalOptions& options() const { return options_; }

  // The net effect of the last remove(), as LocalChecker::after_operation wants it: ids live
  // before that it killed, and ids live now that it made (an id may be in both when reused).
  [[nodiscard]] std::span<const TetId> last_removed() const { return net_removed_; }
  [[nodiscard]] std::span<const TetId> last_created() const { return net_created_; }
  // Live tets that may have come to the surface in the last remove() (neighbours of what went,
  // new tets with a boundary face): what a cautery meets next.
  [[nodiscard]] std::span<const TetId> last_exposed() const { return exposed_; }

 private:
  struct Candidate {
    std::uint32_t begin = 0, size = 0;  // in pool_
    SetRemovalCheck offence;
  };

  bool search(const TetMesh& mesh, std::span<const TetId> seed, const SetRemovalCheck& offence,
              std::vector<TetId>& out);
  void expand(const TetMesh& mesh, const Candidate& from);
  void add_candidate(std::uint32_t begin, std::uint32_t size, std::span<const TetId> extra);

  bool refine_vertex(TetMesh& mesh, TetId& t, VertId v, bool optimized, RemovalResult& result);
  bool refine_edge(TetMesh& mesh, TetId& t, Edge e, int side, RemovalResult& result);
  // Splits edges_, then searches a removable set from the children of `seed_parents_` that
  // contain every vertex of `keep` (1 or 2 vertices) plus all children of t. When none is found
  // the refinement escalates: every edge at the vertex the search stumbled on is split too and
  // its small tets join the set (at most kMaxRefinementLevels splits). Removes the set, or
  // undoes every split of the attempt. `t` follows the undo.
  bool split_and_remove(TetMesh& mesh, TetId& t, std::span<const VertId> keep, RemovalResult& result,
                        bool keep_any = false);
  // Last resort after basic: split every edge at every boundary vertex of T and remove the small
  // tets at those vertices with T's children.
  bool refine_tet_corners(TetMesh& mesh, TetId& t, RemovalResult& result);
  // The last resort, which cannot fail: grows the set by the whole remaining shell of whatever
  // it would leave singular until it is removable (at worst the connected piece of the mesh).
  bool flood(TetMesh& mesh, TetId t, RemovalResult& result);
  // One split of edges_ / edge_refs_ inside an attempt, saving the tets it replaces that
  // existed before the attempt. False (mesh untouched) if the splitter refuses.
  bool split_edges(TetMesh& mesh, RemovalResult& result);
  // Puts back the tets that existed before the attempt; returns T's new id.
  TetId undo_attempt(TetMesh& mesh, std::size_t t_index);
  std::uint32_t fresh_stamp();

  void apply_removal(TetMesh& mesh, std::span<const TetId> set);
  void note_removed(std::span<const TetId> ids);
  void note_created(std::span<const TetId> ids);
  void grow_tet_arrays(const TetMesh& mesh);

  RemovalOptions options_;
  RemovalReport report_;
  SetRemovalWorkspace ws_;
  EdgeSplitter splitter_;
  EdgeKeySet edge_set_;

  // search
  std::vector<TetId> pool_;
  std::vector<Candidate> candidates_, frontier_, next_frontier_;
  std::vector<TetId> tmp_tets_, tmp_path_;
  std::vector<std::uint32_t> tmp_sizes_;

  // refinement
  std::vector<Edge> edges_;
  std::vector<EdgeRef> edge_refs_;  // a tet and local edge for each of edges_
  std::vector<TetId> ring_;
  std::vector<TetId> flood_;
  std::vector<TetId> region_, shell_, seed_parents_, found_, restored_, children_, x_, x_next_;
  std::vector<TetId> attempt_created_;                 // ids made by the attempt's splits
  std::vector<TetId> original_ids_;                    // tets live before the attempt it replaced
  std::vector<TetMesh::TetVerts> original_verts_;      // ... and their vertices, for the undo
  std::vector<std::uint32_t> attempt_stamp_;           // per tet: == attempt_ when made by it
  std::vector<std::uint32_t> aux_stamp_;
  std::vector<std::uint32_t> vert_attempt_stamp_;      // per vertex: == attempt_ when made by it
  std::uint32_t attempt_ = 0;
  ChangeLog split_log_;

  // per request bookkeeping
  std::vector<std::uint32_t> tet_stamp_;   // per tet: region / seed-parent / created stamps
  std::uint32_t stamp_ = 0;
  std::vector<std::uint8_t> met_unresolved_;  // per tet id: already counted as unresolved
  std::vector<TetId> net_removed_, net_created_, exposed_;
  std::vector<std::uint32_t> created_stamp_;  // per tet: == op_ when created by this request
  std::vector<std::uint32_t> removed_stamp_;  // per tet: == op_ when listed in net_removed_
  std::uint32_t op_ = 0;
  ChangeLog* log_ = nullptr;
};

// Picks live tets with a boundary face at random, one at a time, the way a cautery meets the
// surface (tests and `tetcut remove --random`). Seeded: the same sequence on every platform.
class BoundaryTetPicker {
 public:
  // O(#T) once: every tet with a boundary face becomes a candidate.
  BoundaryTetPicker(const TetMesh& mesh, std::uint64_t seed);
  // A uniformly chosen candidate that is still live and on the boundary; kNoTet when none.
  TetId pick(const TetMesh& mesh);
  // Tets that may have reached the boundary since (e.g. Remover::last_exposed()).
  void add(std::span<const TetId> tets);

 private:
  std::vector<TetId> pool_;
  std::vector<std::uint8_t> in_pool_;
  SplitMix64 rng_;
};

}  // namespace tetcut
