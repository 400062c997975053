// The tissue rule, as the cut itself accounts for it before it commits (the independent
// checker verifies the same rule after every cut: I10, invariants/check.hpp). After an ok cut:
//   1. no live cuttable tet that meets the tool has an edge longer than D_ref: the refinement's
//      promise (paper 3.2), which an unconverged loop or an operation of a later stage could
//      break. A cut that cannot keep it is refused;
//   2. no live cuttable tet with its centroid in the tool and its edges within D_ref (what paper
//      3.3 selects) remains, but what the report counts as left: tets the removal stage requested
//      that are still there (unresolved requests, and the pieces of kept tets whose one request
//      did not remove them) and pieces the removal stage's own splits left there. They are
//      counted and listed (Cutter::last_left_in_tool()). Any other such tet (one no request
//      asked for, one a later stage made) means the cut did not do what it reports: it is
//      refused;
// and, for people, the volume of cuttable tissue still inside the tool's ball (volume_in_tool).
//
// Local: the tets that meet the tool after the cut are those of T_hit still live (tets that
// were there before the cut never move) and the live tets the transaction made that meet it.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/tool.hpp"
#include "core/uncuttable_tets.hpp"
#include "cut/removal_loop.hpp"
#include "cut/tissue_selection.hpp"
#include "tetcut/detail/stamped_property.hpp"
#include "tetcut/cut.hpp"
#include "tetcut/mesh.hpp"

namespace tetcut::detail {

class TissueAudit {
 public:
  // What one audit reads: the cut's T_hit, its selection and the removal stage's record.
  struct Context {
    TetMesh& mesh;
    std::span<const TetId> hit;
    TetMesh::Savepoint start;          // the transaction's
    std::span<const TetMesh::TetBirth> removal_births;  // the tets the removal stage made
    const TissueSelection& selection;
    const RemovalLoop& removal;
    const UncuttableTets& uncuttable;
    double d_ref;
  };
  void reserve(std::uint32_t tets);
  // Audits the open transaction into report's left_in_tool and volume_left_in_tool. Returns why
  // the cut must be refused, if so.
  std::optional<std::string> run(const Context& ctx, CutReport& report);
  // The tets left in the tool by the last run(), sorted by id.
  [[nodiscard]] std::span<const TetId> left() const { return left_; }
  void clear() { left_.clear(); }

 private:
  // t (live) when it meets the tool (`meeting`: known to): rule 1 on its edges, rule 2's
  // count, its part of the tool's volume.
  std::optional<std::string> audit(const Context& ctx, TetId t, bool meeting, CutReport& report);

  std::vector<TetId> left_;
  StampedSet<TetId> removal_made_;  // made by the removal stage
};

}  // namespace tetcut::detail
