// The improvement pass that ends every Cutter transaction (a cut, a removal request): local mesh
// improvement of the tets the transaction made, until none is worse than I7's floor
// (invariants/check.hpp, QualityRule::kNoDegradation): min(F, the worst tet it replaced).
//
// The floor is the checker's, computed the engine's way: a made tet's host is the tet that was
// there before the transaction and holds it (its one ancestor in the journal after splits, the
// ancestor containing its centroid after flips: core/host_location.hpp), and the worst host sets
// it. Then, worst made tet first, the operations Klingner and Shewchuk's Stellar combines, each
// accepted only when the worst tet it touches gets better:
//   edge removal and the 2-3 flip (flips.hpp), the best of them on the tet's edges and faces;
//   collapse of one of the tet's vertices that the transaction made into any neighbour
//   (collapse.hpp), the best such;
//   smoothing of the tet's vertices that the transaction made (smoothing.hpp), never another;
//   and when none of those lifts it, insertion: the tet's longest edge split at its midpoint
//   (refine/edge_split.hpp: every tet around it halved), the new vertex smoothed, kept only
//   when the worst tet of what was split ends better (else rolled back to a savepoint).
// A made tet still below the floor after all that, on the surface, within the cut's reach (the
// tool's ball grown by D_ref) and removable on its own (paper 3.3), goes with the tissue: a
// sliver at the surface of the cut's making, the least tissue there is to remove. Reported
// apart (ImproveOutcome::removed).
// The ops run inside the transaction: the journal records them (a flip's tets get every replaced
// tet as parents, a moved vertex its barycentric origin), so a consumer still sees one net
// change, and a rollback undoes them with the rest.
//
// Cost: local. The tets it starts from are the transaction's (the journal's births), each
// operation is O(its star), and a bound on the operations keeps a pathological cut from looping.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "improve/collapse.hpp"
#include "core/tool_ball.hpp"
#include "core/uncuttable_tets.hpp"
#include "improve/flips.hpp"
#include "improve/smoothing.hpp"
#include "refine/edge_split.hpp"
#include "remove/tissue_removal.hpp"
#include "tetcut/detail/stamped_property.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::detail {

struct ImproveOutcome {
  double floor = 1.0;         // min(F, worst host): the quality every made tet must reach (F
                              // itself when every made tet is above F: the hosts are not looked at)
  double worst_before = 1.0;  // the worst made tet before the pass (1 when none)
  double worst_after = 1.0;   // and after: the worst tet the transaction made
  std::uint32_t flips = 0, collapses = 0, moves = 0, insertions = 0;
  std::uint32_t removed = 0;  // slivers removed with the tissue
  bool met = true;            // every made tet at or above the floor
};

class Improver {
 public:
  // Working sizes for meshes up to `tets` tet ids, allocated and touched now.
  void reserve(std::uint32_t tets);
  // The tets the open transaction made since `start` (and still has) against min(F, worst host);
  // improved when `improve`, only measured otherwise.
  // `reach`: the cut's ball grown by D_ref (none for a removal request), where a sliver may go
  // with the tissue and the cut's surface may move within its tolerance.
  // `uncuttable`: tets the pass must leave as a region (uncuttable_tets.hpp): it flips only among
  // tets all or none of which are uncuttable, moves and collapses no vertex of one, and removes
  // none.
  // `tissue`: the transaction's removal path, through which the slivers go (none: removed
  // through one of the Improver's own, untallied).
  ImproveOutcome run(TetMesh& mesh, const TetMesh::Savepoint& start, double floor_f, bool improve,
                     const Ball* reach = nullptr, const UncuttableTets* uncuttable = nullptr,
                     TissueRemoval* tissue = nullptr);

 private:
  // The made tets still live into made_; their worst radius ratio.
  double collect_made(TetMesh& mesh, const TetMesh::Savepoint& start);
  // min(F, the worst host of made_).
  double floor_of(TetMesh& mesh, double floor_f);
  // Operations on the made tets below out.floor, worst first, until none helps (counted in
  // `out`, at most kMaxOperations in all), then the slivers that go with the tissue.
  void lift(TetMesh& mesh, ImproveOutcome& out, std::uint32_t& operations);
  // One operation that lifts tet t, applied; false when none does.
  bool improve_tet(TetMesh& mesh, TetId t);
  // Insertion at the midpoint of t's longest edge, kept when it lifts the worst tet around it.
  bool insert_on_longest_edge(TetMesh& mesh, TetId t);
  // Whether the operations may reshape v's star (move v, collapse v): none of its tets is
  // uncuttable. A flip keeps the polytope it replaces, so it only needs tets of one kind.
  bool may_reshape_star(TetMesh& mesh, VertId v);
  bool may_flip(TetMesh& mesh, const FlipPlan& plan) const;

  Flipper flipper_;
  Collapser collapser_;
  Smoother smoother_;
  CollapsePlan collapse_, collapse_candidate_;
  SmoothPlan smooth_, smooth_candidate_;
  std::vector<TetId> star_;
  std::vector<VertId> neighbours_;
  EdgeSplitter splitter_;
  enum class Operation : std::uint8_t { kFlip, kCollapse, kMove, kInsert };
  Operation last_ = Operation::kFlip;  // what improve_tet() applied
  double goal_ = 0.0;                  // the run's floor, a rounding above
  const Ball* tool_ = nullptr;         // the run's reach, if a cut
  const UncuttableTets* uncuttable_ = nullptr;  // the run's, if any
  TissueRemoval* tissue_ = nullptr;             // the run's removal path
  TissueRemoval own_tissue_;
  FlipPlan plan_, candidate_;
  std::vector<TetId> made_, ancestors_, created_;
  std::vector<std::pair<double, TetId>> bad_;  // (radius ratio, tet), worst first
  StampedMap<TetId, double> host_quality_;
};

}  // namespace tetcut::detail
