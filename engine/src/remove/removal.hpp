// Removing tetrahedra one by one without ever breaking the manifold (paper 3.3-3.7).
//
// A request names one tet T. If the O(1) test of removability.hpp accepts it, T goes alone
// ("direct"). Otherwise removing T alone would make a vertex or an edge singular, and a
// strategy removes a larger set instead:
//   neighbours (3.5)  the paper's search as written: for a vertex singularity every path of tets
//                     from T to the border of the vertex's shell (breadth-first, depth <= 10,
//                     shortest first), each extended by the components it splits a vertex's
//                     shell into when it fails;
//                     for an edge singularity the tets left of T around the edge, right of T,
//                     then all of them. The smallest removable candidate wins. May fail.
//   basic (3.4)       at every singular vertex and edge of T, split every edge at it, then
//                     remove the small tets there together with T's children; as written, with
//                     no repair of ours (the fallback below is counted apart).
//   combined (3.7)    neighbours; if that fails, the optimized local refinement: split only the
//                     edges along the shortest path (vertex) or of one side (edge) and remove
//                     the small tets there with T's children. The default.
//   wide              our extension, not the paper's: a broader search (whole shells, repairs
//                     of failing candidates over a few rounds, smallest set first) in place of
//                     3.5, then as combined. Kept for comparison (`tetcut stats`).
// When a paper set is not removable as it stands (3.4's "we can formally prove" misses cases,
// e.g. a boundary edge from another surface vertex of T to the singular vertex), basic,
// combined and wide end with one construction that always succeeds: T's neighbourhood is cut
// along the normal surface half way between T's vertices and the rest (remove/
// normal_surface_fallback.hpp; proof in docs/removal-proof.md). Only a split that the exact
// predicate refuses (floating-point degeneracy) or the caller's tet budget can stop it.
//
// Plan, then apply: every set is tested by set_removable() before anything is removed, so the
// mesh is a valid manifold after every request. An attempt that splits and then finds its set
// not removable is rolled back to a savepoint of the mesh's journal (the one undo), so a
// request is atomic and what it reports (last_removed/last_created) is its net change.
//
// Cost: local. The searches are bounded (path depth, candidates, set size); nothing scans the
// mesh and, once the Remover's workspaces have grown, nothing allocates.
#pragma once

#include <cstdint>
#include <memory>
#include <span>

#include "core/uncuttable_tets.hpp"
#include "remove/removability.hpp"
#include "remove/selection.hpp"
#include "remove/tissue_removal.hpp"
#include "tetcut/cut_strategies.hpp"  // RemovalStrategy, NeighbourSetChoice
#include "tetcut/ids.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/removal_report.hpp"

namespace tetcut {

struct RemovalOptions {
  RemovalStrategy strategy = RemovalStrategy::kCombined;
  int max_path_depth = 10;            // paper 3.5: breadth-first search limited to depth 10
  // 3.5's two readings (cut_strategies.hpp): keep the smallest removable set, or the first.
  NeighbourSetChoice neighbour_set = NeighbourSetChoice::kSmallest;
  std::uint32_t max_set_size = 64;    // tets in a candidate set of a search
  // The wide search only: repairs of a failing candidate, and set_removable() calls.
  int wide_rounds = 3;
  int wide_evaluations = 32;
  // Also run set_removable() on tets the O(1) test accepts (the two must agree; tests use it).
  bool verify_direct = false;
};

enum class RemovalOutcome : std::uint8_t {
  kDirect,      // removable on its own (paper 3.3)
  kNeighbours,  // removed with neighbours (paper 3.5, or the wide search)
  kRefinement,  // removed after a local refinement (paper 3.4 / 3.7)
  kFallback,    // removed by the normal-surface construction (docs/removal-proof.md)
  kUnresolved,  // left in place; the mesh is as before
};

const char* to_string(RemovalOutcome outcome);

// What one request did: the figures a caller sums (a cut's CutReport), as the Remover sums them
// into its RemovalReport.
struct RemovalResult {
  RemovalOutcome outcome = RemovalOutcome::kUnresolved;
  Removability first;                 // the O(1) test on the requested tet
  // The tet was left unresolved by an earlier request: it was counted as requested, with its
  // singularity, then (the statistics count distinct tets, as the paper's tables do).
  bool repeat = false;
  std::uint32_t tets_removed = 0;     // cardinality of the removed set
  std::uint32_t tets_created = 0;     // by refinement, net of the set removed
  std::uint32_t edges_split = 0;
  std::uint32_t selected_removed = 0; // tets of the removed set the caller had selected
  bool optimized_refinement = false;  // kRefinement: by 3.7's path/side rather than 3.4's
  bool over_budget = false;           // kUnresolved because a split would exceed the budget
  bool set_test_disagrees = false;    // verify_direct: set_removable() refused what 3.3 accepted
  // An edge singularity 3.5 searched: its candidates' verdicts as an EdgeSearchTally
  // configuration (removal_report.hpp); 0xFFFF when 3.5 did not search an edge singularity.
  std::uint16_t edge_search = 0xFFFF;
};

// What one request may do beyond the strategy's own bounds, and where it reports.
struct RequestLimits {
  std::uint32_t max_tets_created = 0xFFFFFFFFu;  // by any split of the request (the cut's budget left)
  const Selection* selection = nullptr;
  // Tets no set may take (Cutter::set_uncuttable()): a set holding one is refused like a set
  // that fails the test, and the request goes on to the next stage.
  const detail::UncuttableTets* uncuttable = nullptr;
  // The transaction's removal path, which tallies what goes (none: the Remover's own, begun anew
  // for each request); and its request-by-request counts, if the caller keeps them (a cut does).
  detail::TissueRemoval* tissue = nullptr;
  RequestCounts* counts = nullptr;
  // Stop after the neighbour search (3.5): no refinement, no fallback. RemovalOrder::kRevisit
  // puts a tet off this way and meets it again later.
  bool search_only = false;
};

// Removes requested tets with one strategy and keeps the statistics. Holds all scratch memory:
// keep one per mesh (or per thread) and reuse it.
class Remover {
 public:
  explicit Remover(RemovalOptions options = {});
  ~Remover();
  Remover(Remover&&) noexcept;
  Remover& operator=(Remover&&) noexcept;

  // Removes t (live) or leaves the mesh as it was. Runs in the mesh's open transaction (whose
  // journal records what it made: TetMesh::tets_made_since a savepoint taken before), or in one
  // of its own.
  RemovalResult remove(TetMesh& mesh, TetId t, const RequestLimits& limits = {});
  // The same for a caller that has just tested t: `first` is removability(mesh, t) on the mesh
  // as it is, and is not computed again (a cut tests every selected tet before it asks).
  RemovalResult remove(TetMesh& mesh, TetId t, const Removability& first, const RequestLimits& limits = {});

  [[nodiscard]] const RemovalReport& report() const { return report_; }
  // Sizes all per-tet and per-vertex scratch for meshes up to these capacities (see Cutter).
  void reserve(std::uint32_t tets, std::uint32_t vertices);
  // The marks of the tets a search-only request put off (RemovalOrder::kRevisit's requests), for
  // ids up to `tets`: reserved only for a caller that asks such requests (4 bytes a tet of room).
  void reserve_search_only(std::uint32_t tets);
  void reset_report() { report_ = {}; }
  // The statistics as they were before a transaction the caller rolled back (Cutter).
  void restore_report(const RemovalReport& before) { report_ = before; }
  // For another mesh (or the same one assigned anew): the report and every per-tet mark of the
  // old one are cleared; the workspaces keep their memory, so nothing is reallocated.
  void reset();
  // Other options, as a new Remover would have them (reset() included), in the same memory.
  void set_options(const RemovalOptions& options);
  [[nodiscard]] const RemovalOptions& options() const { return options_; }

  // The net effect of the last remove(), sorted by id: ids live before it that it killed, and
  // ids live now that it made (never the same id: no id is reused inside a transaction).
  [[nodiscard]] std::span<const TetId> last_removed() const;
  [[nodiscard]] std::span<const TetId> last_created() const;
  // Live tets that may have come to the surface in the last remove() (neighbours of what went,
  // new tets with a boundary face): what a cautery meets next.
  [[nodiscard]] std::span<const TetId> last_exposed() const;

 private:
  struct Workspace;
  RemovalOptions options_;
  RemovalReport report_;
  std::unique_ptr<Workspace> ws_;
};

}  // namespace tetcut
