// One cautery cut, as a simulator calls it many times a second (paper 3.1 to 3.7 together). The
// tool is the paper's ball at the tip (cut()), or the capsule the tip sweeps between two samples
// of a stroke (cut_segment(): every point within the tool's radius of the segment; a ball is the
// capsule of a zero-length segment). Every stage below holds for both, "in the tool" meaning
// within the radius of the segment:
//
//   locate   T_hit = live tets meeting the tool (a walk through faces, never a mesh scan)
//   refine   the loop of paper 3.2 around T_hit with D_ref = d_ref_factor x diameter, following
//            the new tets that meet the tool
//   select   T_removal = the refined region's tets that are inside the tool and have no edge
//            longer than D_ref (paper 3.3). "Inside" means: the tet's centroid lies in the
//            closed tool. A tet that only grazes the tool stays; the cavity then has the
//            tool's size to within one small tet.
//   remove   every directly removable selected tet first (3.3), again until none is left; then
//            the strategy (cut_strategies.hpp) on one stuck tet, on the surface first (outside in),
//            and again (CutParams::order: or the paper's one by one). When a strategy refines a
//            selected tet, its pieces that pass the same test join T_removal; pieces of a kept tet
//            stay kept (selection is decided once, on the refined region). Every selected tet is
//            removed or counted unresolved.
//   improve  flips, collapses, smoothing of the cut's own vertices (improve/improver.hpp) until
//            every tet the cut made reaches min(quality_floor, the worst tet it replaced): the
//            floor the invariant checker holds every cut to (I7). A sliver at the cut's surface
//            that nothing lifts goes with the tissue.
//   audit    the tissue rule (the checker's I10): no cuttable tet that meets the tool keeps an
//            edge longer than D_ref, and the tets the selection would take that are still there
//            are counted and listed (last_left_in_tool()): unresolved requests, pieces of kept
//            tets no request removed. With the volume of tissue left in the tool and removed
//            beyond it (estimates: core/tool.hpp, volume_in_tool).
//   pieces   the pieces the cut detached from the organ (Cutter::last_fragments()): a walk from
//            the cut's new surface in lockstep that stops once every piece but the largest is
//            walked (engine/src/cut/fragment_search.hpp); with CutParams::debris_volume, the
//            detached pieces below it are removed in the same transaction.
//   commit   the transaction, the locator's boundary tets, the change log, the piece labels.
//
// Atomic: the whole cut runs in a mesh transaction; if it cannot complete (a split refused for
// degeneracy, the per-cut tet budget exceeded, a created tet the improvement pass cannot lift to
// the quality floor, a tet meeting the tool with an edge longer than D_ref) it is rolled back, the
// mesh is bit-identical to before, and the report says why (CutReport::refusal, failure). A tet
// left unresolved by the `neighbours` strategy is not a failure: the mesh is valid, the report
// counts it.
//
// The budget counts net tets created: tets the cut made that are still there at its end (an
// attempt a strategy undid, or children a later step removed, do not count).
//
// Cost: local to the tool. Scratch memory lives in the Cutter, allocated when it is constructed;
// nothing allocates once warm (the mesh's arrays grow only when the free lists run dry).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tetcut/change_log.hpp"
#include "tetcut/cut_strategies.hpp"
#include "tetcut/ids.hpp"
#include "tetcut/mesh.hpp"
#include "tetcut/removal_report.hpp"
#include "tetcut/vec3.hpp"

namespace tetcut {

struct CutParams {
  double tool_diameter = 1.0;        // the ball's diameter (paper: the cautery tip), a capsule's width
  double d_ref_factor = 1.5;         // D_ref = d_ref_factor x tool_diameter (paper 3.2)
  double p = 1.5;                    // shell edge ratio of the refinement loop (paper 3.2)
  std::uint32_t search_depth = 10;   // neighbour search depth (paper 3.5)
  std::uint32_t max_refine_iterations = 8;
  std::uint32_t max_tets_created = 20000;  // net tets a cut may create; more is refused early
  RemovalStrategy strategy = RemovalStrategy::kCombined;   // cut_strategies.hpp
  SplitMethod split_method = SplitMethod::kTemplates;
  // Which refinement serves the tool (cut_strategies.hpp): the paper's loop, longest-edge
  // bisection graded to the tool (its tets grow away from the tool instead of splitting coarse
  // neighbours at the tool's scale), or auto: graded for a tool fine for the mesh, else the
  // paper's, made again graded when the improvement pass cannot lift what the paper's made
  // (CutReport::refinement and retries say what ran). The paper's stops after
  // max_refine_iterations rounds, the graded one only at the budget (max_tets_created) or when
  // every tet meeting the tool has its edges within D_ref.
  RefinementRule refinement = RefinementRule::kAuto;
  RemovalOrder order = RemovalOrder::kDirectFirst;        // cut_strategies.hpp
  NeighbourSetChoice neighbour_set = NeighbourSetChoice::kSmallest;  // paper 3.5's two readings
  // The improvement pass that ends a cut or a removal request (flips, collapses, smoothing of
  // the cut's own vertices, insertion): it lifts every tet the cut made to its own floors, a
  // radius ratio of min(quality_floor, its host's) and a smallest dihedral angle of
  // min(min_dihedral_deg, its host's), its host the tet that held it before the cut: the floors
  // the invariant checker holds every transaction to (I7). Off: the paper's algorithm alone, as
  // its tables measure it.
  bool improve = true;
  double quality_floor = 0.1;     // F, a radius ratio in [0, 1]
  double min_dihedral_deg = 15.0;  // theta, degrees in [0, 70] (a regular tet's is 70.53)
  // The pieces a cut detaches (Cutter::last_fragments()) are always reported. With a debris
  // volume > 0, those below it (and with no uncuttable tet) are removed in the same cut, as a
  // simulator drops debris: in the cut's change log, reported apart from the tissue removed
  // (CutReport::debris_*). 0: report only.
  double debris_volume = 0.0;
  // The tets the search for detached pieces visits at most: reached when the two sides of a cut
  // stay joined by a bridge far from it (CutReport::fragment_search_bounded).
  std::uint32_t fragment_search_bound = 65536;
  // The cuts Cutter::undo() can take back, newest first (0: none kept). Each kept cut holds its
  // journal (the old value of every slot it wrote: about 32 bytes a slot, a few hundred slots for
  // a gated cut) and its net change; room for each is made once, about 0.9 MB, so that keeping
  // one allocates nothing.
  std::uint32_t undo_history = 0;

  // D_ref, the one length the refinement, the selection and the tissue rule are judged at.
  [[nodiscard]] double d_ref() const { return d_ref_factor * tool_diameter; }
};

// A message naming the parameter when one is non-finite, non-positive or out of range.
std::optional<std::string> validate(const CutParams& params);

// Each stage's wall time over every attempt of the cut, and the whole call's (total_us, from the
// call to its return: a refused cut's rollback included).
struct CutTimings {
  double locate_us = 0, refine_us = 0, select_us = 0, remove_us = 0, improve_us = 0;
  double finish_us = 0;  // the tissue audit, the commit, the index and the change log
  double pieces_us = 0;  // the search for detached pieces, and the debris removed
  double total_us = 0;
};

// Why a cut or a removal request was refused (CutReport::ok false), the mesh untouched.
enum class CutRefusal : std::uint8_t {
  kNone,
  kStaleIndex,       // the mesh was compacted or replaced behind the Cutter's back
  kParameters,       // validate() or the mesh's scale refuses the parameters (check_scale)
  kRequest,          // remove(): the tet is not live, or uncuttable
  kDegenerateSplit,  // a split the exact predicate refuses (a child would be flat or inverted)
  kTetBudget,        // the cut would make more than max_tets_created tets
  kQualityFloor,     // a created tet the improvement pass cannot lift to the floor (I7)
  kTissueRule,       // a cuttable tet meeting the tool would keep an edge longer than D_ref (I10)
};
inline constexpr int kCutRefusals = 8;
const char* to_string(CutRefusal refusal);

// A cut's account. The removal requests' counts (RequestCounts, removal_report.hpp: requests,
// tets_removed, direct, the singularities and how they were resolved, unresolved) are its base.
struct CutReport : RequestCounts {
  bool ok = true;
  CutRefusal refusal = CutRefusal::kNone;
  std::string failure;               // why the cut was rolled back (when !ok), for people
  // A refused cut's counts say what it did before it was refused; none of it is in the mesh or
  // in removal_report().
  std::uint32_t tets_hit = 0;        // live tets meeting the tool before refinement
  std::uint32_t refine_iterations = 0;
  std::uint32_t edges_split = 0;     // by the refinement loop
  std::uint32_t tets_refined = 0;    // parents replaced by the refinement loop
  std::uint32_t requested = 0;       // |T_removal|, children of selected tets that joined it included
  std::uint32_t tets_created = 0;    // net: by refinement and by removal, still there at the end
  // Pieces of unselected tets that a removal-time split (3.4, 3.7, the fallback) left inside the
  // tool, each requested once (no cascade), in `requests` too.
  std::uint32_t kept_pieces_requested = 0;
  // The tissue rule (I10), after the cut: live cuttable tets whose centroid is in the tool and
  // whose edges are within D_ref, i.e. tissue the paper's selection takes, still there: the tets
  // of unresolved requests and pieces of kept tets their request did not remove. Listed by
  // Cutter::last_left_in_tool(). 0: the cut took all the tissue its rule takes.
  std::uint32_t left_in_tool = 0;
  // The volume of cuttable tissue still inside the tool: of every live cuttable tet that
  // meets it, the part inside (volume_in_tool: exact for tets wholly in or out, else the midpoint
  // rule on 8 equal children). The paper's selection (centroid in the tool, edges within D_ref)
  // leaves the parts of grazing tets by design: this says how much.
  double volume_left_in_tool = 0.0;
  // What the cut removed as tissue (the removal requests and the improvement pass's slivers):
  // its volume, and of it the tets whose centroid is outside the tool, the volume outside the
  // tool (estimated as above) and the tets reaching beyond the cut's reach (the tool grown
  // by D_ref).
  double volume_removed = 0.0;
  std::uint32_t tets_removed_beyond_tool = 0;
  double volume_removed_beyond_tool = 0.0;
  std::uint32_t tets_removed_beyond_reach = 0;
  // Tets the tool selects (3.3) that are uncuttable (Cutter::set_uncuttable()): left in place,
  // neither requested nor counted as unresolved or left in the tool.
  std::uint32_t uncuttable_in_tool = 0;
  double min_radius_ratio = 1.0;     // worst tet created (1 when none), after the improvement pass
  double min_radius_ratio_before_improvement = 1.0;
  double min_dihedral_deg = 180.0;   // smallest dihedral angle of a tet created (180 when none)
  double min_dihedral_deg_before_improvement = 180.0;
  // The lowest floors of the created tets, each min(F or theta, its host's): F and theta when
  // every created tet is above them.
  double quality_floor = 1.0;
  double dihedral_floor_deg = 180.0;
  bool quality_met = true;           // every created tet reaches its floors
  // The theta the cut held its created tets to: CutParams::min_dihedral_deg, or, when the
  // improvement pass could not lift them to it, 10 degrees, then none (the pass going on from
  // where it stood, each time counted in angle_retries): a refused cut costs a simulation more than one
  // angle below theta. Invariant checks of the cut take this theta (scenario::cut_check_options).
  double min_dihedral_held_deg = 180.0;
  std::uint32_t angle_retries = 0;
  // The improvement pass's operations: flips, collapses, vertex moves (smoothing), insertions
  // (an edge split at its midpoint, kept), and the slivers it let go with the tissue (in
  // tets_removed_by_improvement, apart from the requests' tets_removed).
  std::uint32_t improvement_flips = 0, improvement_collapses = 0, improvement_moves = 0, improvement_insertions = 0;
  // Vertices there before the cut that the pass moved (within the cut's reach, each to where its
  // whole star meets the floors): ChangeLog::moved, Cutter::last_moved(). Net: a vertex moved
  // twice counts once.
  std::uint32_t vertices_moved = 0;
  // 1 when the pass was made again from its start with every plan held to the mesh rule (the
  // volume of tets below theta outside the tool does not grow: the checker's I7), because the
  // first grew it; 0 for most cuts.
  std::uint32_t mesh_rule_retries = 0;
  std::uint32_t tets_removed_by_improvement = 0;
  // The pieces the cut detached from the organ (the largest piece its new surface bounds):
  // listed by Cutter::last_fragments(), those removed as debris included. The search visited
  // `fragment_tets_visited` tets; bounded: it stopped at CutParams::fragment_search_bound with
  // pieces it could not tell apart, which are not reported.
  std::uint32_t fragments = 0;
  std::uint32_t fragment_tets_visited = 0;
  bool fragment_search_bounded = false;
  // Detached pieces removed as debris (CutParams::debris_volume): not in tets_removed or
  // volume_removed, which count tissue.
  std::uint32_t debris_pieces_removed = 0, debris_tets_removed = 0;
  double debris_volume_removed = 0.0;
  double d_ref = 0;                  // the D_ref the cut was judged at: CutParams::d_ref()
  RefinementRule refinement = RefinementRule::kPaper;  // the rule of the attempt that ended it
  // Attempts rolled back before the one that ended the cut: under RefinementRule::kAuto, a cut
  // the paper's loop left with tets the pass could not lift is made again with the graded rule
  // (at the same D_ref). Every attempt's time is in `time`.
  std::uint32_t retries = 0;
  CutTimings time;
};

// A face-connected piece of the mesh a cut detached from the rest (CutReport::fragments). Of the
// pieces the cut's new surface bounds that were one piece before it, the largest by volume is
// the organ and is not listed; the others are.
struct Fragment {
  std::span<const TetId> tets;  // sorted by id (dead when removed as debris)
  double volume = 0.0;
  Vec3 centroid{};              // volume-weighted
  bool removed = false;         // dropped as debris (CutParams::debris_volume)
  TetId organ;                  // a live tet of the piece it came away from
};

class Cutter {
 public:
  // Indexes the mesh once (O(#T)); the grid's cell is the mesh's mean edge length. Then
  // prepare(): the first cut costs what the others do. The mesh must outlive the Cutter.
  Cutter(TetMesh& mesh, const CutParams& params);
  ~Cutter();
  Cutter(Cutter&&) noexcept;             // a moved-from Cutter may only be destroyed or assigned
  Cutter& operator=(Cutter&&) noexcept;

  // Makes every working array ready for cuts on the mesh as it is now, O(#T) once: room in the
  // mesh for half as many tets again, the marks, the scratch lists and the journal at their
  // working size, all allocated and touched (a page fault in a cut is a latency spike, and a
  // first cut would otherwise meet them all). The constructor calls it; call it again after the
  // mesh has grown past that room, so that the cuts that follow do not reallocate.
  void prepare();

  // After the mesh this Cutter holds was replaced (assigned another mesh: a fuzzer's next input,
  // a simulator's next case): the index is rebuilt, the scale remeasured, the removal statistics
  // and marks cleared, and prepare() run, all in the memory the Cutter already has (no
  // reallocation unless the new mesh is larger). O(#T).
  void reset();
  // Compacts the mesh (TetMesh::compact(order), ids renumbered densely) and resets this Cutter, so
  // that its index never holds stale ids. Returns the renumbering. The way to compact a mesh a
  // Cutter holds: after TetMesh::compact() called directly, or an assignment to the mesh, the
  // mesh's id_epoch() has moved on and cut(), remove() refuse (ok false, the mesh untouched)
  // and tet_containing() finds nothing until reset().
  Renumbering compact(IdOrder order = IdOrder::kAlongCurve);
  // False when the mesh was compacted or assigned since this Cutter indexed it (see compact()).
  [[nodiscard]] bool indexes_current_mesh() const;

  // Fails (returns the message, keeps the old parameters) when validate() does.
  std::optional<std::string> set_params(const CutParams& params);
  [[nodiscard]] const CutParams& params() const;

  // One cut with the tool centred at `centre`. Appends its net change to `log` when given, as the
  // mesh's journal derives it (change_log.hpp): the tets live before and gone after, the tets
  // live after and not before with their parents among the former, the vertices made that are
  // still used with their origin, the vertices gone.
  CutReport cut(const Vec3& centre, ChangeLog* log = nullptr);
  // One cut by the capsule the tool sweeps from `a` to `b` (its radius the tool's): the tissue a
  // stroke passes through between two haptic samples, whatever the sampling. The same pipeline,
  // guarantees and report as cut(); cut_segment(c, c) is cut(c), bit for bit. Refused
  // (kParameters, the mesh untouched) when an end is not finite, as cut() is.
  CutReport cut_segment(const Vec3& a, const Vec3& b, ChangeLog* log = nullptr);

  // One removal request outside the cut pipeline (tetcut remove, scenarios): tet t with the
  // strategy, atomically, the index kept up to date. Reported like a cut with one request.
  // Refused (ok false, the mesh untouched) when t is uncuttable.
  CutReport remove(TetId t, ChangeLog* log = nullptr);

  // Takes back the last cut, cut_segment or remove that changed the mesh, of the
  // CutParams::undo_history last ones kept (a trainee retries an incision): the mesh's arrays,
  // free lists and vertex attributes bit for bit as before it, and this Cutter's index, piece
  // labels, removal statistics and last_min_dihedral_held() likewise, so that what follows runs
  // as if the cut had never been made (the same cuts give the same hashes). Called again, it
  // takes back the cut before, down to undo_depth() cuts. With `log`, appends the undo's net
  // change (TetMesh::undo: what the cut removed comes back under its ids, marked restored).
  // Refused, with the reason and no change, when nothing is kept: none asked for, all taken
  // back, or the history emptied by reset(), compact(), set_uncuttable(), a change to
  // undo_history or a change to the mesh made outside this Cutter. last_removed() and
  // last_created() and last_moved() then name the undo's net change (a vertex moved back: where
  // it goes as barycentric coordinates in a tet around it before the undo); last_fragments() is
  // empty, and last_undone_reach() says where the undone cut worked.
  std::optional<std::string> undo(ChangeLog* log = nullptr);
  // How many cuts undo() can take back now.
  [[nodiscard]] std::uint32_t undo_depth() const;
  // After undo(): the tool of the cut it took back (the segment a-b, a ball when a == b) and the
  // D_ref it had, within whose sum the cut moved the vertices the undo moves back (the checker's
  // I8 holds an undo to it); none for a removal by id.
  struct CutReach {
    Vec3 a, b;
    double radius = 0.0, d_ref = 0.0;
  };
  [[nodiscard]] std::optional<CutReach> last_undone_reach() const;

  // Tissue every cut and removal request must leave (the paper's Fig. 7 frees the portal vein
  // from the resected liver): these live tets, and every tet later split from them, are never
  // removed. Replaces the set; empty: none (the default, and an unprotected cut is the same cut
  // bit for bit). The removal stages refuse any set holding one (a singularity only such a
  // removal resolves stays unresolved), and the improvement pass flips only among tets of one
  // kind and never moves or collapses a vertex of an uncuttable tet, so the uncuttable region is
  // the same point set after every cut. Returns why, the set unchanged, when a tet is not live
  // or the mesh was compacted or replaced behind the Cutter's back. O(#T).
  // reset() clears the set (the ids it named are gone); compact() keeps it under the new ids.
  std::optional<std::string> set_uncuttable(std::span<const TetId> tets);
  [[nodiscard]] bool uncuttable(TetId t) const;

  // The live tet containing p (lowest id when several share it), or kNoTet: for scenarios that
  // address tets geometrically.
  TetId tet_containing(const Vec3& p);

  // The removal statistics of every request since construction or reset() (paper Tables 1, 2).
  [[nodiscard]] const RemovalReport& removal_report() const;
  [[nodiscard]] TetMesh& mesh();
  // The removals and creations of the last cut, net (what LocalChecker wants).
  [[nodiscard]] const std::vector<TetId>& last_removed() const;
  [[nodiscard]] const std::vector<TetId>& last_created() const;
  // The vertices there before the last cut that it moved (ChangeLog::moved, as raw numbers: what
  // LocalChecker's I8 holds a move to, CheckOptions::moved), sorted by vertex id.
  [[nodiscard]] std::span<const RawMovedVertex> last_moved() const;
  // The tets the last cut left in its tool (CutReport::left_in_tool), sorted by id: what the
  // checker's I10 accepts as reported.
  [[nodiscard]] std::span<const TetId> last_left_in_tool() const;
  // The pieces the last cut or removal request detached, in the order its search finished them
  // (views, valid until the next cut).
  [[nodiscard]] std::span<const Fragment> last_fragments() const;
  // The mesh's face-connected pieces, kept by every cut and removal request without a scan
  // (counted once when the mesh is indexed). Exact unless a search was bounded since the last
  // reset(): then pieces it could not tell apart count as one.
  [[nodiscard]] std::uint32_t pieces() const;
  // The theta the last cut or removal request held its created tets to
  // (CutReport::min_dihedral_held_deg): what the checker's I7 takes for it.
  [[nodiscard]] double last_min_dihedral_held() const;

 private:
  // The index, the refiner, the Remover, the marks and the scratch lists (engine/src/cut/
  // cut_pipeline.hpp): allocated once, by the constructor.
  class Pipeline;
  std::unique_ptr<Pipeline> pipeline_;
};

}  // namespace tetcut
