// The removal stage of a cut or a removal request (paper 3.3 to 3.7): every selected tet is
// removed or counted unresolved.
//
// Directly removable selected tets first, until none is left (paper 3.3: a strategy's larger set
// then meets fewer singularities); then one stuck tet, outside in (on the surface first: the
// paper's statistics are about "removing a tetrahedron on the mesh surface", 3.3, else any, for a
// tool inside the mesh), handed to the strategy (remove/removal.hpp), and again. Or, with
// RemovalOrder::kSurfaceFirstById, the first pending tet on the surface (else the first pending),
// requested as it comes, one by one; with kRevisit the same, but a tet neither removable nor
// taken by the neighbour search is put off until the next removal, and only when every pending
// tet is put off does the first go to the whole strategy.
//
// Removal only turns faces, edges and vertices into boundary ones, so a tet that is not
// removable becomes removable only when it gains a boundary face, i.e. when a face neighbour goes
// and exposes it: one pass over a worklist of what each request exposes or selects, instead of
// passes over T_removal.
//
// Then the pieces of kept tets inside the tool: a removal-time split (3.4, 3.7, the fallback)
// cuts unselected neighbours too, and a piece whose centroid falls in the ball is tissue in the
// tool that the selection does not follow (tissue_selection.hpp). Each is requested once, and
// what its own request makes is not followed as selected tissue; the pieces it leaves in the tool
// in turn are requested in the next round, up to kPieceRounds rounds (one for basic, whose 3.4
// splits only make slivers of them); what stays is counted by the audit.
#pragma once

#include <cstdint>
#include <vector>

#include "core/uncuttable_tets.hpp"
#include "cut/tissue_selection.hpp"
#include "remove/removal.hpp"
#include "remove/tissue_removal.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/detail/stamped_property.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::detail {

class RemovalLoop {
 public:
  void reserve(std::uint32_t tets);
  // The revisit order's marks too (RemovalOrder::kRevisit): reserved only for a Cutter that uses
  // it, since a mark by tet id costs 4 bytes a tet of room. (Here, not in removal_loop.cpp, so
  // that the planted removal stages of the tests, which replace that file, need not.)
  void reserve_revisit(std::uint32_t tets) {
    put_off_.reserve(tets);
    given_up_.reserve(tets);
  }

  // Everything one transaction's removal stage reads and writes.
  struct Context {
    TetMesh& mesh;
    TissueSelection& selection;
    Remover& remover;
    TissueRemoval& tissue;
    const UncuttableTets& uncuttable;
    const CutParams& params;
    TetMesh::Savepoint start;  // the transaction's: its tet budget counts what was made since
  };
  // Removes T_removal (selection.removal(), growing), filling the request counts, `requested`
  // and `kept_pieces_requested` of `report`. False when a request would pass the per-cut tet
  // budget: the caller rolls the transaction back, and `report` then counts none of the requests.
  bool run(const Context& ctx, CutReport& report);
  // Whether the last run() requested t.
  [[nodiscard]] bool requested(TetId t) const { return tried_.contains(t); }

 private:
  // One request for t (`first`: removability(mesh, t), just computed). `pieces`: follow what it
  // made (the selection's loop); off for the kept pieces.
  // `search_only`: no refinement (RequestLimits::search_only).
  bool request(const Context& ctx, TetId t, const Removability& first, bool pieces, CutReport& report,
               bool search_only = false);
  // RemovalOrder::kRevisit's requests (cut_strategies.hpp); false as run().
  bool revisit(const Context& ctx, CutReport& report);
  void enqueue(const Context& ctx, TetId t);
  // Selected, live and not requested yet.
  [[nodiscard]] bool pending(const Context& ctx, TetId t) const;
  // The paper's order: the first pending tet on the surface, else the first pending.
  [[nodiscard]] TetId next_pending(const Context& ctx) const;
  // kRevisit's: the same over the tets not yet handed to the whole strategy (`given_up_`), put
  // off ones skipped unless `put_off_too`.
  [[nodiscard]] TetId next_to_revisit(const Context& ctx, bool put_off_too) const;

  static constexpr int kPieceRounds = 4;
  // Already requested (and left unresolved); waiting in work_.
  StampedSet<TetId> tried_, queued_;
  // kRevisit: put off since the last removal; handed to the whole strategy.
  StampedSet<TetId> put_off_, given_up_;
  std::vector<TetId> work_;
};

}  // namespace tetcut::detail
