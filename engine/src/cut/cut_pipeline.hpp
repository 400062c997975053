// What a Cutter holds (cut.hpp): the spatial index, the refiner, the Remover, the per-tet marks
// and the scratch lists of one cut. Behind a pointer so that the installed cut.hpp names none of
// these internal types; allocated once, by the Cutter's constructor, so that a cut still
// allocates nothing (bench/cut_bench counts it).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/tool_ball.hpp"
#include "core/uncuttable_tets.hpp"
#include "cut/spatial_index.hpp"
#include "improve/improver.hpp"
#include "refine/refine.hpp"
#include "remove/removal.hpp"
#include "tetcut/cut.hpp"

namespace tetcut {

class Cutter::Pipeline {
 public:
  Pipeline(TetMesh& mesh, const CutParams& params);

  void prepare();
  void reset();
  std::optional<std::string> set_params(const CutParams& params);
  // One cut: attempts at D_ref, then at twice it, ... (CutParams::coarser_retries) while the
  // improvement pass cannot meet the floor.
  CutReport cut(const Vec3& centre, ChangeLog* log);
  CutReport remove(TetId t, ChangeLog* log);
  TetId tet_containing(const Vec3& p);
  // The mesh's ids are the ones the index was built on (TetMesh::id_epoch() unchanged since).
  [[nodiscard]] bool indexes_current_mesh() const { return epoch_ == mesh_.id_epoch(); }

  TetMesh& mesh_;
  CutParams params_;
  Remover remover_;
  std::vector<TetId> net_removed_, net_created_;
  RemovalReport removal_at_start_;  // remover_.report() when the transaction began
  detail::UncuttableTets uncuttable_;  // Cutter::set_uncuttable()

 private:
  // Removes the selected tets (removal_, growing), directly removable ones first, and fills the
  // counts.
  void remove_selected(CutReport& report);
  // CutReport::left_in_tool: the live tets the cut made, inside the tool, not selected tissue.
  void count_left_in_tool(CutReport& report);
  // One attempt at the cut with this D_ref: a transaction, committed or rolled back.
  CutReport attempt(const Ball& tool, double d_ref, ChangeLog* log);
  // Follows what a step made since `point` (the journal's record): which of the new tets are
  // pieces of selected tissue inside the tool, and so selected in turn.
  void follow(const TetMesh::Savepoint& point);
  [[nodiscard]] bool selectable(TetId t) const;
  // A tet the cut made, still there, not selected, and selectable: tissue left in the tool.
  [[nodiscard]] bool piece_in_tool(TetId t) const;
  [[nodiscard]] bool pending(TetId t) const;
  void clear_marks();  // a new cut: fresh marks
  // Opens the transaction a cut or a removal request is (savepoint, fresh marks, the removal
  // statistics as they stand), and closes one that failed: the mesh rolled back and the
  // statistics as they were, so that a refused cut counts none of its requests.
  void begin();
  void roll_back();
  // Tets the cut made that are still live: what its budget counts.
  [[nodiscard]] std::uint32_t net_made() const { return mesh_.net_tets_made_since(cut_start_); }
  // The improvement pass (improve/improver.hpp) over what the transaction made, into the report.
  void improve(CutReport& report);
  // Why a cut whose made tets the pass could not lift to the floor is refused.
  static std::string floor_failure(const CutReport& report);
  void finish(CutReport& report, ChangeLog* log);
  // Why the index cannot serve the mesh (compacted or replaced since it was built), if so.
  [[nodiscard]] std::optional<std::string> stale() const;
  // refusal_ from invalid_ and check_scale(): after the parameters or the mesh's scale change.
  void judge_scale();

  std::uint64_t epoch_ = 0;  // mesh_.id_epoch() when the index was built
  MeshScale scale_;          // what the refinement can serve (check_scale), measured once
  // Why every cut would be refused, decided when the parameters or the scale change, not per
  // cut: validate(params_) (invalid_), else check_scale() with scale_ (refusal_ holds either).
  std::optional<std::string> invalid_, refusal_;
  SpatialIndex index_;
  Refiner refiner_;
  detail::Improver improver_;
  ChangeLog changes_;                // the last cut's net change, derived by the journal at commit
  TetMesh::Savepoint cut_start_;
  std::vector<TetId> hit_, region_, removal_;
  // In the current cut: selected; selected tissue (a selected tet or a piece of one, inside the
  // tool or not); already requested (and left unresolved); waiting in work_.
  StampedSet<TetId> selected_, tissue_, tried_, queued_;
  std::vector<TetId> work_;          // selected tets to test for a direct removal
  std::optional<Ball> tool_;         // the cut's ball (none for remove())
  double d_ref_ = 0.0;
};

}  // namespace tetcut
