// What a Cutter holds (cut.hpp) and the walk of one cut through its stages: locate
// (walking_locator.hpp), refine (refine/refine.hpp), select (tissue_selection.hpp), remove (removal_loop.hpp),
// improve (improve/improver.hpp), audit (tissue_audit.hpp), pieces (fragment_search.hpp),
// commit (cut_transaction.hpp, piece_labels.hpp). Behind
// a pointer so that the installed cut.hpp names none of these internal types; allocated once, by
// the Cutter's constructor, so that a cut still allocates nothing (bench/cut_bench counts it).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/tool.hpp"
#include "core/uncuttable_tets.hpp"
#include "cut/cut_transaction.hpp"
#include "cut/fragment_search.hpp"
#include "cut/piece_labels.hpp"
#include "cut/removal_loop.hpp"
#include "cut/spatial_index.hpp"
#include "cut/walking_locator.hpp"
#include "cut/tissue_audit.hpp"
#include "cut/tissue_selection.hpp"
#include "improve/improver.hpp"
#include "refine/refine.hpp"
#include "remove/removal.hpp"
#include "remove/tissue_removal.hpp"
#include "tetcut/cut.hpp"

namespace tetcut {

class Cutter::Pipeline {
 public:
  Pipeline(TetMesh& mesh, const CutParams& params);

  void prepare();
  // The tet ids prepare() makes room for: the mesh's and half as many again.
  [[nodiscard]] std::uint32_t room_for_tets() const {
    return mesh_.tet_capacity() + mesh_.tet_capacity() / 2 + 4096;
  }
  // The revisit order's marks, for a Cutter that uses it (prepare(), set_params()).
  void reserve_revisit();
  void reset();
  Renumbering compact(IdOrder order);
  std::optional<std::string> set_params(const CutParams& params);
  std::optional<std::string> set_uncuttable(std::span<const TetId> tets);
  // A cut by the capsule a-b (a ball when a == b), of the tool's diameter.
  CutReport cut(const Vec3& a, const Vec3& b, ChangeLog* log);
  CutReport remove(TetId t, ChangeLog* log);
  std::optional<std::string> undo(ChangeLog* log);
  [[nodiscard]] std::uint32_t undo_depth() const { return kept_cuts_; }
  [[nodiscard]] const std::optional<CutReach>& last_undone_reach() const { return last_undone_reach_; }
  TetId tet_containing(const Vec3& p);
  // The mesh's ids are the ones the index was built on (TetMesh::id_epoch() unchanged since).
  [[nodiscard]] bool indexes_current_mesh() const { return epoch_ == mesh_.id_epoch(); }
  [[nodiscard]] bool uncuttable(TetId t) const;

  [[nodiscard]] TetMesh& mesh() const { return mesh_; }
  [[nodiscard]] const CutParams& params() const { return params_; }
  [[nodiscard]] const RemovalReport& removal_report() const { return remover_.report(); }
  [[nodiscard]] const std::vector<TetId>& last_removed() const { return transaction_.net_removed(); }
  [[nodiscard]] std::span<const RawMovedVertex> last_moved() const { return transaction_.net_moved(); }
  [[nodiscard]] const std::vector<TetId>& last_created() const { return transaction_.net_created(); }
  [[nodiscard]] std::span<const TetId> last_left_in_tool() const { return audit_.left(); }
  [[nodiscard]] double last_min_dihedral_held() const { return last_min_dihedral_held_; }
  [[nodiscard]] std::span<const Fragment> last_fragments() const { return fragments_; }
  [[nodiscard]] std::uint32_t pieces() const { return labels_.pieces(); }

 private:
  // The stages of one cut, in order; each fills its part of the report. A stage that returns
  // false has refused the cut (refuse()): the caller rolls the transaction back.
  class Laps;  // the stages' stopwatch
  // Refine to commit with one refinement rule: committed, or refused and rolled back.
  void attempt(const Tool& tool, RefinementRule rule, Laps& clock, CutReport& report, ChangeLog* log);
  // attempt(), and when its pass grew the volume below theta outside the tool (the mesh rule,
  // weighed once when the pass ends: improve/improver.hpp), the same attempt again with every
  // plan held to the rule (CutReport::mesh_rule_retries).
  void attempt_under_mesh_rule(const Tool& tool, RefinementRule rule, Laps& clock, CutReport& report, ChangeLog* log);
  // `make` (an attempt, or a removal request's one transaction), and again with every plan held
  // to the mesh rule when its pass grew the volume below theta; the report counts the second.
  template <class Attempt>
  void under_mesh_rule(CutReport& report, Attempt&& make);
  void locate(const Tool& tool);
  bool refine(const Tool& tool, RefinementRule rule, CutReport& report);
  void select(CutReport& report);
  bool remove_selected(CutReport& report);
  bool improve(CutReport& report);
  bool audit(CutReport& report);
  void find_pieces(CutReport& report);
  void commit(CutReport& report, ChangeLog* log);
  // The end of a cut's attempt and of a removal request, after their removals (`ok`: none was
  // refused): improve, audit, the pieces and commit, or the roll-back.
  void conclude(bool ok, Laps& clock, CutReport& report, ChangeLog* log);

  // Opens the transaction a cut or a removal request is, with the tool (none for a request).
  void begin(const Tool* tool);
  // A refusal, into the report: false, for the stage to return.
  static bool refuse(CutReport& report, CutRefusal refusal, std::string why);
  // Rolls the open transaction back after a refusal: the mesh and the removal statistics as
  // before the cut; the report keeps what the stages measured before the refusal.
  void roll_back(CutReport& report);
  // Why the index cannot serve the mesh (compacted or replaced since it was built), if so.
  [[nodiscard]] std::optional<std::string> stale() const;
  // refusal_ from invalid_ and check_scale(), and the refinement rule: after the parameters or
  // the mesh's scale change.
  void judge_scale();

  TetMesh& mesh_;
  CutParams params_;
  std::uint64_t epoch_ = 0;  // mesh_.id_epoch() when the index was built
  MeshScale scale_;          // what the refinement can serve (check_scale), measured once
  RefinementRule rule_ = RefinementRule::kPaper;  // params_.refinement, auto resolved by judge_scale()
  // Why every cut would be refused, decided when the parameters or the scale change, not per
  // cut: validate(params_) (invalid_), else check_scale() with scale_ (refusal_ holds either).
  std::optional<std::string> invalid_, refusal_;
  WalkingLocator locator_;
  std::vector<TetId> rewired_;  // an undo's rewired tets, for the locator
#ifdef TETCUT_CHECK_LOCATE
  std::vector<TetId> scanned_;
#endif
  Refiner refiner_;
  Remover remover_;
  detail::Improver improver_;
  detail::UncuttableTets uncuttable_;  // Cutter::set_uncuttable()
  detail::CutTransaction transaction_;
  detail::TissueSelection selection_;
  detail::TissueRemoval tissue_;
  detail::RemovalLoop removal_loop_;
  detail::TissueAudit audit_;
  detail::PieceLabels labels_;          // which piece each tet is in: Cutter::pieces()
  detail::FragmentSearch search_;       // the pieces a transaction detached
  std::vector<Fragment> fragments_;     // the last transaction's: Cutter::last_fragments()
  std::vector<TetId> removed_, created_;  // the open transaction's net change, for the search
  bool grew_bad_volume_ = false;          // the last pass's outcome: the mesh rule asks for another attempt
  bool hold_plans_to_mesh_rule_ = false;  // the attempt being made is that other one
  double last_min_dihedral_held_ = 180.0;  // the last transaction's (CutReport::min_dihedral_held_deg)
  std::vector<TetId> hit_, region_;  // T_hit, and the refined region
  // Where the removal stage began and ended in the journal: what it made, for the audit.
  TetMesh::Savepoint removal_start_, removal_end_;

  // A committed cut kept for undo(): the mesh's record of it, and what this pipeline changed.
  struct KeptCut {
    TetMesh::TransactionRecord mesh;
    RemovalReport removal_before;
    double min_dihedral_held_before = 180.0;
    std::vector<TetId> removed, created;  // its net change
    detail::PieceLabels::Undo labels;
    std::optional<CutReach> reach;  // its tool and D_ref (none: a removal by id)
  };
  // A ring of params_.undo_history, the newest kept_cuts_ of them at history_top_ and below it.
  std::vector<KeptCut> history_;
  std::uint32_t history_top_ = 0, kept_cuts_ = 0;
  const char* history_emptied_by_ = nullptr;  // why nothing is kept, for undo()'s refusal
  std::uint64_t version_at_begin_ = 0;
  double min_dihedral_held_at_begin_ = 180.0;
  std::optional<CutReach> reach_at_begin_, last_undone_reach_;
  ChangeLog undo_log_;  // undo()'s net change when the caller asks for none (the moves, for last_moved())
  // The ring sized by params_.undo_history, every record with room to be kept without allocating.
  void reserve_history();
  void empty_history(const char* why) {
    kept_cuts_ = 0;
    history_emptied_by_ = why;
  }
};

}  // namespace tetcut
